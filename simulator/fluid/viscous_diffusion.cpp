#include "simulator/fluid/viscous_diffusion.h"

#include <array>
#include <cmath>

#include "simulator/fluid/grid_lines.h"

namespace viscera::sim::fluid {
namespace {

/// Face neighbours along x, y, then z (a planar grid uses the first four).
constexpr std::array<std::array<int, 3>, 6> kNeighbours{
    {{-1, 0, 0}, {1, 0, 0}, {0, -1, 0}, {0, 1, 0}, {0, 0, -1}, {0, 0, 1}}};

/// (I − α∇²) over the active faces of one component, with its constant part (prescribed and
/// ghost neighbours) moved to the right-hand side.
class DiffusionMatrix {
 public:
  DiffusionMatrix(const FlowGrid& grid, int axis, double alpha)
      : d_(grid.face_dims(axis)),
        states_(grid.face_states(axis)),
        alpha_(alpha),
        planar_(grid.planar()) {
    const auto& u = grid.velocity(axis);
    diagonal_.assign(u.size(), 0.0);
    rhs_.assign(u.size(), 0.0);
    for (int k = 0; k < d_.z; ++k) {
      for (int j = 0; j < d_.y; ++j) {
        for (int i = 0; i < d_.x; ++i) {
          const auto f = static_cast<std::size_t>(d_.index(i, j, k));
          if (states_[f] != FaceState::Active) continue;
          double weight = 0.0, constant = 0.0;
          for (int n = 0; n < neighbour_count(); ++n) {
            const auto& [di, dj, dk] = kNeighbours[static_cast<std::size_t>(n)];
            const int a = i + di, b = j + dj, c = k + dk;
            if (a < 0 || b < 0 || c < 0 || a >= d_.x || b >= d_.y || c >= d_.z) {
              weight += 2.0;  // past the grid: a wall at rest
              continue;
            }
            const auto g = static_cast<std::size_t>(d_.index(a, b, c));
            switch (states_[g]) {
              case FaceState::Active:
                weight += 1.0;
                break;
              case FaceState::Prescribed:
                weight += 1.0;
                constant += u[g];
                break;
              case FaceState::Inside:  // ghost 2·u_wall − u across the wall
                weight += 2.0;
                constant += 2.0 * u[g];
                break;
            }
          }
          diagonal_[f] = 1.0 + alpha * weight;
          rhs_[f] = u[f] + alpha * constant;
        }
      }
    }
  }

  const FaceDims& dims() const { return d_; }
  bool active(std::size_t f) const { return states_[f] == FaceState::Active; }
  double diagonal(std::size_t f) const { return diagonal_[f]; }
  double rhs(std::size_t f) const { return rhs_[f]; }

  /// (A x) on line (j, k) into `out`; returns Σ y·(A x) over the line.
  double apply_line(int j, int k, const std::vector<double>& x, std::vector<double>& out,
                    const std::vector<double>& y) const {
    double dot = 0.0;
    for (int i = 0; i < d_.x; ++i) {
      const auto f = static_cast<std::size_t>(d_.index(i, j, k));
      if (!active(f)) continue;
      double s = diagonal_[f] * x[f];
      for (int n = 0; n < neighbour_count(); ++n) {
        const auto& [di, dj, dk] = kNeighbours[static_cast<std::size_t>(n)];
        const int a = i + di, b = j + dj, c = k + dk;
        if (a < 0 || b < 0 || c < 0 || a >= d_.x || b >= d_.y || c >= d_.z) continue;
        const auto g = static_cast<std::size_t>(d_.index(a, b, c));
        if (active(g)) s -= alpha_ * x[g];
      }
      out[f] = s;
      dot += y[f] * s;
    }
    return dot;
  }

 private:
  int neighbour_count() const { return planar_ ? 4 : 6; }

  FaceDims d_;
  const std::vector<FaceState>& states_;
  double alpha_;
  bool planar_;
  std::vector<double> diagonal_, rhs_;
};

}  // namespace

int diffuse(FlowGrid& grid, const DiffusionSettings& settings) {
  const double h = grid.cell_size();
  const double alpha = settings.viscosity * settings.time_step / (h * h);
  if (!(alpha > 0.0)) return 0;
  int iterations = 0;
  std::vector<double> partials;
  for (int axis = 0; axis < (grid.planar() ? 2 : 3); ++axis) {
    const DiffusionMatrix A(grid, axis, alpha);
    const FaceDims d = A.dims();
    std::vector<double>& x = grid.velocity(axis);
    const std::size_t n = x.size();
    std::vector<double> r(n, 0.0), z(n, 0.0), p(n, 0.0), q(n, 0.0);
    // x starts at the advected velocity, a close guess for small α.
    for_each_line(d.y, d.z, settings.threads, [&](int j, int k) { A.apply_line(j, k, x, q, q); });
    const auto line_start = [&](int j, int k) {
      double rz = 0.0;
      for (int i = 0; i < d.x; ++i) {
        const auto f = static_cast<std::size_t>(d.index(i, j, k));
        if (!A.active(f)) continue;
        r[f] = A.rhs(f) - q[f];
        z[f] = r[f] / A.diagonal(f);
        p[f] = z[f];
        rz += r[f] * z[f];
      }
      return rz;
    };
    double rz = sum_over_lines(d.y, d.z, settings.threads, partials, line_start);
    const double b_norm =
        std::sqrt(sum_over_lines(d.y, d.z, settings.threads, partials, [&](int j, int k) {
          double s = 0.0;
          for (int i = 0; i < d.x; ++i) {
            const auto f = static_cast<std::size_t>(d.index(i, j, k));
            if (A.active(f)) s += A.rhs(f) * A.rhs(f);
          }
          return s;
        }));
    const double target = settings.relative_tolerance * b_norm;
    for (int it = 0; it < settings.max_iterations; ++it) {
      const double r_norm =
          std::sqrt(sum_over_lines(d.y, d.z, settings.threads, partials, [&](int j, int k) {
            double s = 0.0;
            for (int i = 0; i < d.x; ++i) {
              const auto f = static_cast<std::size_t>(d.index(i, j, k));
              s += r[f] * r[f];
            }
            return s;
          }));
      if (r_norm <= target) break;
      const double pq = sum_over_lines(d.y, d.z, settings.threads, partials,
                                       [&](int j, int k) { return A.apply_line(j, k, p, q, p); });
      if (!(pq > 0.0)) break;
      const double step = rz / pq;
      const double rz_next =
          sum_over_lines(d.y, d.z, settings.threads, partials, [&](int j, int k) {
            double s = 0.0;
            for (int i = 0; i < d.x; ++i) {
              const auto f = static_cast<std::size_t>(d.index(i, j, k));
              if (!A.active(f)) continue;
              x[f] += step * p[f];
              r[f] -= step * q[f];
              z[f] = r[f] / A.diagonal(f);
              s += r[f] * z[f];
            }
            return s;
          });
      const double beta = rz_next / rz;
      rz = rz_next;
      for_each_line(d.y, d.z, settings.threads, [&](int j, int k) {
        for (int i = 0; i < d.x; ++i) {
          const auto f = static_cast<std::size_t>(d.index(i, j, k));
          if (A.active(f)) p[f] = z[f] + beta * p[f];
        }
      });
      ++iterations;
    }
  }
  return iterations;
}

}  // namespace viscera::sim::fluid
