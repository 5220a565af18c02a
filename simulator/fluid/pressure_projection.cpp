#include "simulator/fluid/pressure_projection.h"

#include <algorithm>
#include <cmath>

#include "simulator/fluid/grid_lines.h"

namespace viscera::sim::fluid {
namespace {

/// The Poisson matrix over the fluid cells: A p = Σ over non-solid neighbours (p_c − p_n), with
/// p = 0 held in open cells. Vectors span every cell and are 0 outside the fluid.
class PoissonMatrix {
 public:
  explicit PoissonMatrix(const FlowGrid& grid)
      : nx_(grid.nx()), ny_(grid.ny()), nz_(grid.nz()), planar_(grid.planar()) {
    diagonal_.assign(static_cast<std::size_t>(grid.cell_count()), 0.0);
    for (int k = 0; k < nz_; ++k) {
      for (int j = 0; j < ny_; ++j) {
        for (int i = 0; i < nx_; ++i) {
          if (grid.cell(i, j, k) != FlowCell::Fluid) continue;
          int open_sides = 0;
          const auto side = [&](int a, int b, int c) {
            if (grid.cell_or_solid(a, b, c) != FlowCell::Solid) ++open_sides;
          };
          side(i - 1, j, k), side(i + 1, j, k), side(i, j - 1, k), side(i, j + 1, k);
          if (!planar_) side(i, j, k - 1), side(i, j, k + 1);
          diagonal_[static_cast<std::size_t>(grid.cell_index(i, j, k))] = open_sides;
        }
      }
    }
    for (int k = 0; k < nz_ && !has_open_; ++k)
      for (int j = 0; j < ny_ && !has_open_; ++j)
        for (int i = 0; i < nx_ && !has_open_; ++i)
          has_open_ = grid.cell(i, j, k) == FlowCell::Open;
  }

  bool has_open() const { return has_open_; }
  double diagonal(std::size_t c) const { return diagonal_[c]; }

  /// (A x)_c for the cells of line (j, k), into `out`; returns Σ d_c (A x)_c over the line.
  double apply_line(int j, int k, const std::vector<double>& x, std::vector<double>& out,
                    const std::vector<double>& d) const {
    return apply_line(j, k, x, out, &d);
  }
  void apply_line(int j, int k, const std::vector<double>& x, std::vector<double>& out) const {
    apply_line(j, k, x, out, nullptr);
  }

 private:
  double apply_line(int j, int k, const std::vector<double>& x, std::vector<double>& out,
                    const std::vector<double>* d) const {
    double dot = 0.0;
    const int row = nx_ * (j + ny_ * k);
    const int plane = nx_ * ny_;
    for (int i = 0; i < nx_; ++i) {
      const auto c = static_cast<std::size_t>(row + i);
      if (diagonal_[c] == 0.0) {
        out[c] = 0.0;
        continue;
      }
      double s = diagonal_[c] * x[c];
      if (i > 0) s -= x[c - 1];
      if (i + 1 < nx_) s -= x[c + 1];
      if (j > 0) s -= x[c - static_cast<std::size_t>(nx_)];
      if (j + 1 < ny_) s -= x[c + static_cast<std::size_t>(nx_)];
      if (!planar_) {
        if (k > 0) s -= x[c - static_cast<std::size_t>(plane)];
        if (k + 1 < nz_) s -= x[c + static_cast<std::size_t>(plane)];
      }
      out[c] = s;
      if (d != nullptr) dot += (*d)[c] * s;
    }
    return dot;
  }

  int nx_, ny_, nz_;
  bool planar_;
  bool has_open_ = false;
  std::vector<double> diagonal_;  ///< non-solid neighbours of each fluid cell; 0 elsewhere
};

/// h·∇·u of fluid cell (i,j,k): the net outflow through its faces, m/s.
double net_outflow(const FlowGrid& grid, int i, int j, int k) {
  const FaceDims du = grid.face_dims(0), dv = grid.face_dims(1), dw = grid.face_dims(2);
  const auto& u = grid.velocity(0);
  const auto& v = grid.velocity(1);
  const auto& w = grid.velocity(2);
  return u[static_cast<std::size_t>(du.index(i + 1, j, k))] -
         u[static_cast<std::size_t>(du.index(i, j, k))] +
         v[static_cast<std::size_t>(dv.index(i, j + 1, k))] -
         v[static_cast<std::size_t>(dv.index(i, j, k))] +
         (grid.planar() ? 0.0
                        : w[static_cast<std::size_t>(dw.index(i, j, k + 1))] -
                              w[static_cast<std::size_t>(dw.index(i, j, k))]);
}

}  // namespace

ProjectionResult project(FlowGrid& grid, const ProjectionSettings& settings) {
  const int nx = grid.nx(), ny = grid.ny(), nz = grid.nz(), threads = settings.threads;
  const double h = grid.cell_size(), dt = settings.time_step;
  const PoissonMatrix A(grid);
  const auto n = static_cast<std::size_t>(grid.cell_count());
  std::vector<double> b(n, 0.0), r(n, 0.0), z(n, 0.0), d(n, 0.0), q(n, 0.0), partials;
  std::vector<double>& p = grid.pressure();

  // b = −(h/Δt)·(h ∇·u); a closed region's b must sum to zero.
  double b_sum = 0.0, fluid = 0.0;
  for (int k = 0; k < nz; ++k) {
    for (int j = 0; j < ny; ++j) {
      for (int i = 0; i < nx; ++i) {
        const auto c = static_cast<std::size_t>(grid.cell_index(i, j, k));
        if (A.diagonal(c) == 0.0) {
          p[c] = 0.0;
          continue;
        }
        b[c] = -(h / dt) * net_outflow(grid, i, j, k);
        b_sum += b[c];
        fluid += 1.0;
      }
    }
  }
  if (!A.has_open() && fluid > 0.0) {
    for (std::size_t c = 0; c < n; ++c)
      if (A.diagonal(c) != 0.0) b[c] -= b_sum / fluid;
  }

  // Jacobi-preconditioned CG from the last pressure; |r| ≤ tol·h²/Δt bounds |∇·u| by tol.
  const double r_tolerance = settings.divergence_tolerance * h * h / dt;
  for_each_line(ny, nz, threads, [&](int j, int k) { A.apply_line(j, k, p, q); });
  // Per-line: r = b − A p and z = M⁻¹ r over the fluid; returns Σ r·z, the line's max |r| in
  // `line_largest`.
  std::vector<double> line_largest(static_cast<std::size_t>(ny * nz));
  const auto residual_line = [&](int j, int k, bool restart, double alpha) {
    const std::size_t row = static_cast<std::size_t>(nx * (j + ny * k));
    double line_rz = 0.0, m = 0.0;
    for (std::size_t c = row; c < row + static_cast<std::size_t>(nx); ++c) {
      if (A.diagonal(c) == 0.0) {
        r[c] = z[c] = 0.0;
        continue;
      }
      if (restart) {
        r[c] = b[c] - q[c];
      } else {
        p[c] += alpha * d[c];
        r[c] -= alpha * q[c];
      }
      z[c] = r[c] / A.diagonal(c);
      line_rz += r[c] * z[c];
      m = std::max(m, std::abs(r[c]));
    }
    line_largest[static_cast<std::size_t>(j + ny * k)] = m;
    return line_rz;
  };
  const auto largest_residual = [&] {
    double m = 0.0;
    for (const double line : line_largest)
      m = std::max(m, line);
    return m;
  };
  double rz = sum_over_lines(ny, nz, threads, partials,
                             [&](int j, int k) { return residual_line(j, k, true, 0.0); });
  double largest = largest_residual();
  d = z;

  ProjectionResult result;
  while (largest > r_tolerance && result.iterations < settings.max_iterations) {
    const double dq = sum_over_lines(ny, nz, threads, partials,
                                     [&](int j, int k) { return A.apply_line(j, k, d, q, d); });
    if (!(dq > 0.0)) break;
    const double alpha = rz / dq;
    const double rz_next = sum_over_lines(
        ny, nz, threads, partials, [&](int j, int k) { return residual_line(j, k, false, alpha); });
    largest = largest_residual();
    const double beta = rz_next / rz;
    rz = rz_next;
    for_each_line(ny, nz, threads, [&](int j, int k) {
      const std::size_t row = static_cast<std::size_t>(nx * (j + ny * k));
      for (std::size_t c = row; c < row + static_cast<std::size_t>(nx); ++c)
        d[c] = z[c] + beta * d[c];
    });
    ++result.iterations;
  }
  result.converged = largest <= r_tolerance;

  // u −= Δt ∇p on the active faces (p = 0 in open cells, solid faces untouched).
  const double scale = dt / h;
  for (int axis = 0; axis < (grid.planar() ? 2 : 3); ++axis) {
    const FaceDims fd = grid.face_dims(axis);
    const auto& states = grid.face_states(axis);
    auto& velocity = grid.velocity(axis);
    for_each_line(fd.y, fd.z, threads, [&](int j, int k) {
      for (int i = 0; i < fd.x; ++i) {
        const auto f = static_cast<std::size_t>(fd.index(i, j, k));
        if (states[f] != FaceState::Active) continue;
        // Cells on the face's two sides; an index past the grid only occurs for solid sides.
        const int ci = i - (axis == 0), cj = j - (axis == 1), ck = k - (axis == 2);
        const double before = grid.cell(ci, cj, ck) == FlowCell::Fluid
                                  ? p[static_cast<std::size_t>(grid.cell_index(ci, cj, ck))]
                                  : 0.0;
        const double after = grid.cell(i, j, k) == FlowCell::Fluid
                                 ? p[static_cast<std::size_t>(grid.cell_index(i, j, k))]
                                 : 0.0;
        velocity[f] -= scale * (after - before);
      }
    });
  }
  result.max_divergence = grid.max_divergence();
  return result;
}

}  // namespace viscera::sim::fluid
