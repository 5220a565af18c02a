#pragma once
/// Symmetric sparse matrices of 3×3 blocks over the global nodes (the stiffness K = ∂²E/∂x²
/// and damping D = −∂f/∂v of SOFA's addKToMatrix). The pattern is declared once per topology by
/// the force terms, the values are refilled every step; terms may keep slot indices until the
/// next topology change. Both (i, j) and (j, i) are stored, so a product reads one row at a time.

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "core/math_types.h"

namespace viscera::sim {

using core::Vec3;
using Mat3 = Eigen::Matrix3d;

/// The (i, j) node pairs whose block a matrix holds; (i, i) is always present.
class BlockPattern {
 public:
  /// Every pattern gets a process-wide unique id, which the matrices set from it carry.
  explicit BlockPattern(std::size_t nodes = 0);
  /// Empties the pattern for `nodes` nodes under a new id, keeping the room of its pair list (a
  /// solver re-declaring after a cut allocates nothing).
  void reset(std::size_t nodes);
  std::uint64_t id() const { return id_; }
  std::size_t node_count() const { return nodes_; }
  /// Room for `pairs` declarations (a solver re-declaring a scene knows about how many).
  void reserve(std::size_t pairs) { pairs_.reserve(pairs); }
  /// Declares blocks (i, j) and (j, i).
  void add(int i, int j);
  /// Declares every pair of `nodes` (an element's blocks).
  void add_clique(std::span<const int> nodes);
  const std::vector<std::pair<int, int>>& pairs() const { return pairs_; }
  /// Records that every edge of the tets of `mesh` (a body's mesh, by its address) is declared:
  /// the body's distance term declares them all, and a term whose blocks are among them (the
  /// volume term's tet cliques, six blocks per tet that repeat each edge about five times) then
  /// need not declare them again. Until the next reset().
  void cover_tet_edges(const void* mesh) { covered_.push_back(mesh); }
  bool covers_tet_edges(const void* mesh) const;

 private:
  std::size_t nodes_;
  std::uint64_t id_;
  std::vector<std::pair<int, int>> pairs_;  ///< i < j
  std::vector<const void*> covered_;        ///< meshes whose tet edges are declared
};

/// Block-compressed rows: row i holds blocks at columns columns_[row_start_[i] .. row_start_[i+1]),
/// sorted, the diagonal among them.
class BlockSparseMatrix {
 public:
  /// Sets the blocks from `pattern`, all zero. The arrays keep their room between patterns and
  /// grow with a quarter to spare, so a cut's new pattern neither allocates nor touches fresh
  /// pages (which cost more than the pass itself, 0.3–0.7 ms for a 1,000-node scene).
  void set_pattern(const BlockPattern& pattern);
  /// The same blocks as `other` (set from one pattern: the same slots), all zero; a copy, not a
  /// second pass over the pattern.
  void set_structure_of(const BlockSparseMatrix& other);
  std::size_t node_count() const { return row_start_.empty() ? 0 : row_start_.size() - 1; }
  std::size_t block_count() const { return columns_.size(); }
  /// Id of the pattern the matrix was set from: terms that cache slot indices refresh them
  /// when it changes (matrices set from one pattern share their slots).
  std::uint64_t pattern_id() const { return pattern_id_; }
  /// Slot of block (i, j); −1 when the pattern lacks it.
  int slot(int i, int j) const;
  /// Slot of the diagonal block (i, i).
  int diagonal_slot(int i) const { return diagonal_[static_cast<std::size_t>(i)]; }
  Mat3& block(int slot) { return blocks_[static_cast<std::size_t>(slot)]; }
  const Mat3& block(int slot) const { return blocks_[static_cast<std::size_t>(slot)]; }
  /// Adds `value` to block (i, j) and its transpose to (j, i) (once when i == j).
  void add_symmetric(int i, int j, const Mat3& value);
  void set_zero();
  /// y = A x.
  void multiply(std::span<const Vec3> x, std::span<Vec3> y) const;
  /// y += scale · A x.
  void multiply_add(std::span<const Vec3> x, double scale, std::span<Vec3> y) const;
  /// y = A x on the rows i with rows[i] ≠ 0 (the bits multiply() gives there), zero on the
  /// others: products restricted to some independent blocks of a block-diagonal matrix.
  void multiply_rows(std::span<const Vec3> x, std::span<Vec3> y, std::span<const char> rows) const;
  /// Row i's columns and slots, for solvers.
  std::span<const int> row_columns(int i) const;
  int row_begin(int i) const { return row_start_[static_cast<std::size_t>(i)]; }

 private:
  std::vector<int> row_start_, columns_, diagonal_;
  std::vector<Mat3> blocks_;
  std::uint64_t pattern_id_ = 0;
  std::vector<int> listed_, fill_, seen_in_row_;  ///< set_pattern's work arrays, kept
};

}  // namespace viscera::sim
