#pragma once
/// What the SOFA template tests compare against: the packages of every template made by
/// `viscera new`, and the constants Viscera's simulator builds from them.

#include <filesystem>
#include <map>
#include <ostream>
#include <string>
#include <utility>

#include "core/scenario/scenario.h"

namespace viscera::testing {

struct TemplateCase {
  const char* label;
  const char* template_name;
  const char* sets;            ///< extra `viscera new` arguments, e.g. " --set floor=1"
  const char* refused_object;  ///< nullptr when the template exports
};

/// Names the case in test output.
inline void PrintTo(const TemplateCase& c, std::ostream* os) {
  *os << c.label;
}

/// The package of a case made by `viscera new --seed 2`, once per build of the program for all
/// the test processes (in shared_test_folder()).
std::filesystem::path template_package(const TemplateCase& c);

/// The material of tet `t` of `o`: its layer's, or the object's.
const core::Material& material_of_tet(const core::Scenario& s, const core::SceneObject& o,
                                      std::size_t t);

/// Viscera's KisMo edge constants (simulator/physics/deformable_body.h): k1 = c₁ · share / l0 on
/// the strain, i.e. c₁ share / l0² in N/m, and damping s_d share / l0² in N·s/m, per edge (a < b).
std::map<std::pair<int, int>, std::pair<double, double>> viscera_edges(const core::Scenario& s,
                                                                       const core::SceneObject& o);

/// The SOFA v26.06 plugin registering component `type` ("" for Sofa.Simulation.Core's).
std::string plugin_of(const std::string& type);

}  // namespace viscera::testing
