#pragma once
/// The `urethra` template (seed 002 §3.1, §5): the lattice of the NTUA urological trainer — w
/// circular sections of n points whose centres lie equidistant in z on the centre line
/// y = a z², each section normal to the line's tangent, the bladder-entrance section (the
/// last, j = w − 1) fixed — with the constants of its force model (eq. 6–13) as a
/// core::UrethraLatticeSpec. Coordinates: z from the meatus (0) to the bladder entrance, y up.

#include "templates/template_catalog.h"

namespace viscera::templates {

/// Builds a urethra for urethral endoscopy. The seed sets only the texture.
class UrethraTemplate final : public ScenarioTemplate {
 public:
  std::string name() const override { return "urethra"; }
  std::string description() const override;
  std::string version() const override { return "1"; }
  std::string procedure() const override { return "urethral-endoscopy"; }
  std::vector<TemplateParameter> parameters() const override;
  std::vector<core::VariabilityRule> default_variability() const override;
  core::Scenario build(const ParameterValues& parameters, std::uint64_t seed,
                       core::Progress& progress) const override;
};

}  // namespace viscera::templates
