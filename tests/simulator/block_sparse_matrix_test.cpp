// The implicit solver's block-sparse matrix (simulator/dynamics/block_sparse_matrix.h): a pattern
// with repeated pairs (elements sharing an edge) gives each row its columns once, sorted, with
// the diagonal; a matrix given another's structure has the same slots; products match a dense
// matrix; a matrix and a pattern reused for the next topology (their room kept) give what fresh
// ones give.

#include "simulator/dynamics/block_sparse_matrix.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <utility>
#include <vector>

namespace viscera::sim {
namespace {

TEST(BlockSparseMatrix, a_pattern_with_repeated_pairs_gives_sorted_unique_rows_and_dense_products) {
  // Two tets sharing the face (1, 2, 3), declared as cliques, plus a repeated contact pair.
  BlockPattern pattern(6);
  const int a[] = {0, 1, 2, 3}, b[] = {3, 2, 1, 4};
  pattern.add_clique(a);
  pattern.add_clique(b);
  pattern.add(4, 0);
  pattern.add(0, 4);
  pattern.add(5, 5);  // a diagonal: always present anyway
  BlockSparseMatrix m;
  m.set_pattern(pattern);
  const std::vector<std::vector<int>> rows = {{0, 1, 2, 3, 4}, {0, 1, 2, 3, 4}, {0, 1, 2, 3, 4},
                                              {0, 1, 2, 3, 4}, {0, 1, 2, 3, 4}, {5}};
  ASSERT_EQ(m.node_count(), 6u);
  std::size_t blocks = 0;
  for (int i = 0; i < 6; ++i) {
    const auto columns = m.row_columns(i);
    EXPECT_EQ(std::vector<int>(columns.begin(), columns.end()), rows[static_cast<std::size_t>(i)])
        << "row " << i;
    EXPECT_EQ(m.diagonal_slot(i), m.slot(i, i));
    blocks += columns.size();
  }
  EXPECT_EQ(m.block_count(), blocks);
  EXPECT_EQ(m.slot(5, 0), -1);

  // Fill it and compare A x with the dense product.
  Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(18, 18);
  for (int i = 0; i < 6; ++i)
    for (int j = i; j < 6; ++j) {
      if (m.slot(i, j) < 0) continue;
      Mat3 value;
      value << i + 1, j, 0.5, j, 2.0 * i, 1, 0.5, 1, i + j + 3;
      if (i == j) value = 0.5 * (value + value.transpose()).eval();
      m.add_symmetric(i, j, value);
      dense.block<3, 3>(3 * i, 3 * j) += value;
      if (i != j) dense.block<3, 3>(3 * j, 3 * i) += value.transpose();
    }
  std::vector<Vec3> x(6), y(6);
  Eigen::VectorXd flat(18);
  for (int i = 0; i < 6; ++i) {
    x[static_cast<std::size_t>(i)] = Vec3(0.1 * i, 1.0 - i, 0.3 + i * i);
    flat.segment<3>(3 * i) = x[static_cast<std::size_t>(i)];
  }
  m.multiply(x, y);
  const Eigen::VectorXd expected = dense * flat;
  for (int i = 0; i < 6; ++i)
    EXPECT_LT((y[static_cast<std::size_t>(i)] - expected.segment<3>(3 * i)).norm(), 1e-12);

  // The same structure, zeroed, in a second matrix.
  BlockSparseMatrix twin;
  twin.set_structure_of(m);
  EXPECT_EQ(twin.pattern_id(), m.pattern_id());
  ASSERT_EQ(twin.block_count(), m.block_count());
  for (int i = 0; i < 6; ++i) {
    const auto c = twin.row_columns(i), d = m.row_columns(i);
    EXPECT_EQ(std::vector<int>(c.begin(), c.end()), std::vector<int>(d.begin(), d.end()));
    for (const int j : c)
      EXPECT_EQ(twin.block(twin.slot(i, j)), Mat3::Zero());
  }
}

/// A chain of `nodes` nodes with neighbours `reach` apart, declared in `pattern`.
void declare_chain(BlockPattern& pattern, int nodes, int reach) {
  for (int i = 0; i + reach < nodes; ++i)
    for (int r = 1; r <= reach; ++r)
      pattern.add(i, i + r);
}

TEST(BlockSparseMatrix, a_reused_matrix_and_pattern_equal_fresh_ones_for_each_new_topology) {
  BlockSparseMatrix reused, reused_twin;
  BlockPattern kept;
  // Big, then smaller, then bigger than ever (the arrays grow), as cuts and rebuilds go.
  for (const auto& [nodes, reach] : {std::pair{40, 3}, std::pair{12, 2}, std::pair{90, 4}}) {
    const std::uint64_t last_id = kept.id();
    kept.reset(static_cast<std::size_t>(nodes));
    EXPECT_NE(kept.id(), last_id);
    declare_chain(kept, nodes, reach);
    reused.set_pattern(kept);
    reused_twin.set_structure_of(reused);
    BlockPattern fresh_pattern(static_cast<std::size_t>(nodes));
    declare_chain(fresh_pattern, nodes, reach);
    BlockSparseMatrix fresh;
    fresh.set_pattern(fresh_pattern);
    ASSERT_EQ(reused.node_count(), fresh.node_count());
    ASSERT_EQ(reused.block_count(), fresh.block_count());
    ASSERT_EQ(reused_twin.block_count(), fresh.block_count());
    EXPECT_EQ(reused.pattern_id(), kept.id());
    for (int i = 0; i < nodes; ++i) {
      const auto r = reused.row_columns(i), f = fresh.row_columns(i);
      EXPECT_EQ(std::vector<int>(r.begin(), r.end()), std::vector<int>(f.begin(), f.end()))
          << nodes << " nodes, row " << i;
      EXPECT_EQ(reused_twin.diagonal_slot(i), fresh.diagonal_slot(i));
      for (const int j : r) {
        EXPECT_EQ(reused.block(reused.slot(i, j)), Mat3::Zero());
        EXPECT_EQ(reused_twin.block(reused_twin.slot(i, j)), Mat3::Zero());
      }
    }
    // Dirty both for the next round.
    reused.block(reused.diagonal_slot(0)) = Mat3::Identity();
    reused_twin.block(reused_twin.diagonal_slot(0)) = Mat3::Identity();
  }
}

}  // namespace
}  // namespace viscera::sim
