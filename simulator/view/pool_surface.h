#pragma once
/// The pool of irrigation fluid and blood in a laparoscopy (seed 001 §4.3: a pool "realised by a
/// deformable flat object … rendered transparently", its colour and transparency from the
/// amounts of water and blood): a flat translucent disc across gravity at the pool's surface,
/// as wide as its area, tinted from saline's pale blue-grey to blood red by its blood fraction
/// and more opaque the more blood it holds, lifted and lowered by its waves (a polar mesh whose
/// vertices take the elevations the session's snapshot carries; sim::SessionSnapshot::
/// pool_waves). The seed's fake reflection is not drawn: the head light's highlight on the
/// moving surface shows the waves.

#include <vtkSmartPointer.h>

#include <span>

#include "core/math_types.h"

class vtkActor;
class vtkPoints;
class vtkPolyData;
class vtkPolyDataNormals;
class vtkRenderer;

namespace viscera::view {

class PoolSurface {
 public:
  /// Adds the (hidden) disc to `scene`.
  explicit PoolSurface(vtkRenderer* scene);
  ~PoolSurface();
  PoolSurface(const PoolSurface&) = delete;
  PoolSurface& operator=(const PoolSurface&) = delete;

  /// Shows the pool's surface centred at `centre` (m) facing `up` (unit), of radius `radius` m
  /// (0: no pool, hidden), with `blood_fraction` (0…1) of blood and the wave elevations `waves`
  /// (m, in sim::SessionSnapshot::pool_waves' layout; empty: a flat surface).
  void update(const core::Vec3& centre, const core::Vec3& up, double radius, double blood_fraction,
              std::span<const float> waves = {});
  bool visible() const;
  /// The highest and lowest vertex along `up` of the drawn surface about its centre, m.
  double relief() const { return relief_; }

 private:
  vtkSmartPointer<vtkPoints> points_;
  vtkSmartPointer<vtkPolyData> surface_;
  vtkSmartPointer<vtkPolyDataNormals> normals_;  ///< smooth shading shows the waves
  double relief_ = 0.0;
  vtkSmartPointer<vtkActor> actor_;
};

}  // namespace viscera::view
