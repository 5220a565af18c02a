#pragma once
// The laparoscopy-gyn patient cut down to its left tube alone (no connections, vessels or
// motility), built once: a small laparoscopy scene whose sessions run in seconds, for the
// tests of the laparoscopic tools (sterilisation, suction–irrigation).

#include <algorithm>
#include <vector>

#include "core/scenario/scenario.h"
#include "simulator/world/world.h"
#include "templates/template_catalog.h"

namespace viscera::testing {

inline const core::Scenario& left_tube_patient() {
  static const core::Scenario s = [] {
    core::Scenario p = templates::build_from_template("laparoscopy-gyn", {}, 1);
    std::erase_if(p.objects, [](const auto& o) { return o.id != "tube-left"; });
    p.connections.clear();
    p.vessel_trees.clear();
    p.active_deformations.clear();
    return p;
  }();
  return s;
}

/// The left tube's isthmus where it hangs once the patient has settled (m): the session starts
/// from the settled patient, whose free isthmus hangs a few millimetres below its authored place,
/// by the mean displacement of its knots within 4 mm of the landmark.
inline core::Vec3 settled_left_isthmus() {
  const auto& marks = left_tube_patient().landmarks;
  const auto it = std::find_if(marks.begin(), marks.end(),
                               [](const auto& l) { return l.id == "fallopian-tube-left"; });
  sim::World settled(left_tube_patient());
  settled.settle();
  const int tube = settled.body_index("tube-left");
  const auto rest = settled.state().range(settled.state().rest_positions, tube);
  const auto now = settled.state().range(settled.state().positions, tube);
  core::Vec3 sag = core::Vec3::Zero();
  int near = 0;
  for (std::size_t k = 0; k < rest.size(); ++k)
    if ((rest[k] - it->position).norm() < 0.004) sag += now[k] - rest[k], ++near;
  return it->position + sag / std::max(near, 1);
}

}  // namespace viscera::testing
