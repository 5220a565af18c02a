#pragma once
/// The rest description of one simulated body that its force terms are built from: the rest
/// tet mesh of its current topology and the material of every tet (an object's wall layers
/// each have their own, core::SceneObject::layer_materials). The world owns one per body and
/// updates it before calling topology_changed().

#include <span>
#include <string>
#include <vector>

#include "core/mesh/tet_mesh.h"
#include "core/scenario/material.h"
#include "core/scenario/scene_object.h"

namespace viscera::sim {

/// How a body's internal forces are modelled.
enum class BodyModelKind {
  Teschner,         ///< distance, area and volume energies (seed 000 §3)
  KismoMassSpring,  ///< cubic springs on the mesh edges with damping elements (seed 001 §3.2)
  CellAgent         ///< cell agents of seed 003 §V (mesh.nodes the cells' homes, no tets)
};

struct BodyModel {
  std::string name;  ///< the object's id
  int body = 0;      ///< index of its node range in the SimulationState
  BodyModelKind kind = BodyModelKind::Teschner;
  core::TetMesh mesh;                     ///< rest nodes and tets of the current topology
  std::vector<core::Triangle> surface;    ///< outward boundary triangles (mesh or derived)
  std::vector<core::Material> materials;  ///< distinct materials of the body
  std::vector<int> tet_material;          ///< per tet: index into materials

  const core::Material& material_of(int tet) const {
    return materials[static_cast<std::size_t>(tet_material[static_cast<std::size_t>(tet)])];
  }
};

/// The per-tet materials of `object`: `base` everywhere, except tets whose label is listed in
/// object.layer_materials, which take that material from `materials`. Throws core::InputError
/// naming the object for a layer material id that is not in `materials`.
void assign_layer_materials(BodyModel& model, const core::SceneObject& object,
                            const core::Material& base,
                            const std::map<std::string, core::Material>& materials);

/// The stiffness of the tissue around each node of `model` at rest, N/m per body node: how stiff
/// a spring tying the node to a target must be to match its neighbourhood (MotilityForces,
/// HydrometraForces),
///   k_i = ⅓ Σ_{tet edges e at i} k_D,e / D0,e²,
/// with k_D,e = Σ over the edge's tets of distance_stiffness (Pa) × V0/6 (m³), the Teschner
/// distance stiffness of each tet's material (seed 000 §3), and D0,e the edge's rest length (m).
/// `rest` holds the body's rest positions (m), indexed like model.mesh.nodes. Edges of zero
/// length add nothing; a node on no tet gets 0. Held nodes are not special here.
std::vector<double> node_distance_stiffness(const BodyModel& model,
                                            std::span<const core::Vec3> rest);

}  // namespace viscera::sim
