#pragma once
/// The `laparoscopy-gyn` template: the gynaecology scene of the Karlsruhe trainer (seed 001
/// §3.3, its scene table) — uterus, 2 ovaries, 2 fallopian tubes, 2 (round) ligaments, an
/// arterial tree of 6 objects, a venous tree of 7 and the intestine: 21 objects, each a KisMo
/// two-layer mass-spring net (seed 001 §3.3: an inner copy of the surface, offset along the
/// normals, joined to it by springs), sized so that the knot counts at the default resolution
/// follow the table:
///
/// | model         | objs | knots (seed 001) | springs (seed 001) |
/// |---------------|------|------------------|--------------------|
/// | uterus        | 1    | 339              | 1,328              |
/// | ovaries       | 2    | 230              | 864                |
/// | fallop. tubes | 2    | 408              | 1,462              |
/// | ligaments     | 2    | 358              | 1,376              |
/// | arterial tree | 6    | 594              | 2,508              |
/// | venous tree   | 7    | 675              | 2,844              |
/// | intestines    | 1    | 147              | 560                |
/// | total         | 21   | 2,751            | 10,942             |
///
/// Our counts are in laparoscopy_gyn_counts() and `viscera templates --json`. Every object is
/// held where it is tied in (vessels, ligaments and tubes at their ends and their middle — in
/// the broad ligament —, the intestine at its ends and its mesentery, the
/// uterus at the cervix, each ovary at both poles). Lengths in m.

#include <nlohmann/json.hpp>

#include "templates/template_catalog.h"

namespace viscera::templates {

/// Builds the gynaecological laparoscopy scene.
class LaparoscopyGynTemplate final : public ScenarioTemplate {
 public:
  std::string name() const override { return "laparoscopy-gyn"; }
  std::string description() const override;
  std::string version() const override { return "1"; }
  std::string procedure() const override { return "laparoscopy-gyn"; }
  std::vector<TemplateParameter> parameters() const override;
  std::vector<core::VariabilityRule> default_variability() const override;
  core::Scenario build(const ParameterValues& parameters, std::uint64_t seed,
                       core::Progress& progress) const override;
  /// laparoscopy_gyn_counts() of the scene at the defaults (seed 1).
  nlohmann::json reference_counts() const override;
};

/// Knots (body nodes) and springs (unique body edges) per model group of `scenario` (objects
/// grouped by the part of their id before the first digit-free side: "uterus", "ovary",
/// "tube", "ligament", "artery", "vein", "intestine"), with the seed 001 table beside them:
/// {group: {objects, knots, springs, seed_objects, seed_knots, seed_springs}, total: …}.
nlohmann::json laparoscopy_gyn_counts(const core::Scenario& scenario);

}  // namespace viscera::templates
