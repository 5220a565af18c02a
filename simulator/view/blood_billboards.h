#pragma once
/// Blood in the endoscopic view as billboards (seed 000 §6.2 and §7: "the particles are rendered
/// as billboards", textured by the stage of their life): each particle of the cavity's flow is
/// a round Gaussian splat facing the camera, drawn in the scene pass so the lens distorts and
/// blurs it with the tissue. Its stage (age over life, 0…1) picks colour, opacity and size: a
/// fresh drop is small, opaque and bright arterial red; as it mixes into the distension fluid it
/// grows, darkens and fades — the cloud the concentration field then carries as haze (the lens
/// pass's haze_density). Sizes and colours are stated choices; the seed gives none.

#include <vtkNew.h>
#include <vtkSmartPointer.h>

#include <vector>

#include "core/math_types.h"

class vtkActor;
class vtkFloatArray;
class vtkPointGaussianMapper;
class vtkPoints;
class vtkPolyData;
class vtkRenderer;

namespace viscera::view {

class BloodBillboards {
 public:
  /// Splat radius at birth and at the end of life, m.
  static constexpr double kBirthRadius = 0.4e-3;
  static constexpr double kDeathRadius = 1.6e-3;

  /// Adds the (empty) billboards to `scene`.
  explicit BloodBillboards(vtkRenderer* scene);
  ~BloodBillboards();
  BloodBillboards(const BloodBillboards&) = delete;
  BloodBillboards& operator=(const BloodBillboards&) = delete;

  /// Shows one billboard per particle at `positions` (m) with `stages` (0…1, one each).
  void update(const std::vector<core::Vec3>& positions, const std::vector<float>& stages);
  std::size_t size() const;

 private:
  vtkSmartPointer<vtkPoints> points_;
  vtkSmartPointer<vtkFloatArray> stage_, radius_;
  vtkSmartPointer<vtkPolyData> cloud_;
  vtkSmartPointer<vtkPointGaussianMapper> mapper_;
  vtkSmartPointer<vtkActor> actor_;
};

}  // namespace viscera::view
