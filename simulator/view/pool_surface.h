#pragma once
/// The pool of irrigation fluid and blood in a laparoscopy (seed 001 §4.3: a pool "realised by a
/// deformable flat object … rendered transparently", its colour and transparency from the
/// amounts of water and blood): a flat translucent disc across gravity at the pool's surface,
/// as wide as its area, tinted from saline's pale blue-grey to blood red by its blood fraction
/// and more opaque the more blood it holds. The seed's waves and fake reflection are not drawn.

#include <vtkSmartPointer.h>

#include "core/math_types.h"

class vtkActor;
class vtkPoints;
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
  /// (0: no pool, hidden), with `blood_fraction` (0…1) of blood.
  void update(const core::Vec3& centre, const core::Vec3& up, double radius, double blood_fraction);
  bool visible() const;

 private:
  static constexpr int kSides = 64;  ///< of the polygon drawn for the disc
  vtkSmartPointer<vtkPoints> rim_;
  vtkSmartPointer<vtkActor> actor_;
};

}  // namespace viscera::view
