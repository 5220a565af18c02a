#include "simulator/camera/surface_coverage.h"

#include <cmath>
#include <numbers>

#include "core/error.h"

namespace viscera::sim {

SurfaceCoverage::SurfaceCoverage(const core::SurfaceMesh& surface,
                                 const std::string& region_attribute, double region_value,
                                 int rays_across)
    : bvh_(surface.triangles, surface.vertices), rays_across_(std::max(2, rays_across)) {
  const std::vector<double>* region = nullptr;
  if (!region_attribute.empty()) {
    const auto it = surface.vertex_attributes.find(region_attribute);
    if (it == surface.vertex_attributes.end()) {
      throw core::InputError("the surface has no vertex attribute \"" + region_attribute +
                             "\" to select the region to inspect");
    }
    region = &it->second;
  }
  area_.resize(surface.triangles.size());
  in_region_.assign(surface.triangles.size(), 1);
  seen_.assign(surface.triangles.size(), 0);
  for (std::size_t t = 0; t < surface.triangles.size(); ++t) {
    const auto& tri = surface.triangles[t];
    area_[t] = 0.5 * (surface.vertices[tri[1]] - surface.vertices[tri[0]])
                         .cross(surface.vertices[tri[2]] - surface.vertices[tri[0]])
                         .norm();
    if (region != nullptr) {
      for (const int v : tri)
        in_region_[t] &= static_cast<std::uint8_t>((*region)[v] == region_value);
    }
    if (in_region_[t]) region_area_ += area_[t];
  }
}

CameraSample SurfaceCoverage::observe(const InstrumentState& state,
                                      const core::InstrumentSpec& instrument) {
  CameraSample sample;
  const core::Vec3 view = view_direction(state, instrument.optics_angle);
  // An orthonormal image frame around the view direction.
  core::Vec3 right = view.cross(state.axis.cross(state.up).normalized());
  if (right.norm() < 1e-9) right = view.unitOrthogonal();
  right.normalize();
  const core::Vec3 down = view.cross(right).normalized();
  const double half = std::tan(0.5 * instrument.field_of_view * std::numbers::pi / 180.0);
  const RayHit centre = bvh_.cast(state.tip, view, 10.0);
  sample.centre_distance = centre.triangle >= 0 ? centre.distance : -1.0;
  for (int j = 0; j < rays_across_; ++j) {
    for (int i = 0; i < rays_across_; ++i) {
      const double u = 2.0 * (i + 0.5) / rays_across_ - 1.0,
                   v = 2.0 * (j + 0.5) / rays_across_ - 1.0;
      if (u * u + v * v > 1.0) continue;  // the endoscope's image is a disc
      const core::Vec3 direction = (view + half * (u * right + v * down)).normalized();
      ++sample.rays;
      const RayHit hit = bvh_.cast(state.tip, direction, instrument.max_view_distance);
      if (hit.triangle < 0 || seen_[hit.triangle]) continue;
      seen_[hit.triangle] = 1;
      ++sample.newly_seen;
      if (in_region_[hit.triangle]) seen_area_ += area_[hit.triangle];
    }
  }
  return sample;
}

bool SurfaceCoverage::visible(const core::Vec3& eye, const core::Vec3& target,
                              double tolerance) const {
  const core::Vec3 d = target - eye;
  const double length = d.norm();
  if (length < 1e-12) return true;
  const RayHit hit = bvh_.cast(eye, d / length, length + tolerance);
  return hit.triangle < 0 || hit.distance >= length - tolerance;
}

}  // namespace viscera::sim
