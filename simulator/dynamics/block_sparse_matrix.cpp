#include "simulator/dynamics/block_sparse_matrix.h"

#include <algorithm>
#include <atomic>
#include <stdexcept>
#include <string>

namespace viscera::sim {

BlockPattern::BlockPattern(std::size_t nodes) : nodes_(nodes) {
  static std::atomic<std::uint64_t> next{1};
  id_ = next.fetch_add(1);
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
  const std::size_t n = pattern.node_count();
  pattern_id_ = pattern.id();
  std::vector<std::pair<int, int>> pairs = pattern.pairs();
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  std::vector<int> count(n, 1);  // the diagonal
  for (const auto& [i, j] : pairs) {
    ++count[static_cast<std::size_t>(i)];
    ++count[static_cast<std::size_t>(j)];
  }
  row_start_.assign(n + 1, 0);
  for (std::size_t i = 0; i < n; ++i)
    row_start_[i + 1] = row_start_[i] + count[i];
  columns_.assign(static_cast<std::size_t>(row_start_[n]), 0);
  std::vector<int> fill(row_start_.begin(), row_start_.end() - 1);
  for (std::size_t i = 0; i < n; ++i)
    columns_[static_cast<std::size_t>(fill[i]++)] = static_cast<int>(i);
  for (const auto& [i, j] : pairs) {
    columns_[static_cast<std::size_t>(fill[static_cast<std::size_t>(i)]++)] = j;
    columns_[static_cast<std::size_t>(fill[static_cast<std::size_t>(j)]++)] = i;
  }
  diagonal_.assign(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    std::sort(columns_.begin() + row_start_[i], columns_.begin() + row_start_[i + 1]);
    diagonal_[i] = slot(static_cast<int>(i), static_cast<int>(i));
  }
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
