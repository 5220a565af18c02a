#pragma once
// Finite-difference checks of a force term: its forces are minus the gradient of its energy and
// its exact Hessian (add_stiffness, project = false) is minus the derivative of its forces.

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <vector>

#include "simulator/dynamics/force_term.h"

namespace viscera::testing {

/// Largest |f + ∇E| over all coordinates at x (v = 0), ∇E by central differences of step eps.
inline double force_gradient_mismatch(const sim::ForceTerm& term, std::vector<core::Vec3> x,
                                      double eps) {
  const std::vector<core::Vec3> zero(x.size(), core::Vec3::Zero());
  std::vector<core::Vec3> f(x.size(), core::Vec3::Zero());
  term.add_forces(x, zero, f);
  double worst = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      const double keep = x[i][k];
      x[i][k] = keep + eps;
      const double up = term.energy(x);
      x[i][k] = keep - eps;
      const double down = term.energy(x);
      x[i][k] = keep;
      worst = std::max(worst, std::abs(f[i][k] + (up - down) / (2.0 * eps)));
    }
  return worst;
}

/// Largest |K e_jk + ∂f/∂x_jk| over all columns, K the exact Hessian at x, the derivative of
/// the forces (v = 0) by central differences of step eps.
inline double hessian_force_mismatch(const sim::ForceTerm& term, std::vector<core::Vec3> x,
                                     double eps) {
  const std::size_t n = x.size();
  sim::BlockPattern pattern(n);
  term.declare_blocks(pattern);
  sim::BlockSparseMatrix k;
  k.set_pattern(pattern);
  k.set_zero();
  term.add_stiffness(x, 1.0, false, k);
  const std::vector<core::Vec3> zero(n, core::Vec3::Zero());
  std::vector<core::Vec3> unit(n, core::Vec3::Zero()), column(n), up(n), down(n);
  double worst = 0.0;
  for (std::size_t j = 0; j < n; ++j)
    for (int a = 0; a < 3; ++a) {
      unit[j][a] = 1.0;
      k.multiply(unit, column);
      unit[j][a] = 0.0;
      const double keep = x[j][a];
      std::fill(up.begin(), up.end(), core::Vec3::Zero());
      std::fill(down.begin(), down.end(), core::Vec3::Zero());
      x[j][a] = keep + eps;
      term.add_forces(x, zero, up);
      x[j][a] = keep - eps;
      term.add_forces(x, zero, down);
      x[j][a] = keep;
      for (std::size_t i = 0; i < n; ++i)
        worst =
            std::max(worst, (column[i] + (up[i] - down[i]) / (2.0 * eps)).cwiseAbs().maxCoeff());
    }
  return worst;
}

/// Smallest eigenvalue of the projected Hessian (add_stiffness, project = true) assembled
/// densely: ≥ 0 up to rounding for a term fit for implicit solves.
inline double smallest_projected_eigenvalue(const sim::ForceTerm& term,
                                            const std::vector<core::Vec3>& x) {
  const std::size_t n = x.size();
  sim::BlockPattern pattern(n);
  term.declare_blocks(pattern);
  sim::BlockSparseMatrix k;
  k.set_pattern(pattern);
  k.set_zero();
  term.add_stiffness(x, 1.0, true, k);
  Eigen::MatrixXd dense(3 * n, 3 * n);
  std::vector<core::Vec3> unit(n, core::Vec3::Zero()), column(n);
  for (std::size_t j = 0; j < n; ++j)
    for (int a = 0; a < 3; ++a) {
      unit[j][a] = 1.0;
      k.multiply(unit, column);
      unit[j][a] = 0.0;
      for (std::size_t i = 0; i < n; ++i)
        for (int b = 0; b < 3; ++b)
          dense(3 * i + b, 3 * j + a) = column[i][b];
    }
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(0.5 * (dense + dense.transpose()));
  return solver.eigenvalues().minCoeff();
}

}  // namespace viscera::testing
