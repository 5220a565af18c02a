#pragma once
/// Layered volumetric bodies (seed 001 §3.3: "An object with multiple layers is modelled by
/// scaling copies of the object and connecting layer knots with other knots on the neighbouring
/// layers using virtual springs, so that volumetric elements are created", Fig. 4 right).
///
/// Two bodies come from the same layers: KisMo's mass-spring net — every vertex of every copy a
/// knot, springs along the copies' edges, between a knot and its copy, and across each quad
/// between neighbouring copies, the prisms between copies split into three tetrahedra each as
/// the volumetric elements — and, the default for physics, the shell between the surface and
/// its innermost copy filled with gmsh tetrahedra. Positions in m.

#include <array>
#include <string>
#include <vector>

#include "core/mesh/surface_embedding.h"
#include "core/mesh/surface_mesh.h"
#include "core/mesh/tet_mesh.h"
#include "core/meshing/tet_mesher.h"
#include "core/progress.h"

namespace viscera::core {

/// How the inner copies are made.
enum class LayerMode {
  Offset,  ///< each vertex moved inward along its normal (even wall thickness)
  Scale    ///< the surface scaled about its centroid, as KisMo did
};
std::string to_string(LayerMode mode);
/// Parses "offset" or "scale"; throws UsageError otherwise.
LayerMode layer_mode_from_string(const std::string& name);

/// The copies of a surface.
struct LayerOptions {
  int layers = 1;          ///< inner copies, ≥ 1 (the surface itself is layer 0)
  double thickness = 0.0;  ///< m from the surface to the innermost copy (scale: on average)
  LayerMode mode = LayerMode::Offset;

  bool operator==(const LayerOptions&) const = default;
};

/// Vertex positions of layers 0 … layers (layer 0 is the surface). An open surface is offset
/// below its normal side. Throws UsageError for layers < 1, a thickness that is not positive, or
/// copies that fold (the thickness exceeds what the surface's curvature allows) — naming a vertex.
std::vector<std::vector<Vec3>> layer_positions(const SurfaceMesh& surface,
                                               const LayerOptions& options);

/// A KisMo mass-spring net. Knot l·n + i is vertex i of layer l (n vertices per layer).
struct MassSpringNet {
  std::vector<Vec3> knots;
  int knots_per_layer = 0;
  int layer_count = 0;                      ///< copies including the surface
  std::vector<std::array<int, 2>> springs;  ///< unique, sorted by knot indices
  std::vector<double> rest_length;          ///< m, one per spring
  std::vector<Tetrahedron> tets;            ///< volumetric elements, positively oriented
};

/// The net of `surface` and its copies. Each prism between neighbouring copies is split into
/// three tetrahedra with the diagonal of every quad face chosen from its smallest knot index, so
/// neighbouring prisms agree (Dompierre et al. 1999) and the springs are the tets' edges.
/// Throws as layer_positions, and UsageError naming the triangle when a prism is inverted.
MassSpringNet layered_mass_spring_net(const SurfaceMesh& surface, const LayerOptions& options);

/// The net as the simulator's body (BodyKind::MassSpring: springs on the tet edges): its knots,
/// tets and outward boundary faces; no masses (the simulator lumps them from the density).
TetMesh mass_spring_body(const MassSpringNet& net);

/// The shell between `surface` and its innermost copy filled by gmsh. A closed surface gives a
/// hollow shell; an open one a slab closed by a rim. Unless `meshing.cell_size` is set, the
/// cell size is thickness / layers (so about `layers` tets span the wall), capped by the mean
/// edge length. The surface's vertices are the body's first nodes.
TetMesh layered_shell_tets(const SurfaceMesh& surface, const LayerOptions& options,
                           TetMeshingOptions meshing = {}, Progress& progress = Progress::none());

/// Embeds the first `count` body nodes as visual vertices: vertex i rides on a tet holding node
/// i with weight 1 there (the visual surface is layer 0 of a layered body, or the boundary of a
/// body filled from it). Throws InputError when a node is in no tet.
SurfaceEmbedding embed_leading_nodes(const TetMesh& body, std::size_t count);

}  // namespace viscera::core
