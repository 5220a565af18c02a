#pragma once
/// Building blocks every template uses to assemble a scenario: materials, texture specs, scene
/// objects with gmsh tet bodies, and attachments between objects.

#include <cstdint>
#include <string>
#include <vector>

#include "core/progress.h"
#include "core/scenario/scenario.h"

namespace viscera::templates {

/// Adds a soft-tissue material: density kg/m³, Teschner distance stiffness density Pa; the
/// volume stiffness equals it, the damping density is 2e-4 s times it (Pa·s: weak enough
/// that damping does not limit the explicit step of millimetre elements) and the area term 1e-4 of
/// it (N/m).
void add_material(core::Scenario& scenario, const std::string& id, const std::string& name,
                  double density, double stiffness, const std::string& source);

/// Adds a texture spec of a built-in preset (textures/texture_preset.h), size × size pixels.
void add_texture(core::Scenario& scenario, const std::string& id, const std::string& preset,
                 std::uint64_t seed, int size);

/// Adds an object whose simulation body is `surface` filled by gmsh (the surface's vertices
/// are the body's first nodes, so the visual surface rides on them exactly), with lumped masses
/// of `density`. Throws core::InputError when gmsh refuses the surface.
core::SceneObject& add_tet_object(core::Scenario& scenario, const std::string& id,
                                  const std::string& name, core::ObjectRole role,
                                  const std::string& material, const std::string& texture,
                                  const core::SurfaceMesh& surface, double density,
                                  core::Progress& progress);

/// Removes the boundary slivers of `body` that gmsh's optimiser cannot reach: tets whose
/// smallest dihedral angle is below `min_dihedral_degrees`, whose four nodes are all surface
/// vertices (index < `surface_nodes`) and two of whose faces are on the boundary — a flat tet
/// spanning a nearly planar quad of the surface. Removing one moves the boundary onto its two
/// inner faces (a change of its volume only, ≈ 0); a tet is kept when removing it would leave a
/// node without tets. Refreshes surface_faces (and tet_labels). Returns the number removed.
std::size_t remove_boundary_slivers(core::TetMesh& body, std::size_t surface_nodes,
                                    double min_dihedral_degrees);

/// Connects `part` to `host` (seed 001 §3.3: at the nearest knots): each of the part's body
/// nodes in `part_nodes` (its base on the host) is paired with its nearest host knot within
/// `within` m. Nothing is pinned in world space: the simulator binds a pathology's paired nodes
/// to the host tets that hold them at rest (barycentric attachments, `stiffness` N/m each), so
/// the part moves with its host. Throws core::InputError when fewer than 3 pairs are found (the
/// part does not touch its host).
void attach(core::Scenario& scenario, const std::string& host, const std::string& part,
            const std::vector<int>& part_nodes, double within, double stiffness = 200.0);

}  // namespace viscera::templates
