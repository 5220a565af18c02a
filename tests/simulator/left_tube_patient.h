#pragma once
// The laparoscopy-gyn patient cut down to its left tube alone (no connections, vessels or
// motility), built once: a small laparoscopy scene whose sessions run in seconds, for the
// tests of the laparoscopic tools (sterilisation, suction–irrigation).

#include <vector>

#include "core/scenario/scenario.h"
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

}  // namespace viscera::testing
