#include "simulator/session/world_tissue.h"

#include <algorithm>
#include <cstdio>
#include <limits>
#include <map>

#include "simulator/dynamics/authored_terms.h"

namespace viscera::sim {

WorldTissue::WorldTissue(World& world, int body, double stiffness, const core::Vec3& tip,
                         double perforation_depth)
    : world_(world),
      body_(body),
      stiffness_(stiffness),
      perforation_depth_(perforation_depth),
      tip_(tip) {
  world_.attach_instrument(body_, stiffness_, tip_);
  const BodyView& b = world_.bodies()[static_cast<std::size_t>(body_)];
  wall_ = std::make_unique<SurfaceBvh>(b.surface_faces(), b.rest_positions());
  thickness_.assign(b.surface_faces().size(), -1.0);
}

const std::string& WorldTissue::name() const {
  return body()->name();
}

const BodyView* WorldTissue::body() const {
  return &world_.bodies()[static_cast<std::size_t>(body_)];
}

void WorldTissue::move(const InstrumentState& state, double /*dt*/) {
  tip_ = state.tip;
  world_.set_instrument_tip(tip_);
}

std::vector<TissueEvent> WorldTissue::warnings() {
  if (tear_count(world_.terms()) <= reported_tears_) return {};
  const std::vector<TearEvent> tears = tears_of(world_.terms());
  // One warning per body for the tears of this step.
  struct Torn {
    int count = 0;
    double strain = 0.0, threshold = 0.0;
  };
  std::map<std::string, Torn> per_body;
  for (std::size_t k = reported_tears_; k < tears.size(); ++k) {
    Torn& torn = per_body[tears[k].body];
    ++torn.count;
    torn.strain = std::max(torn.strain, tears[k].strain);
    torn.threshold = tears[k].threshold;
  }
  reported_tears_ = tears.size();
  std::vector<TissueEvent> out;
  for (const auto& [body, torn] : per_body) {
    char text[200];
    std::snprintf(text, sizeof text,
                  "%d link%s of \"%s\" tore, stretched up to %.0f %% past the original length "
                  "(tearing threshold %.0f %%)",
                  torn.count, torn.count == 1 ? "" : "s", body.c_str(), 100.0 * torn.strain,
                  100.0 * torn.threshold);
    out.push_back({"tissue-tear", text});
  }
  return out;
}

std::optional<TissueEvent> WorldTissue::complication() {
  // Perforation is judged on the wall the instrument works on, not on a polyp it touches.
  if (!world_.instrument_in_contact() || world_.instrument_touched_body() != body_)
    return std::nullopt;
  const double depth = penetration();
  const double limit = perforation_depth_ > 0.0
                           ? perforation_depth_
                           : wall_thickness(world_.instrument_contact().triangle);
  if (depth <= limit) return std::nullopt;
  return TissueEvent{"perforation", "the tool went " + std::to_string(depth * 1000.0) +
                                        " mm into the wall, past its " +
                                        std::to_string(limit * 1000.0) + " mm"};
}

double WorldTissue::wall_thickness(int triangle) {
  if (wall_ == nullptr || triangle < 0) return std::numeric_limits<double>::infinity();
  double& t = thickness_[static_cast<std::size_t>(triangle)];
  if (t < 0.0) {
    // Rest thickness under the triangle: from its centre straight into the tissue to the far side.
    const auto& tri = wall_->triangles()[static_cast<std::size_t>(triangle)];
    const auto& p = wall_->positions();
    const core::Vec3 centre = (p[tri[0]] + p[tri[1]] + p[tri[2]]) / 3.0;
    const core::Vec3 inward = -(p[tri[1]] - p[tri[0]]).cross(p[tri[2]] - p[tri[0]]).normalized();
    const RayHit hit = wall_->cast(centre + 1e-7 * inward, inward, 1.0);
    t = hit.triangle >= 0 ? hit.distance : std::numeric_limits<double>::infinity();
  }
  return t;
}

double WorldTissue::penetration() const {
  // How deep the tool is in the wall: the proxy–tip distance (the spring's stretch), or how
  // far the tip lies below the rest position of the touched face, whichever is larger — a soft
  // wall gives way, but a tool through its rest thickness has gone through it.
  const double spring = world_.instrument_force().norm() / stiffness_;
  const ProxyContact contact = world_.instrument_contact();
  if (wall_ == nullptr || contact.triangle < 0 || world_.instrument_touched_body() != body_)
    return spring;
  const auto& tri = wall_->triangles()[static_cast<std::size_t>(contact.triangle)];
  const auto& p = wall_->positions();
  const core::Vec3 rest_point = contact.barycentric[0] * p[tri[0]] +
                                contact.barycentric[1] * p[tri[1]] +
                                contact.barycentric[2] * p[tri[2]];
  const core::Vec3 outward = (p[tri[1]] - p[tri[0]]).cross(p[tri[2]] - p[tri[0]]).normalized();
  return std::max(spring, (rest_point - tip_).dot(outward));
}

}  // namespace viscera::sim
