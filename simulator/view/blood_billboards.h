#pragma once
/// Blood in the endoscopic view as billboards (seed 000 §6.2 and §7: "the particles are rendered
/// as billboards", textured by the stage of their life): each particle of the cavity's flow is a
/// small screen-aligned sprite (a point sprite of a few pixels, softened by the lens pass's
/// resampling and blur), drawn opaque in the scene pass so the lens distorts and blurs it with
/// the tissue. Its stage (age over life, 0…1) picks one of `kStages` looks, from a
/// small bright arterial-red drop to a larger dark venous-red one; the blood the particles
/// release clouds the view as the lens pass's haze (haze_density, from the concentration
/// field). Sprites are sized in pixels, not metres, and square: blended world-size splats cost
/// seconds a frame on a software rasteriser with 10,000 of them, sphere impostors 40 ms. Sizes and
/// colours are stated choices; the seed gives none.

#include <vtkSmartPointer.h>

#include <array>
#include <vector>

#include "core/math_types.h"

class vtkActor;
class vtkCellArray;
class vtkPoints;
class vtkPolyData;
class vtkRenderer;

namespace viscera::view {

class BloodBillboards {
 public:
  static constexpr int kStages = 4;
  /// Sprite diameter at birth and at the end of life, pixels of the scene pass.
  static constexpr double kBirthSize = 6.0;
  static constexpr double kDeathSize = 12.0;

  /// Adds the (empty) billboards to `scene`.
  explicit BloodBillboards(vtkRenderer* scene);
  ~BloodBillboards();
  BloodBillboards(const BloodBillboards&) = delete;
  BloodBillboards& operator=(const BloodBillboards&) = delete;

  /// Shows one billboard per particle at `positions` (m) with `stages` (0…1, one each).
  void update(const std::vector<core::Vec3>& positions, const std::vector<float>& stages);
  std::size_t size() const { return size_; }

 private:
  struct Stage {
    vtkSmartPointer<vtkPoints> points;
    vtkSmartPointer<vtkCellArray> vertices;
    vtkSmartPointer<vtkPolyData> cloud;
    vtkSmartPointer<vtkActor> actor;
  };
  std::array<Stage, kStages> stages_;
  std::size_t size_ = 0;
};

}  // namespace viscera::view
