#include "simulator/dynamics/authored_terms.h"

#include <algorithm>

#include "core/error.h"
#include "simulator/dynamics/agent_tissue_term.h"
#include "simulator/dynamics/motility_forces.h"
#include "simulator/dynamics/plastic_flow.h"
#include "simulator/dynamics/pulse_waves.h"

namespace viscera::sim {
namespace {

/// FNV-1a of the deformation id mixed with the scenario's seed: each motility draws its own
/// amplitudes, the same ones in every run of the scenario.
std::uint64_t motility_seed(const core::Scenario& scenario, const std::string& id) {
  std::uint64_t hash = 1469598103934665603ull ^ scenario.provenance.seed;
  for (const unsigned char c : id) {
    hash ^= c;
    hash *= 1099511628211ull;
  }
  return hash;
}

}  // namespace

std::shared_ptr<BodyModel> add_cell_agent_body(const core::Scenario& scenario,
                                               const core::SceneObject& object,
                                               SimulationState& state) {
  const core::ErrorLocation where{"", "", "object " + object.id};
  const auto spec =
      std::find_if(scenario.cell_tissues.begin(), scenario.cell_tissues.end(),
                   [&](const core::CellTissueSpec& s) { return s.object == object.id; });
  if (spec == scenario.cell_tissues.end())
    throw core::InputError("cell-agent object \"" + object.id + "\" has no cell tissue", where);
  const core::TetMesh& cells = object.body;
  if (cells.node_mass.size() != cells.nodes.size())
    throw core::InputError("cell-agent object \"" + object.id + "\" gives " +
                               std::to_string(cells.node_mass.size()) + " masses for " +
                               std::to_string(cells.nodes.size()) + " cells",
                           where);
  if (!cells.fixed.empty() && cells.fixed.size() != cells.nodes.size())
    throw core::InputError("cell-agent object \"" + object.id + "\" gives " +
                               std::to_string(cells.fixed.size()) + " fixed flags for " +
                               std::to_string(cells.nodes.size()) + " cells",
                           where);
  for (std::size_t i = 0; i < cells.nodes.size(); ++i) {
    const bool fixed = !cells.fixed.empty() && cells.fixed[i] != 0;
    if (!fixed && !(cells.node_mass[i] > 0.0))
      throw core::InputError("free cell has no positive mass",
                             {"body " + object.id, "", "node " + std::to_string(i)});
  }
  for (const auto& face : cells.surface_faces)
    for (const int n : face)
      if (n < 0 || n >= static_cast<int>(cells.nodes.size()))
        throw core::InputError(
            "a surface face names cell " + std::to_string(n) + ", which the tissue does not have",
            where);
  core::Material material;
  if (!object.material.empty()) {
    const auto it = scenario.materials.find(object.material);
    if (it == scenario.materials.end())
      throw core::InputError("unknown material id \"" + object.material + "\"", where);
    material = it->second;
  }
  auto model = std::make_shared<BodyModel>();
  model->name = object.id;
  model->kind = BodyModelKind::CellAgent;
  model->mesh.nodes = cells.nodes;
  model->mesh.node_mass = cells.node_mass;
  model->mesh.fixed = cells.fixed;
  model->mesh.surface_faces = cells.surface_faces;
  model->surface = cells.surface_faces;
  model->materials = {material};
  model->body = state.add_body(object.id, cells.nodes, cells.node_mass, cells.fixed);
  return model;
}

std::vector<std::unique_ptr<ForceTerm>> authored_terms(
    const core::Scenario& scenario, const SimulationState& state,
    const std::vector<std::shared_ptr<BodyModel>>& models,
    const std::vector<std::unique_ptr<ForceTerm>>& terms, double time_step) {
  std::vector<std::unique_ptr<ForceTerm>> out;
  // Plastic flow and tearing on every body's edges.
  for (const auto& term : terms) {
    if (auto* distance = dynamic_cast<TeschnerDistanceTerm*>(term.get())) {
      out.push_back(std::make_unique<PlasticFlow>(BodyEdges(*distance), state));
      out.push_back(std::make_unique<TissueTearing>(BodyEdges(*distance), state));
    } else if (auto* springs = dynamic_cast<KismoSpringTerm*>(term.get())) {
      out.push_back(std::make_unique<PlasticFlow>(BodyEdges(*springs), state));
      out.push_back(std::make_unique<TissueTearing>(BodyEdges(*springs), state));
    }
  }
  // The cell agents.
  for (const auto& model : models) {
    if (model->kind != BodyModelKind::CellAgent) continue;
    for (std::size_t t = 0; t < scenario.cell_tissues.size(); ++t)
      if (scenario.cell_tissues[t].object == model->name)
        out.push_back(
            std::make_unique<AgentTissueTerm>(model, state, scenario.cell_tissues[t], time_step,
                                              "/scenario/cell_tissues/" + std::to_string(t)));
  }
  // Active deformations on their targets.
  for (std::size_t d = 0; d < scenario.active_deformations.size(); ++d) {
    const core::ActiveDeformation& deformation = scenario.active_deformations[d];
    const core::ErrorLocation where{"", "/scenario/active_deformations/" + std::to_string(d),
                                    deformation.id};
    const auto target = std::find_if(models.begin(), models.end(), [&](const auto& m) {
      return m->name == deformation.target_object;
    });
    if (target == models.end()) {
      throw core::InputError("active deformation \"" + deformation.id + "\" targets \"" +
                                 deformation.target_object + "\", which has no simulated body",
                             where);
    }
    if (const auto* motility = std::get_if<core::MotilitySpec>(&deformation.spec)) {
      out.push_back(std::make_unique<MotilityForces>(
          *target, state, *motility, motility_seed(scenario, deformation.id), deformation.id));
      continue;
    }
    const auto& pulse = std::get<core::PulseSpec>(deformation.spec);
    const auto tree =
        std::find_if(scenario.vessel_trees.begin(), scenario.vessel_trees.end(),
                     [&](const core::VesselTree& t) { return t.id == pulse.vessel_tree; });
    if (tree == scenario.vessel_trees.end()) {
      throw core::InputError("pulse \"" + deformation.id + "\" runs on vessel tree \"" +
                                 pulse.vessel_tree + "\", which the scenario does not have",
                             where);
    }
    out.push_back(std::make_unique<PulseWaves>(*target, state, pulse, *tree, deformation.id));
  }
  return out;
}

bool drives_bodies(const std::vector<std::unique_ptr<ForceTerm>>& terms) {
  return std::any_of(terms.begin(), terms.end(), [](const auto& t) {
    return dynamic_cast<const MotilityForces*>(t.get()) != nullptr ||
           dynamic_cast<const PulseWaves*>(t.get()) != nullptr;
  });
}

std::size_t tear_count(const std::vector<std::unique_ptr<ForceTerm>>& terms) {
  std::size_t count = 0;
  for (const auto& t : terms) {
    if (const auto* edges = dynamic_cast<const TissueTearing*>(t.get()))
      count += edges->tears().size();
    else if (const auto* cells = dynamic_cast<const AgentTissueTerm*>(t.get()))
      count += cells->tears().size();
  }
  return count;
}

std::vector<TearEvent> tears_of(const std::vector<std::unique_ptr<ForceTerm>>& terms) {
  std::vector<TearEvent> tears;
  for (const auto& t : terms) {
    if (const auto* edges = dynamic_cast<const TissueTearing*>(t.get()))
      tears.insert(tears.end(), edges->tears().begin(), edges->tears().end());
    else if (const auto* cells = dynamic_cast<const AgentTissueTerm*>(t.get()))
      tears.insert(tears.end(), cells->tears().begin(), cells->tears().end());
  }
  std::stable_sort(tears.begin(), tears.end(),
                   [](const TearEvent& a, const TearEvent& b) { return a.time < b.time; });
  return tears;
}

}  // namespace viscera::sim
