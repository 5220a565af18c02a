#pragma once
/// Collision detection of deformable tetrahedral meshes by spatial hashing (Teschner,
/// Heidelberger, Müller, Pomeranets & Gross 2003; seed 000 §4.1). Pass 1 hashes every vertex
/// into the implicit grid cell that contains it; pass 2 hashes the cells covered by each
/// tetrahedron's bounding box and tests the vertices found there for containment. Instead of
/// the paper's time-stamped buckets the table is rebuilt per query as one compact array sorted
/// by bucket (a counting sort, O(vertices + table)): the same cost, but each bucket's vertices
/// lie next to each other in memory.

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "core/math_types.h"

namespace viscera::sim {

/// The deformed state of one body as the collision query sees it.
struct CollisionBodyView {
  std::span<const core::Vec3> positions;  ///< m
  std::span<const core::Tetrahedron> tets;
};

/// A vertex of one body inside a tetrahedron of another (or of the same body, for
/// self-collisions).
struct VertexInTet {
  int vertex_body = 0;
  int vertex = 0;
  int tet_body = 0;
  int tet = 0;
  std::array<double, 4> barycentric{};  ///< of the vertex in the tet, all ≥ 0

  bool operator==(const VertexInTet&) const = default;
};

/// Reusable spatial hash. Keeps its table between queries; not thread-safe.
class SpatialHash {
 public:
  /// `cell_size` in m (Teschner et al. found the mean edge length best); `table_size` buckets
  /// (a prime somewhat larger than the vertex count works well). Throws UsageError for a
  /// non-positive cell size or an empty table.
  SpatialHash(double cell_size, std::size_t table_size);

  /// Every vertex–tetrahedron containment between different bodies, and within a body when
  /// `self_collisions` (a vertex is never tested against a tet it belongs to). Sorted by
  /// (vertex_body, vertex, tet_body, tet), so results are deterministic.
  std::vector<VertexInTet> detect(std::span<const CollisionBodyView> bodies, bool self_collisions);

  /// The hash of Teschner et al. 2003 for integer cell (i, j, k): (i·73856093 xor j·19349663
  /// xor k·83492791) mod table size, in 32-bit arithmetic as in the paper.
  std::size_t hash(std::int64_t i, std::int64_t j, std::int64_t k) const;

  double cell_size() const { return cell_size_; }

 private:
  std::int64_t cell_of(double coordinate) const;

  /// x mod table size without a division (Lemire, Kaser & Kurz 2019), exact for 32-bit x.
  std::uint32_t reduce(std::uint32_t x) const;

  double cell_size_;
  double inverse_cell_size_;
  std::size_t table_size_;
  std::uint64_t reduce_factor_;
  std::vector<std::array<std::int32_t, 3>>
      cells_;                                 ///< scratch: cell of every vertex of a body with tets
  std::vector<std::size_t> first_cell_;       ///< per body: offset of its vertices in cells_
  std::vector<std::uint32_t> bucket_start_;   ///< table_size_ + 1 offsets into entries_
  std::vector<std::array<int, 2>> entries_;   ///< (body, vertex), grouped by bucket
  std::vector<std::uint32_t> vertex_bucket_;  ///< scratch: bucket of each hashed vertex
  std::vector<std::vector<std::int64_t>>
      last_tested_;  ///< per body and vertex: last cell range that listed it
};

/// Mean length in m of the tetrahedral edges of `bodies` (each edge counted once per tet that
/// has it): the cell size Teschner et al. recommend.
double mean_edge_length(std::span<const CollisionBodyView> bodies);

}  // namespace viscera::sim
