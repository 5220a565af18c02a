#pragma once
/// The pressure Poisson equation of the distension flow (seed 000 §2.2) solved by conjugate
/// gradients preconditioned with one geometric multigrid V-cycle — MGPCG after McAdams, Sifakis &
/// Teran 2010 ("A parallel multigrid Poisson solver for fluids simulation on large grids").
///
/// The matrix is the 7-point Laplacian over the fluid cells of a labelled grid, scaled by h²:
/// (A p)_c = n_c p_c − Σ p_n over the fluid neighbours, n_c the non-solid neighbours (Neumann at
/// solid cells, Dirichlet p = 0 in open cells). Coarse levels halve each axis of more than one
/// cell (a planar grid stays planar). A coarse level's operator is not rediscretised from labels
/// but aggregated from the level below (a Galerkin product with piecewise-constant transfers):
/// the coupling of two coarse cells is the sum of the couplings of the fine faces between their
/// children, and a coarse diagonal sums its children's couplings to cells outside it, open cells
/// included, each scaled by 1/4 (1/2 when planar) so that inside the fluid it is the
/// rediscretised stencil again. At a wall, an outflow or a partly solid coarse cell the coarse
/// operator then keeps the fine wall's position and the fine outflow's size; McAdams et al.'s
/// "open if any child is open" rule made a 2×2-cell outflow drain a whole coarse cell and moved
/// every wall by up to a coarse cell, and the coarse correction, not the smoother, set the rate
/// (9 iterations at 40³ for 2 or 3 sweeps). The unknowns of a coarse level are the cells with an
/// unknown child; open cells exist only on the finest level. Transfers are cell-centred
/// trilinear (weights ¾ and ¼ per axis), renormalised over the coarse unknowns so a wall does
/// not read as a zero pressure; restriction is the transpose of that prolongation. The smoother
/// is Jacobi with Chebyshev weights (three sweeps before and after each coarse correction,
/// together damping [0.15, 2] of D⁻¹A's spectrum by 0.36 — Adams et al. 2003), a polynomial
/// in D⁻¹A, so the V-cycle is symmetric and positive definite, as conjugate gradients require.
/// The V-cycle runs in single precision, as McAdams et al. run theirs: it only preconditions,
/// while the conjugate gradients around it — their residual, directions and the pressure — stay
/// in double, so the stated residual is met in double; half the bytes and twice the vector lanes
/// make each V-cycle about twice as fast. Every loop runs line by line over the threads and sums
/// in line order: bit-identical results for any thread count.

#include <cstdint>
#include <vector>

#include "simulator/fluid/flow_grid.h"

namespace viscera::sim::fluid {

struct PoissonSolveSettings {
  double residual_tolerance = 1e-9;  ///< largest |b − A p| left in a fluid cell (A's units)
  int max_iterations = 200;          ///< conjugate-gradient iterations before giving up
  int threads = 0;                   ///< worker threads; 0 = all cores
};

struct PoissonSolveResult {
  int iterations = 0;
  double largest_residual = 0.0;  ///< max |b − A p| over the fluid cells at the end
  bool converged = false;
};

/// The multigrid hierarchy of one labelling of a FlowGrid, reusable while the labels stay.
class MultigridPoisson {
 public:
  /// Builds the levels from `grid`'s cell labels (coarsening down to a few cells per axis).
  explicit MultigridPoisson(const FlowGrid& grid);

  int levels() const { return static_cast<int>(levels_.size()); }
  /// Whether the fine level has an open (Dirichlet) cell; without one A is singular and `b`
  /// must sum to zero over the fluid cells.
  bool has_open() const { return has_open_; }
  /// Whether cell c of the grid (FlowGrid::cell_index) is an unknown: fluid with at least one
  /// non-solid neighbour.
  bool unknown(int c) const { return unknown_[static_cast<std::size_t>(c)] != 0; }

  /// Solves A p = b; `b` and `p` are indexed like the grid's cells (values outside the unknowns
  /// are ignored in b and set to 0 in p). `p` holds the starting guess (the last step's pressure).
  PoissonSolveResult solve(const std::vector<double>& b, std::vector<double>& p,
                           const PoissonSolveSettings& settings);

 private:
  /// One level on a grid padded with solid cells (one before, two after along each axis, so the
  /// restriction of an odd-sized level stays inside), so stencils need no bounds tests.
  using Real = float;  ///< the V-cycle's precision
  struct Level {
    int nx = 0, ny = 0, nz = 0;          ///< cells
    int sx = 0, sy = 0;                  ///< padded strides: 1, sx, sx·sy
    std::vector<Real> diagonal;          ///< A_cc of an unknown, 0 elsewhere
    std::vector<Real> inverse_diagonal;  ///< 1 / A_cc of an unknown, 0 elsewhere
    /// −A between c and c + 1, c + sx, c + sxy (0 unless both are unknowns). Empty on the finest
    /// level, where every such coupling is 1 and the stencil needs no loads for it.
    std::vector<Real> face_x, face_y, face_z;
    std::vector<Real> prolongation_scale;  ///< 1 / Σ trilinear weights over the unknown parents
    std::vector<Real> x, b, r, scratch;
    std::vector<Real> restricted_x, restricted_xy;  ///< the restriction's partial sums into it
    std::size_t at(int i, int j, int k) const {
      return static_cast<std::size_t>((i + 1) + sx * ((j + 1) + sy * (k + 1)));
    }
    std::size_t size() const { return diagonal.size(); }
  };

  /// The finest level: nx×ny×nz cells labelled by `labels` (FlowCell values, cell order).
  void build_finest(Level& level, int nx, int ny, int nz, const std::vector<std::uint8_t>& labels);
  /// The next level's operator aggregated from `fine`'s (see the file comment).
  void coarsen(const Level& fine, Level& coarse) const;
  /// (A x)_c at padded index c of the finest level, in double for the conjugate gradients.
  static double apply(const Level& level, const std::vector<double>& x, std::size_t c) {
    const auto sx = static_cast<std::size_t>(level.sx),
               sxy = sx * static_cast<std::size_t>(level.sy);
    return static_cast<double>(level.diagonal[c]) * x[c] -
           (x[c - 1] + x[c + 1] + x[c - sx] + x[c + sx] + x[c - sxy] + x[c + sxy]);
  }
  void vcycle(std::size_t l, int threads);
  void smooth(Level& level, int sweeps, bool from_zero, int threads);
  void residual(Level& level, int threads);
  void restrict_residual(const Level& fine, Level& coarse, int threads);
  void prolong_add(const Level& coarse, Level& fine, int threads);
  void remove_mean(std::vector<Real>& v, const Level& level) const;

  std::vector<Level> levels_;
  std::vector<std::uint8_t> unknown_;  ///< per grid cell
  bool planar_ = false;
  bool has_open_ = false;
  double restriction_scale_ = 0.5;           ///< 4 / 2^d: A is h²-scaled and restriction averages
  std::vector<double> rhs_, p_, r_, d_, q_;  ///< the conjugate gradients' vectors (padded)
  std::vector<double> partials_, line_largest_;
};

}  // namespace viscera::sim::fluid
