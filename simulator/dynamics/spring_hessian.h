#pragma once
/// The 3×3 Hessian block of a radial two-node potential E(|d|), d = x_j − x_i: with E' the
/// force magnitude and E'' its derivative, ∂²E/∂d² = E'' d̂d̂ᵀ + E'/|d| (I − d̂d̂ᵀ). Blocks:
/// (j, j) and (i, i) get +H, (i, j) gets −H. Projection to positive semi-definite clamps the two
/// eigenvalues E'' and E'/|d| at zero (exact for this rank-structured block).

#include "simulator/dynamics/block_sparse_matrix.h"

namespace viscera::sim {

/// H for direction `unit`, length `length` (m), dE/dl `first` (N), d²E/dl² `second` (N/m).
inline Mat3 radial_hessian(const Vec3& unit, double length, double first, double second,
                           bool project) {
  double along = second;
  double across = length > 0.0 ? first / length : 0.0;
  if (project) {
    along = along > 0.0 ? along : 0.0;
    across = across > 0.0 ? across : 0.0;
  }
  const Mat3 outer = unit * unit.transpose();
  return along * outer + across * (Mat3::Identity() - outer);
}

/// Adds scale·H at (i,i), (j,j) and −scale·H at (i,j), (j,i).
inline void add_pair_block(BlockSparseMatrix& m, int i, int j, const Mat3& h, double scale) {
  m.add_symmetric(i, i, scale * h);
  m.add_symmetric(j, j, scale * h);
  m.add_symmetric(i, j, -scale * h);
}

}  // namespace viscera::sim
