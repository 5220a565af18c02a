#pragma once
// One object of a template's patient alone: the object, the vessel trees it hosts and the
// active deformations on it, without connections or a procedure (the arterial clip and hook
// tests work on one artery of the laparoscopy-gyn patient).

#include <map>
#include <string>

#include "core/scenario/scenario.h"
#include "templates/template_catalog.h"

namespace viscera::testing {

inline core::Scenario object_alone(const std::string& template_name, const std::string& id,
                                   const std::map<std::string, std::string>& parameters = {},
                                   std::uint64_t seed = 1) {
  core::Scenario p = templates::build_from_template(template_name, parameters, seed);
  std::erase_if(p.objects, [&](const auto& o) { return o.id != id; });
  std::erase_if(p.vessel_trees, [&](const auto& t) { return t.host_object != id; });
  std::erase_if(p.active_deformations, [&](const auto& d) { return d.target_object != id; });
  p.connections.clear();
  p.session.steps.clear();
  p.session.tasks.clear();
  return p;
}

}  // namespace viscera::testing
