#pragma once
// A polyp scooped by the resection loop: the hysteroscopy patient with a resectoscope, the
// polyp's frame where the session finds it, and a script that draws the loop across its apex.
// Shared by the loop resection and chip retrieval tests.

#include <algorithm>
#include <nlohmann/json.hpp>

#include "simulator/dynamics/attachment_term.h"
#include "simulator/world/world.h"
#include "templates/template_catalog.h"

namespace viscera::testing {

inline constexpr double kRadius = 0.0025;  // sim::standard_resection_loop()

inline core::Scenario resectoscope_patient(int seed = 1) {
  core::Scenario s = templates::build_from_template("hysteroscopy", {}, seed);
  s.session.instrument.kind = "resectoscope";
  return s;
}

/// Where the polyp grows: its attached nodes' centre (base), its apex and the unit axis between.
struct PolypFrame {
  int body = -1;
  core::Vec3 base, apex, axis, across;
  double half_width = 0.0;  ///< m, largest distance of a node from the axis
};

inline PolypFrame polyp_frame(const sim::World& world) {
  PolypFrame f;
  f.body = world.body_index("polyp-1");
  const auto x = world.state().range(world.state().positions, f.body);
  core::Vec3 sum = core::Vec3::Zero();
  int count = 0;
  for (const auto& term : world.terms())
    if (const auto* a = dynamic_cast<const sim::AttachmentTerm*>(term.get()))
      for (const auto& at : a->attachments())
        if (at.body == f.body) {
          sum += x[static_cast<std::size_t>(at.node)];
          ++count;
        }
  f.base = sum / std::max(count, 1);
  f.apex = *std::max_element(x.begin(), x.end(), [&](const auto& p, const auto& q) {
    return (p - f.base).squaredNorm() < (q - f.base).squaredNorm();
  });
  f.axis = (f.apex - f.base).normalized();
  f.across = f.axis.unitOrthogonal();
  for (const auto& p : x) {
    const core::Vec3 d = p - f.base;
    f.half_width = std::max(f.half_width, (d - d.dot(f.axis) * f.axis).norm());
  }
  return f;
}

/// A script: rest beside the polyp, pedal down, draw the loop across the apex `depth` m deep
/// (its arc's lowest point below the apex), pedal up beyond it, then rest. The shaft points
/// against the motion: the loop is drawn back towards the optics (seed 000 §5).
inline nlohmann::json scoop_script(const PolypFrame& f, double depth,
                                   double release_fraction = 1.0) {
  const double reach = f.half_width + 2.0 * kRadius + 0.002;
  const core::Vec3 height = f.apex + (kRadius - depth) * f.axis;
  const core::Vec3 from = height + reach * f.across, to = height - reach * f.across;
  const core::Vec3 release = from + release_fraction * (to - from);
  const auto point = [](const core::Vec3& p) { return nlohmann::json{p.x(), p.y(), p.z()}; };
  const nlohmann::json axis = point(f.across), up = point(-f.axis);
  return {{"format", "viscera-script"},
          {"version", 2},
          {"body", "uterus"},
          {"waypoints",
           {{{"t", 0.0}, {"tip", point(from)}, {"axis", axis}, {"up", up}},
            {{"t", 0.2}, {"tip", point(from)}, {"activate", 1}},
            {{"t", 0.7}, {"tip", point(release)}},
            {{"t", 0.72}, {"tip", point(release)}, {"activate", 0}},
            {{"t", 1.5}, {"tip", point(release)}}}}};
}

/// The polyp where a session finds it at its start: settled on its wall (World::settle).
inline PolypFrame frame_of(const core::Scenario& scenario) {
  sim::World world(scenario);
  world.settle();
  return polyp_frame(world);
}

}  // namespace viscera::testing
