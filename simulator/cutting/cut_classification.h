#pragma once
/// First half of the hybrid cut (seed 000 §5.1; Steinemann et al. 2006): which tets the cut
/// surface traverses, where it crosses their edges, which nodes it snaps onto, and which side of
/// the cut every other corner lies on. Internal to simulator/cutting.

#include <cstdint>
#include <unordered_map>
#include <vector>

#include "core/mesh/tet_mesh.h"
#include "simulator/cutting/cut_surface_index.h"
#include "simulator/cutting/tet_decomposition.h"

namespace viscera::sim::cutting {

/// Key of the edge between nodes a and b (order-free).
inline std::uint64_t edge_key(int a, int b) {
  const auto lo = static_cast<std::uint64_t>(a < b ? a : b);
  const auto hi = static_cast<std::uint64_t>(a < b ? b : a);
  return (lo << 32) | hi;
}

/// Side of a node: kUnknown for nodes the cut does not decide.
inline constexpr std::int8_t kUnknownSide = 2;

/// Where the cut surface crosses one edge: t from its lower-indexed node to the higher one.
struct EdgeHit {
  double t = 0.0;
  int direction = 0;  ///< +1 when the lower node lies on the "−" side
};

struct CutClassification {
  std::vector<int> traversed;     ///< tets with a cut edge or a corner on the cut
  std::vector<std::int8_t> side;  ///< per node: −1, 0 (on the cut), +1 or kUnknownSide
  std::unordered_map<std::uint64_t, EdgeHit> hits;  ///< edges crossed away from their ends
  std::vector<std::uint64_t> cut_edges;             ///< sorted keys of the edges that get a node
  std::size_t snapped = 0;
};

/// Tuning of node snapping and the quality gate.
struct ClassificationOptions {
  double snap_fraction = 0.2;         ///< crossing within this fraction of an edge from a node
  double min_dihedral_degrees = 1.0;  ///< children below this, in either configuration, snap
};

/// True when edge (a, b) of the classification gets a node.
bool is_cut(const CutClassification& c, int a, int b);

/// The pattern of tet `t` (its corners' sides, cut edges and vertex ranks).
TetCutPattern pattern_of(const CutClassification& c, const core::Tetrahedron& tet, int node_count);

/// Position of the node on edge (a, b) for one configuration.
core::Vec3 edge_point(const CutClassification& c, const std::vector<core::Vec3>& x, int a, int b);

/// Smallest dihedral angle's cosine test and positive volume: true when the tet is fit.
bool tet_is_fit(const core::Vec3& a, const core::Vec3& b, const core::Vec3& c, const core::Vec3& d,
                double max_cos_dihedral);

/// Cosine of the smallest dihedral angle of a tet (1 for a flat or inverted one): the largest
/// cosine over its six edges, so the smallest angle of many tets is one arc cosine.
double max_cos_dihedral(const core::Vec3& a, const core::Vec3& b, const core::Vec3& c,
                        const core::Vec3& d);

/// An angle in degrees from its cosine.
double dihedral_degrees(double cos_dihedral);

/// Smallest dihedral angle of a tet in degrees (0 for a flat or inverted one).
double min_dihedral_degrees(const core::Vec3& a, const core::Vec3& b, const core::Vec3& c,
                            const core::Vec3& d);

/// Classifies the body against the cut. rest: body.nodes; current: deformed positions.
CutClassification classify_cut(const core::TetMesh& body, const std::vector<core::Vec3>& current,
                               const CutSurfaceIndex& index, const ClassificationOptions& options);

}  // namespace viscera::sim::cutting
