#pragma once
/// The `ball` template: a spherical organ resting on its fixed base. The simplest real patient,
/// used by the foundation's thin path from authoring to a simulated session.

#include "templates/template_catalog.h"

namespace viscera::templates {

/// A sphere with an icosphere visual surface, a gmsh tetrahedral body, the nodes of its lowest
/// slice fixed, and a soft-tissue default material. The seed is recorded but the ball has no
/// random features.
class BallTemplate final : public ScenarioTemplate {
 public:
  std::string name() const override { return "ball"; }
  std::string description() const override;
  std::string version() const override { return "1"; }
  std::string procedure() const override { return "none"; }
  std::vector<TemplateParameter> parameters() const override;
  core::Scenario build(const ParameterValues& parameters, std::uint64_t seed,
                       core::Progress& progress) const override;
};

}  // namespace viscera::templates
