#include "simulator/dynamics/block_sparse_matrix.h"

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <stdexcept>
#include <string>

namespace viscera::sim {

namespace {

std::uint64_t next_pattern_id() {
  static std::atomic<std::uint64_t> next{1};
  return next.fetch_add(1);
}

/// Makes room for `size` elements with a quarter to spare when `v` must grow.
template <typename T>
void reserve_with_room(std::vector<T>& v, std::size_t size) {
  if (v.capacity() < size) v.reserve(size + size / 4);
}

}  // namespace

BlockPattern::BlockPattern(std::size_t nodes) : nodes_(nodes), id_(next_pattern_id()) {}

void BlockPattern::reset(std::size_t nodes) {
  nodes_ = nodes;
  id_ = next_pattern_id();
  pairs_.clear();
  covered_.clear();
}

bool BlockPattern::covers_tet_edges(const void* mesh) const {
  return std::find(covered_.begin(), covered_.end(), mesh) != covered_.end();
}

void BlockPattern::add(int i, int j) {
  if (i == j) return;  // diagonals are always present
  pairs_.emplace_back(std::min(i, j), std::max(i, j));
}

void BlockPattern::add_clique(std::span<const int> nodes) {
  for (std::size_t a = 0; a < nodes.size(); ++a)
    for (std::size_t b = a + 1; b < nodes.size(); ++b)
      add(nodes[a], nodes[b]);
}

void BlockSparseMatrix::set_pattern(const BlockPattern& pattern) {
  // Rows are filled with every declared neighbour once (a stamp per column drops the repeats
  // of elements sharing an edge as they come), then each short row is sorted: no sort over all
  // the pattern's pairs, which a cut's rebuild of a whole scene paid for.
  const std::size_t n = pattern.node_count();
  pattern_id_ = pattern.id();
  const auto& pairs = pattern.pairs();
  // Row starts of the listed neighbours (fill_ counts, then starts), diagonal included.
  reserve_with_room(fill_, n + 1);
  fill_.assign(n + 1, 1);
  fill_[0] = 0;
  for (const auto& [i, j] : pairs) {
    ++fill_[static_cast<std::size_t>(i) + 1];
    ++fill_[static_cast<std::size_t>(j) + 1];
  }
  for (std::size_t i = 0; i < n; ++i)
    fill_[i + 1] += fill_[i];
  // Neighbours listed by row: (row, column) in row order, through a counting pass; after it
  // fill_[i] is where row i's listing ends (and row i + 1's begins).
  reserve_with_room(listed_, static_cast<std::size_t>(fill_[n]));
  listed_.resize(static_cast<std::size_t>(fill_[n]));
  for (std::size_t i = 0; i < n; ++i)
    listed_[static_cast<std::size_t>(fill_[i]++)] = static_cast<int>(i);
  for (const auto& [i, j] : pairs) {
    listed_[static_cast<std::size_t>(fill_[static_cast<std::size_t>(i)]++)] = j;
    listed_[static_cast<std::size_t>(fill_[static_cast<std::size_t>(j)]++)] = i;
  }
  reserve_with_room(row_start_, n + 1);
  row_start_.assign(n + 1, 0);
  columns_.clear();
  reserve_with_room(columns_, listed_.size() / 2);
  reserve_with_room(seen_in_row_, n);
  seen_in_row_.assign(n, -1);
  for (std::size_t i = 0; i < n; ++i) {
    const auto row_begin = static_cast<std::ptrdiff_t>(columns_.size());
    for (int k = i == 0 ? 0 : fill_[i - 1]; k < fill_[i]; ++k) {
      const int column = listed_[static_cast<std::size_t>(k)];
      if (seen_in_row_[static_cast<std::size_t>(column)] == static_cast<int>(i)) continue;
      seen_in_row_[static_cast<std::size_t>(column)] = static_cast<int>(i);
      columns_.push_back(column);
    }
    // A row holds a few dozen columns: insertion sort, no introsort set-up per row.
    for (auto it = columns_.begin() + row_begin + 1; it < columns_.end(); ++it)
      for (auto at = it; at > columns_.begin() + row_begin && *(at - 1) > *at; --at)
        std::iter_swap(at - 1, at);
    row_start_[i + 1] = static_cast<int>(columns_.size());
  }
  reserve_with_room(diagonal_, n);
  diagonal_.assign(n, 0);
  for (std::size_t i = 0; i < n; ++i)
    diagonal_[i] = slot(static_cast<int>(i), static_cast<int>(i));
  reserve_with_room(blocks_, columns_.size());
  blocks_.assign(columns_.size(), Mat3::Zero());
}

void BlockSparseMatrix::set_structure_of(const BlockSparseMatrix& other) {
  // Copies into kept room, like set_pattern.
  const auto copy = [](const std::vector<int>& from, std::vector<int>& to) {
    reserve_with_room(to, from.size());
    to.assign(from.begin(), from.end());
  };
  copy(other.row_start_, row_start_);
  copy(other.columns_, columns_);
  copy(other.diagonal_, diagonal_);
  pattern_id_ = other.pattern_id_;
  reserve_with_room(blocks_, columns_.size());
  blocks_.assign(columns_.size(), Mat3::Zero());
}

int BlockSparseMatrix::slot(int i, int j) const {
  const auto begin = columns_.begin() + row_start_[static_cast<std::size_t>(i)];
  const auto end = columns_.begin() + row_start_[static_cast<std::size_t>(i) + 1];
  const auto it = std::lower_bound(begin, end, j);
  return it != end && *it == j ? static_cast<int>(it - columns_.begin()) : -1;
}

void BlockSparseMatrix::add_symmetric(int i, int j, const Mat3& value) {
  if (i == j) {
    blocks_[static_cast<std::size_t>(diagonal_[static_cast<std::size_t>(i)])] += value;
    return;
  }
  const int ij = slot(i, j), ji = slot(j, i);
  if (ij < 0 || ji < 0)
    throw std::logic_error("block (" + std::to_string(i) + ", " + std::to_string(j) +
                           ") was not declared in the matrix pattern");
  blocks_[static_cast<std::size_t>(ij)] += value;
  blocks_[static_cast<std::size_t>(ji)] += value.transpose();
}

void BlockSparseMatrix::set_zero() {
  for (Mat3& b : blocks_)
    b.setZero();
}

void BlockSparseMatrix::multiply(std::span<const Vec3> x, std::span<Vec3> y) const {
  for (std::size_t i = 0; i + 1 < row_start_.size(); ++i) {
    Vec3 sum = Vec3::Zero();
    for (int s = row_start_[i]; s < row_start_[i + 1]; ++s)
      sum.noalias() += blocks_[static_cast<std::size_t>(s)] *
                       x[static_cast<std::size_t>(columns_[static_cast<std::size_t>(s)])];
    y[i] = sum;
  }
}

void BlockSparseMatrix::multiply_rows(std::span<const Vec3> x, std::span<Vec3> y,
                                      std::span<const char> rows) const {
  for (std::size_t i = 0; i + 1 < row_start_.size(); ++i) {
    if (rows[i] == 0) {
      y[i].setZero();
      continue;
    }
    Vec3 sum = Vec3::Zero();
    for (int s = row_start_[i]; s < row_start_[i + 1]; ++s)
      sum.noalias() += blocks_[static_cast<std::size_t>(s)] *
                       x[static_cast<std::size_t>(columns_[static_cast<std::size_t>(s)])];
    y[i] = sum;
  }
}

void BlockSparseMatrix::multiply_add(std::span<const Vec3> x, double scale,
                                     std::span<Vec3> y) const {
  for (std::size_t i = 0; i + 1 < row_start_.size(); ++i) {
    Vec3 sum = Vec3::Zero();
    for (int s = row_start_[i]; s < row_start_[i + 1]; ++s)
      sum.noalias() += blocks_[static_cast<std::size_t>(s)] *
                       x[static_cast<std::size_t>(columns_[static_cast<std::size_t>(s)])];
    y[i] += scale * sum;
  }
}

std::span<const int> BlockSparseMatrix::row_columns(int i) const {
  const auto b = static_cast<std::size_t>(row_start_[static_cast<std::size_t>(i)]);
  const auto e = static_cast<std::size_t>(row_start_[static_cast<std::size_t>(i) + 1]);
  return {columns_.data() + b, e - b};
}

}  // namespace viscera::sim
