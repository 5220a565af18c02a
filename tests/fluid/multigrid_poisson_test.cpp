// The pressure solver (simulator/fluid/multigrid_poisson): it recovers a known pressure from the
// right-hand side it produces (up to a constant when no cell is open), its iteration count stays
// flat as the grid is refined (what the multigrid preconditioner is for), planar grids are
// solved in 2D, and the thread count changes no bit.

#include "simulator/fluid/multigrid_poisson.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/random.h"
#include "tests/support/walled_flow_box.h"

using namespace viscera;
using namespace viscera::sim::fluid;

namespace {

/// An n×n×nz box of 1 mm cells walled all round with a solid pillar inside and, when `open`, an
/// outflow patch on one wall.
FlowGrid vessel_box(int n, int nz, bool open) {
  FlowGrid grid(n, n, nz, 0.001);
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const bool wall =
            i == 0 || j == 0 || i == n - 1 || j == n - 1 || (nz > 1 && (k == 0 || k == nz - 1));
        const bool pillar = i >= n / 3 && i < n / 3 + 2 && j >= n / 2 && j < n / 2 + 3;
        if (wall || pillar) grid.set_cell(i, j, k, FlowCell::Solid);
      }
  if (open)
    for (int j = n / 4; j < n / 4 + 2; ++j)
      grid.set_cell(n - 1, j, nz > 1 ? nz / 2 : 0, FlowCell::Open);
  grid.update_faces();
  return grid;
}

/// (A p)_c written out cell by cell from the labels, independently of the solver's padding.
std::vector<double> apply_laplacian(const FlowGrid& grid, const std::vector<double>& p) {
  std::vector<double> out(p.size(), 0.0);
  for (int k = 0; k < grid.nz(); ++k)
    for (int j = 0; j < grid.ny(); ++j)
      for (int i = 0; i < grid.nx(); ++i) {
        if (grid.cell(i, j, k) != FlowCell::Fluid) continue;
        double sum = 0.0;
        int sides = 0;
        const int offsets[6][3] = {{-1, 0, 0}, {1, 0, 0},  {0, -1, 0},
                                   {0, 1, 0},  {0, 0, -1}, {0, 0, 1}};
        for (const auto& o : offsets) {
          const FlowCell n = grid.cell_or_solid(i + o[0], j + o[1], k + o[2]);
          if (n == FlowCell::Solid) continue;
          ++sides;
          if (n == FlowCell::Fluid) sum += p[grid.cell_index(i + o[0], j + o[1], k + o[2])];
        }
        const int c = grid.cell_index(i, j, k);
        out[c] = sides * p[c] - sum;
      }
  return out;
}

std::vector<double> known_pressure(const FlowGrid& grid, std::uint64_t seed) {
  core::Rng rng(seed);
  std::vector<double> p(static_cast<std::size_t>(grid.cell_count()), 0.0);
  for (int c = 0; c < grid.cell_count(); ++c)
    p[c] = rng.uniform(-1.0, 1.0);
  return p;
}

double mean_over_unknowns(const MultigridPoisson& solver, const std::vector<double>& v) {
  double sum = 0.0;
  int count = 0;
  for (int c = 0; c < static_cast<int>(v.size()); ++c)
    if (solver.unknown(c)) sum += v[c], ++count;
  return sum / count;
}

}  // namespace

TEST(MultigridPoisson, recovers_a_known_pressure_from_its_right_hand_side) {
  for (const bool open : {true, false}) {
    const FlowGrid grid = vessel_box(20, 14, open);
    MultigridPoisson solver(grid);
    EXPECT_EQ(solver.has_open(), open);
    EXPECT_GE(solver.levels(), 3);
    std::vector<double> truth = known_pressure(grid, 5);
    for (int c = 0; c < grid.cell_count(); ++c)
      if (!solver.unknown(c)) truth[c] = 0.0;
    const std::vector<double> b = apply_laplacian(grid, truth);
    std::vector<double> p(b.size(), 0.0);
    PoissonSolveSettings settings;
    settings.residual_tolerance = 1e-10;
    settings.threads = 1;
    const PoissonSolveResult result = solver.solve(b, p, settings);
    ASSERT_TRUE(result.converged) << "open " << open;
    EXPECT_LE(result.largest_residual, 1e-10);
    // The residual it reports is the residual of what it returns.
    const std::vector<double> Ap = apply_laplacian(grid, p);
    double largest = 0.0;
    for (int c = 0; c < grid.cell_count(); ++c)
      if (solver.unknown(c)) largest = std::max(largest, std::abs(b[c] - Ap[c]));
    EXPECT_LE(largest, 1e-10);
    // Without an open cell the pressure is known up to a constant.
    const double shift =
        open ? 0.0 : mean_over_unknowns(solver, p) - mean_over_unknowns(solver, truth);
    for (int c = 0; c < grid.cell_count(); ++c)
      if (solver.unknown(c)) {
        EXPECT_NEAR(p[c] - shift, truth[c], 1e-6) << c;
      }
  }
}

TEST(MultigridPoisson, iterations_stay_flat_as_the_grid_is_refined) {
  // Jacobi-preconditioned CG needs iterations in proportion to n; one V-cycle per iteration
  // keeps the count nearly constant.
  std::vector<int> counts;
  for (const int n : {16, 32, 64}) {
    const FlowGrid grid = vessel_box(n, n, true);
    MultigridPoisson solver(grid);
    std::vector<double> truth = known_pressure(grid, 9);
    const std::vector<double> b = apply_laplacian(grid, truth);
    std::vector<double> p(b.size(), 0.0);
    double largest_b = 0.0;
    for (const double v : b)
      largest_b = std::max(largest_b, std::abs(v));
    PoissonSolveSettings settings;
    settings.residual_tolerance = 1e-8 * largest_b;
    const PoissonSolveResult result = solver.solve(b, p, settings);
    ASSERT_TRUE(result.converged) << n;
    counts.push_back(result.iterations);
  }
  EXPECT_LE(counts.back(), 30);
  EXPECT_LE(counts.back(), counts.front() + 8)
      << counts[0] << ", " << counts[1] << ", " << counts[2];
}

TEST(MultigridPoisson, a_small_outflow_in_a_walled_box_takes_few_iterations) {
  // The flow benchmark's case: all walls but a 2×2-cell outflow, a nearly singular matrix. With
  // coarse levels rediscretised "open if any child is open" and two ⅔-Jacobi sweeps this took
  // 16 iterations; aggregated coarse levels and Chebyshev-weighted sweeps take 10.
  FlowGrid grid = test::walled_flow_box(32, 32, 32, 0.001);
  for (int dj = 0; dj < 2; ++dj)
    for (int dk = 0; dk < 2; ++dk)
      grid.set_cell(31, 8 + dj, 16 + dk, FlowCell::Open);
  grid.update_faces();
  MultigridPoisson solver(grid);
  core::Rng rng(7);
  std::vector<double> b(static_cast<std::size_t>(grid.cell_count()), 0.0), p(b.size(), 0.0);
  for (int c = 0; c < grid.cell_count(); ++c)
    if (solver.unknown(c)) b[c] = rng.uniform(-1.0, 1.0);
  PoissonSolveSettings settings;
  settings.residual_tolerance = 1e-8;
  settings.threads = 1;
  const PoissonSolveResult result = solver.solve(b, p, settings);
  ASSERT_TRUE(result.converged);
  EXPECT_LE(result.iterations, 12);
}

TEST(MultigridPoisson, solves_a_planar_grid_in_two_dimensions) {
  const FlowGrid grid = vessel_box(40, 1, true);
  MultigridPoisson solver(grid);
  std::vector<double> truth = known_pressure(grid, 3);
  for (int c = 0; c < grid.cell_count(); ++c)
    if (!solver.unknown(c)) truth[c] = 0.0;
  const std::vector<double> b = apply_laplacian(grid, truth);
  std::vector<double> p(b.size(), 0.0);
  PoissonSolveSettings settings;
  settings.residual_tolerance = 1e-11;
  const PoissonSolveResult result = solver.solve(b, p, settings);
  ASSERT_TRUE(result.converged);
  EXPECT_LE(result.iterations, 25);
  for (int c = 0; c < grid.cell_count(); ++c)
    if (solver.unknown(c)) {
      EXPECT_NEAR(p[c], truth[c], 1e-7);
    }
}

TEST(MultigridPoisson, any_number_of_threads_gives_the_same_bits) {
  const FlowGrid grid = vessel_box(23, 17, false);
  std::vector<double> reference;
  for (const int threads : {1, 2, 3}) {
    MultigridPoisson solver(grid);
    std::vector<double> truth = known_pressure(grid, 1);
    std::vector<double> b = apply_laplacian(grid, truth);
    std::vector<double> p(b.size(), 0.0);
    PoissonSolveSettings settings;
    settings.threads = threads;
    solver.solve(b, p, settings);
    if (threads == 1)
      reference = p;
    else
      EXPECT_EQ(p, reference) << threads << " threads";
  }
}
