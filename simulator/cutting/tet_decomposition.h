#pragma once
/// The decomposition patterns of the hybrid cut (Steinemann, Harders, Gross & Székely 2006;
/// seed 000 §5.1: "five rotationally invariant schemes to decompose a tetrahedron that has at
/// least one of its edges cut. In addition, there are three schemes where one, two, or three
/// existing nodes are separated").
///
/// After node snapping every corner of a traversed tet is on the cut (0) or on one side (±1),
/// and an edge is cut exactly when its corners lie on opposite sides. Up to rotation the tet
/// then falls in one of these patterns (the node-separation schemes need no new tets: the
/// corners on the cut are duplicated afterwards by hybrid_cut):
///   cut edges | corners (+ / − / 0) | pieces                         | child tets
///   1         | 1 / 1 / 2           | two tets                       | 2
///   2         | 1 / 2 / 1           | tet + pyramid                  | 3
///   3         | 1 / 3 / 0           | tet + prism                    | 4
///   4         | 2 / 2 / 0           | two prisms                     | 6
/// Quads on the tet's faces (shared with the neighbour) and the cut quad of the 4-edge pattern
/// are split by the diagonal through their lowest-ranked corner, a rule that depends only on the
/// quad, so both tets of a shared face split it the same way and the mesh stays conforming; on a
/// prism it never gives the cyclic diagonals that admit no tetrahedralisation (Dompierre,
/// Labbé, Vallet & Camarero 1999).

#include <array>
#include <cstdint>
#include <vector>

namespace viscera::sim::cutting {

/// Local corner pairs of the six edges, in the order used by TetCutPattern::edge_cut.
inline constexpr std::array<std::array<int, 2>, 6> kTetEdges{
    {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}}};

/// One traversed tet. Local vertices 0–3 are its corners, 4 + e the node on edge e.
struct TetCutPattern {
  std::array<int, 4> side{};       ///< −1, 0 (on the cut) or +1 per corner
  std::array<bool, 6> edge_cut{};  ///< true when edge e is cut (its corners on opposite sides)
  std::array<std::uint64_t, 10> rank{};  ///< global order of the local vertices (quad diagonals)
};

/// Child tets as local vertex indices (orientation not fixed: the caller orients them by
/// their volume). Returns no children when no edge is cut. Throws std::logic_error when the
/// sides and cut edges disagree (a caller bug, never input).
std::vector<std::array<int, 4>> decompose(const TetCutPattern& pattern);

}  // namespace viscera::sim::cutting
