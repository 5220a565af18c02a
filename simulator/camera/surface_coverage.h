#pragma once
/// What the endoscope's camera has seen of a surface, computed headlessly (seed 000 §11:
/// "quantification of the properly visualized surface"): rays through the optics' circular
/// field of view are cast against the surface's BVH; a triangle whose centre region a ray meets
/// within the usable viewing distance counts as seen. No rendering is needed, so sessions score
/// the same with or without a window.

#include <optional>
#include <vector>

#include "core/mesh/surface_mesh.h"
#include "core/scenario/scenario_parts.h"
#include "simulator/camera/surface_bvh.h"
#include "simulator/session/instrument_state.h"

namespace viscera::sim {

/// One look through the optics.
struct CameraSample {
  double centre_distance = -1.0;  ///< m to the surface along the view axis, −1 when nothing is hit
  int rays = 0;                   ///< rays cast
  int newly_seen = 0;             ///< triangles seen for the first time
};

/// Coverage of one surface (or a region of it) by the camera.
class SurfaceCoverage {
 public:
  /// `surface` at its current positions. When `region_attribute` names a vertex attribute,
  /// only triangles whose three vertices carry `region_value` count towards the fraction
  /// (rays still stop at every triangle). `rays_across` rays span the field of view's
  /// diameter (those outside the circle are skipped).
  SurfaceCoverage(const core::SurfaceMesh& surface, const std::string& region_attribute = "",
                  double region_value = 1.0, int rays_across = 32);

  /// Moves the surface to new vertex positions (a deforming organ).
  void refit(std::span<const core::Vec3> positions) { bvh_.refit(positions); }

  /// Looks through the optics of `instrument` from `state`; marks what is seen.
  CameraSample observe(const InstrumentState& state, const core::InstrumentSpec& instrument);

  /// Seen area over the region's area, in [0, 1].
  double fraction_seen() const { return region_area_ > 0.0 ? seen_area_ / region_area_ : 0.0; }
  double region_area() const { return region_area_; }  ///< m²
  const std::vector<std::uint8_t>& seen() const { return seen_; }
  const SurfaceBvh& bvh() const { return bvh_; }

  /// True when nothing of the surface lies between `eye` and `target` (a target on the
  /// surface itself is visible when the first hit is within `tolerance` m of it).
  bool visible(const core::Vec3& eye, const core::Vec3& target, double tolerance) const;

 private:
  SurfaceBvh bvh_;
  std::vector<double> area_;
  std::vector<std::uint8_t> in_region_, seen_;
  double region_area_ = 0.0, seen_area_ = 0.0;
  int rays_across_;
};

}  // namespace viscera::sim
