#pragma once
/// Blood, air bubbles and tissue debris in the endoscopic view as billboards (seed 000 §6.2 and §7:
/// "the particles are rendered as billboards", textured by the stage of their life; "endometrial
/// material, floating tissue fragments, and bubbles … are represented by billboards"): each
/// particle of the cavity's flow is a small screen-aligned sprite (a point sprite of a few
/// pixels, softened by the lens pass's resampling and blur), drawn opaque in the scene pass so
/// the lens distorts and blurs it with the tissue. Its stage (0…1) picks one of `kStages` looks
/// between the two ends of a ParticleLook: for blood the age over life, from a small bright
/// arterial-red drop to a larger dark venous-red one (the blood the particles release clouds
/// the view as the lens pass's haze, from the concentration field); for bubbles the radius
/// within its range, from a small to a large silvery one; for debris its size, from a small
/// pale shred to a larger flesh-coloured one; for the irrigation jet's drops the
/// age over their longest flight. Sprites are sized in pixels, not
/// metres, and square: blended world-size splats cost seconds a frame on a software rasteriser
/// with 10,000 of them, sphere impostors 40 ms. Sizes and colours are stated choices; the seed
/// gives none.

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

/// The two ends of a kind of particle's look; stages in between blend linearly.
struct ParticleLook {
  std::array<double, 3> first_colour, last_colour;  ///< RGB 0…1 at stage 0 and at stage 1
  double first_size, last_size;                     ///< sprite diameter, pixels of the scene pass
  double ambient;                                   ///< 0…1, the rest diffuse
  /// Shaded as small spheres with a highlight (a few hundred bubbles afford it) instead of flat
  /// squares (ten thousand blood drops do not).
  bool spheres = false;
};

/// Blood: 6 px bright arterial red at birth to 12 px dark venous red at the end of its life.
inline constexpr ParticleLook kBloodLook{{0.72, 0.03, 0.03}, {0.32, 0.05, 0.05}, 6.0, 12.0, 0.35};
/// Irrigation drops: 3 px to 5 px over their flight, pale blue-white saline.
inline constexpr ParticleLook kDropLook{{0.78, 0.86, 0.95}, {0.70, 0.80, 0.92}, 3.0, 5.0, 0.6};
/// Tissue debris: 4 px to 9 px from the smallest shred to one of the debris bound, pale pink
/// (cut endometrium or myoma, bloodless) to a deeper flesh tone.
inline constexpr ParticleLook kDebrisLook{{0.93, 0.80, 0.76}, {0.80, 0.55, 0.50}, 4.0, 9.0, 0.45};
/// Air bubbles: 5 px to 12 px from the smallest radius to the largest, silvery and bright.
inline constexpr ParticleLook kBubbleLook{
    {0.80, 0.86, 0.92}, {0.92, 0.95, 1.0}, 5.0, 12.0, 0.5, true};

class ParticleBillboards {
 public:
  static constexpr int kStages = 4;

  /// Adds the (empty) billboards to `scene`.
  ParticleBillboards(vtkRenderer* scene, const ParticleLook& look);
  ~ParticleBillboards();
  ParticleBillboards(const ParticleBillboards&) = delete;
  ParticleBillboards& operator=(const ParticleBillboards&) = delete;

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
