#pragma once
/// Surgical smoke in the endoscopic view (seed 001 §4.2, method B: "texture slices … mapped onto
/// circles", hung along an animated spline, "increasing size along the curve", transparency
/// "increasing from the center to the corners of each circle"): each puff of SurgicalSmoke is a
/// camera-facing square carrying a turbulence texture (a sum of octaves of value noise, the
/// stand-in for Perlin's turbulence) whose alpha falls off radially, tinted grey-white and
/// faded by the puff's opacity. Each puff shows the texture in one of its eight symmetries
/// (by its number), so neighbouring puffs do not repeat one pattern. Blended in the scene's
/// translucent pass, so the lens pass distorts and blurs them with the tissue.

#include <vtkSmartPointer.h>

#include <vector>

#include "simulator/session/surgical_smoke.h"

class vtkActor;
class vtkImageData;
class vtkPolyData;
class vtkRenderer;

namespace viscera::view {

class SmokeBillboards {
 public:
  /// Texture side in texels; the turbulence has four octaves.
  static constexpr int kTextureSize = 64;

  explicit SmokeBillboards(vtkRenderer* scene);
  ~SmokeBillboards();
  SmokeBillboards(const SmokeBillboards&) = delete;
  SmokeBillboards& operator=(const SmokeBillboards&) = delete;

  /// Shows `puffs` facing a camera whose image axes are `right` and `up` (unit, world).
  void update(const std::vector<sim::SmokeBillboard>& puffs, const core::Vec3& right,
              const core::Vec3& up);
  std::size_t size() const { return size_; }

 private:
  vtkSmartPointer<vtkPolyData> quads_;
  vtkSmartPointer<vtkActor> actor_;
  std::size_t size_ = 0;
};

/// The RGBA turbulence texture of the smoke: white, alpha = turbulence × radial falloff, zero at
/// and beyond the inscribed circle. Deterministic.
vtkSmartPointer<vtkImageData> smoke_texture(int size);

}  // namespace viscera::view
