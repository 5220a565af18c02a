#pragma once
/// Consistent penetration depth and direction for colliding tetrahedral meshes (Heidelberger,
/// Teschner, Keiser, Müller & Gross 2004; seed 000 §4.2, eq. 8–9). Border points — colliding
/// points with a non-colliding neighbour — take a weighted average over the points where their
/// edges to non-colliding neighbours cross the penetrated surface; the other colliding points
/// receive depth and direction by propagation from processed neighbours, layer by layer.

#include <array>
#include <span>
#include <vector>

#include "core/math_types.h"

namespace viscera::sim {

/// Vertex adjacency of a mesh in compressed rows: the neighbours of v are
/// neighbours[offsets[v] .. offsets[v+1]).
struct VertexAdjacency {
  std::vector<int> offsets;
  std::vector<int> neighbours;

  /// From undirected edges over `vertex_count` vertices; neighbours sorted ascending.
  static VertexAdjacency from_edges(std::size_t vertex_count,
                                    std::span<const std::array<int, 2>> edges);
  /// The edges of tetrahedra over `vertex_count` vertices (each edge once, however many tets
  /// share it); neighbours sorted ascending, as from_edges gives them.
  static VertexAdjacency from_tets(std::size_t vertex_count,
                                   std::span<const std::array<int, 4>> tets);
  std::span<const int> of(int v) const {
    return {neighbours.data() + offsets[v], static_cast<std::size_t>(offsets[v + 1] - offsets[v])};
  }
};

/// The closed, outward-oriented surface of the penetrated body at its current positions.
struct PenetratedSurface {
  std::span<const core::Vec3> positions;  ///< m
  std::span<const core::Triangle> faces;  ///< outward
};

/// Depth in m and unit direction out of the penetrated body for one colliding point: moving the
/// point by depth · direction resolves its penetration.
struct PointPenetration {
  int point = 0;
  double depth = 0.0;
  core::Vec3 direction = core::Vec3::Zero();
  bool border = false;  ///< depth from surface intersections (stage 2) rather than propagation
};

/// Penetration of the `colliding` points (sorted, unique) of a mesh with `positions` and
/// `adjacency` into `surface`. Points that neither touch an intersection nor connect to a
/// processed point (an isolated colliding component) are left out of the result.
/// Cost: O(colliding points × neighbours + candidate triangles of the intersection tests).
std::vector<PointPenetration> penetration_depths(std::span<const core::Vec3> positions,
                                                 const VertexAdjacency& adjacency,
                                                 std::span<const int> colliding,
                                                 const PenetratedSurface& surface);

/// Where segment p→q first crosses triangle (a, b, c), as the parameter t ∈ [0, 1] along the
/// segment, or a negative value when it does not (Möller & Trumbore 1997).
double segment_triangle_intersection(const core::Vec3& p, const core::Vec3& q, const core::Vec3& a,
                                     const core::Vec3& b, const core::Vec3& c);

}  // namespace viscera::sim
