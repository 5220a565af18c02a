#pragma once
/// The `agent-tissue` template (seed 003 §V): a sheet of cell agents laid out as data — a grid
/// of cells with home positions, each of one of two cell types (a soft matrix and stiffer
/// inclusions placed at random, "heterogeneous tissue by drag-and-drop" done by the seed), the
/// edge row along y = 0 fixed as where the sheet is held, and the ten state constants of each
/// type as a core::CellTissueSpec (neighbours: the four nearest within 1.05 spacings).

#include "templates/template_catalog.h"

namespace viscera::templates {

/// Builds a heterogeneous agent-based tissue sheet for the agent-tissue lab.
class AgentTissueTemplate final : public ScenarioTemplate {
 public:
  std::string name() const override { return "agent-tissue"; }
  std::string description() const override;
  std::string version() const override { return "1"; }
  std::string procedure() const override { return "agent-tissue-lab"; }
  std::vector<TemplateParameter> parameters() const override;
  std::vector<core::VariabilityRule> default_variability() const override;
  core::Scenario build(const ParameterValues& parameters, std::uint64_t seed,
                       core::Progress& progress) const override;
};

}  // namespace viscera::templates
