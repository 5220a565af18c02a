#pragma once
/// The Scenario: everything the simulator needs about one virtual patient (DESIGN.md §3).

#include <map>
#include <string>
#include <vector>

#include "core/scenario/material.h"
#include "core/scenario/scenario_parts.h"
#include "core/scenario/scene_object.h"

namespace viscera::core {

/// Procedures a scenario can be trained on.
inline constexpr const char* kProcedures[] = {"none", "hysteroscopy", "laparoscopy-gyn",
                                              "urethral-endoscopy", "agent-tissue-lab"};

/// One virtual patient and its session set-up.
struct Scenario {
  Metadata metadata;
  std::string procedure = "none";
  std::vector<SceneObject> objects;
  std::map<std::string, Material> materials;    ///< keyed by Material::id
  std::map<std::string, TextureSpec> textures;  ///< keyed by TextureSpec::id
  std::vector<VesselTree> vessel_trees;
  std::vector<ActiveDeformation> active_deformations;
  std::vector<Pathology> pathologies;
  std::vector<Connection> connections;
  FluidSpec fluid;
  SessionSpec session;
  std::vector<VariabilityRule> variability;
  std::vector<Landmark> landmarks;                   ///< named points tasks refer to
  std::vector<CellTissueSpec> cell_tissues;          ///< one per cell-agent object
  std::vector<UrethraLatticeSpec> urethra_lattices;  ///< one per urethra-lattice object
  Provenance provenance;

  /// The object with this id, or nullptr.
  const SceneObject* find_object(const std::string& id) const;

  bool operator==(const Scenario&) const = default;
};

}  // namespace viscera::core
