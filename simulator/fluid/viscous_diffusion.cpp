#include "simulator/fluid/viscous_diffusion.h"

#include <cmath>

#include "simulator/fluid/grid_lines.h"

namespace viscera::sim::fluid {
namespace {

/// Face neighbours along x, y, then z (a planar grid uses the first four).
constexpr std::array<std::array<int, 3>, 6> kNeighbours{
    {{-1, 0, 0}, {1, 0, 0}, {0, -1, 0}, {0, 1, 0}, {0, 0, -1}, {0, 0, 1}}};

/// Unknowns per chunk of the parallel loops and sums.
constexpr int kChunk = 2048;

}  // namespace

void ViscousDiffusion::build(const FlowGrid& grid) {
  labelling_ = grid.labelling();
  const int neighbours = grid.planar() ? 4 : 6;
  for (int axis = 0; axis < 3; ++axis) {
    Component& c = components_[static_cast<std::size_t>(axis)];
    c = Component{};
    if (axis == 2 && grid.planar()) continue;
    const FaceDims d = grid.face_dims(axis);
    const auto& states = grid.face_states(axis);
    std::vector<int> unknown(states.size(), -1);
    for (std::size_t f = 0; f < states.size(); ++f) {
      if (states[f] != FaceState::Active) continue;
      unknown[f] = static_cast<int>(c.faces.size());
      c.faces.push_back(static_cast<int>(f));
    }
    const int m = static_cast<int>(c.faces.size());
    c.next.assign(c.faces.size(), {m, m, m, m, m, m});
    c.weight.assign(c.faces.size(), 0.0);
    c.boundary_start.assign(c.faces.size() + 1, 0);
    for (int u = 0; u < m; ++u) {
      const int f = c.faces[static_cast<std::size_t>(u)];
      const int i = f % d.x, j = (f / d.x) % d.y, k = f / (d.x * d.y);
      double weight = 0.0;
      for (int n = 0; n < neighbours; ++n) {
        const auto& [di, dj, dk] = kNeighbours[static_cast<std::size_t>(n)];
        const int a = i + di, b = j + dj, e = k + dk;
        if (a < 0 || b < 0 || e < 0 || a >= d.x || b >= d.y || e >= d.z) {
          weight += 2.0;  // past the grid: a wall at rest
          continue;
        }
        const int g = d.index(a, b, e);
        switch (states[static_cast<std::size_t>(g)]) {
          case FaceState::Active:
            weight += 1.0;
            c.next[static_cast<std::size_t>(u)][static_cast<std::size_t>(n)] =
                unknown[static_cast<std::size_t>(g)];
            break;
          case FaceState::Prescribed:
            weight += 1.0;
            c.boundary.emplace_back(g, 1.0);
            break;
          case FaceState::Inside:  // ghost 2·u_wall − u across the wall
            weight += 2.0;
            c.boundary.emplace_back(g, 2.0);
            break;
        }
      }
      c.weight[static_cast<std::size_t>(u)] = weight;
      c.boundary_start[static_cast<std::size_t>(u) + 1] = static_cast<int>(c.boundary.size());
    }
  }
}

int ViscousDiffusion::diffuse(FlowGrid& grid, const DiffusionSettings& settings) {
  const double h = grid.cell_size();
  const double alpha = settings.viscosity * settings.time_step / (h * h);
  if (!(alpha > 0.0)) return 0;
  if (grid.labelling() != labelling_) build(grid);
  const int threads = settings.threads;
  int iterations = 0;
  for (int axis = 0; axis < (grid.planar() ? 2 : 3); ++axis) {
    const Component& c = components_[static_cast<std::size_t>(axis)];
    const int m = static_cast<int>(c.faces.size());
    if (m == 0) continue;
    std::vector<double>& u = grid.velocity(axis);
    if (alpha <= settings.explicit_limit) {
      step_explicitly(c, u, alpha, threads);
      continue;
    }
    for (auto* v : {&x_, &b_, &r_, &z_, &p_, &q_})
      v->assign(static_cast<std::size_t>(m) + 1, 0.0);
    const auto diagonal = [&](int v) {
      return 1.0 + alpha * c.weight[static_cast<std::size_t>(v)];
    };
    // (A y) into q over [begin, end); returns Σ y·(A y) there.
    const auto apply = [&](const std::vector<double>& y, int begin, int end) {
      double dot = 0.0;
      for (int v = begin; v < end; ++v) {
        const auto& n = c.next[static_cast<std::size_t>(v)];
        const double around =
            y[static_cast<std::size_t>(n[0])] + y[static_cast<std::size_t>(n[1])] +
            y[static_cast<std::size_t>(n[2])] + y[static_cast<std::size_t>(n[3])] +
            y[static_cast<std::size_t>(n[4])] + y[static_cast<std::size_t>(n[5])];
        const double s = diagonal(v) * y[static_cast<std::size_t>(v)] - alpha * around;
        q_[static_cast<std::size_t>(v)] = s;
        dot += y[static_cast<std::size_t>(v)] * s;
      }
      return dot;
    };
    // x starts at the advected velocity, a close guess for small α; the fixed neighbours (walls,
    // the inflow, ghosts) move to the right-hand side.
    const double b_norm2 = sum_over_chunks(m, kChunk, threads, partials_, [&](int begin, int end) {
      double s = 0.0;
      for (int v = begin; v < end; ++v) {
        const auto vi = static_cast<std::size_t>(v);
        x_[vi] = u[static_cast<std::size_t>(c.faces[vi])];
        double constant = 0.0;
        for (int t = c.boundary_start[vi]; t < c.boundary_start[vi + 1]; ++t) {
          const auto& [g, factor] = c.boundary[static_cast<std::size_t>(t)];
          constant += factor * u[static_cast<std::size_t>(g)];
        }
        b_[vi] = x_[vi] + alpha * constant;
        s += b_[vi] * b_[vi];
      }
      return s;
    });
    for_each_chunk(m, kChunk, threads, [&](int begin, int end) { apply(x_, begin, end); });
    double rz = sum_over_chunks(m, kChunk, threads, partials_, [&](int begin, int end) {
      double s = 0.0;
      for (int v = begin; v < end; ++v) {
        const auto vi = static_cast<std::size_t>(v);
        r_[vi] = b_[vi] - q_[vi];
        z_[vi] = r_[vi] / diagonal(v);
        p_[vi] = z_[vi];
        s += r_[vi] * z_[vi];
      }
      return s;
    });
    const double target = settings.relative_tolerance * std::sqrt(b_norm2);
    for (int it = 0; it < settings.max_iterations; ++it) {
      const double r_norm =
          std::sqrt(sum_over_chunks(m, kChunk, threads, partials_, [&](int begin, int end) {
            double s = 0.0;
            for (int v = begin; v < end; ++v)
              s += r_[static_cast<std::size_t>(v)] * r_[static_cast<std::size_t>(v)];
            return s;
          }));
      if (r_norm <= target) break;
      const double pq = sum_over_chunks(m, kChunk, threads, partials_,
                                        [&](int begin, int end) { return apply(p_, begin, end); });
      if (!(pq > 0.0)) break;
      const double step = rz / pq;
      const double rz_next =
          sum_over_chunks(m, kChunk, threads, partials_, [&](int begin, int end) {
            double s = 0.0;
            for (int v = begin; v < end; ++v) {
              const auto vi = static_cast<std::size_t>(v);
              x_[vi] += step * p_[vi];
              r_[vi] -= step * q_[vi];
              z_[vi] = r_[vi] / diagonal(v);
              s += r_[vi] * z_[vi];
            }
            return s;
          });
      const double beta = rz_next / rz;
      rz = rz_next;
      for_each_chunk(m, kChunk, threads, [&](int begin, int end) {
        for (int v = begin; v < end; ++v)
          p_[static_cast<std::size_t>(v)] =
              z_[static_cast<std::size_t>(v)] + beta * p_[static_cast<std::size_t>(v)];
      });
      ++iterations;
    }
    for_each_chunk(m, kChunk, threads, [&](int begin, int end) {
      for (int v = begin; v < end; ++v)
        u[static_cast<std::size_t>(c.faces[static_cast<std::size_t>(v)])] =
            x_[static_cast<std::size_t>(v)];
    });
  }
  return iterations;
}

void ViscousDiffusion::step_explicitly(const Component& c, std::vector<double>& u, double alpha,
                                       int threads) {
  const int m = static_cast<int>(c.faces.size());
  // The unknowns' old values with the zero slot m for missing neighbours, then the sweep.
  x_.resize(static_cast<std::size_t>(m) + 1);
  x_[static_cast<std::size_t>(m)] = 0.0;
  for_each_chunk(m, kChunk, threads, [&](int begin, int end) {
    for (int v = begin; v < end; ++v)
      x_[static_cast<std::size_t>(v)] =
          u[static_cast<std::size_t>(c.faces[static_cast<std::size_t>(v)])];
  });
  for_each_chunk(m, kChunk, threads, [&](int begin, int end) {
    for (int v = begin; v < end; ++v) {
      const auto vi = static_cast<std::size_t>(v);
      const auto& n = c.next[vi];
      double around = x_[static_cast<std::size_t>(n[0])] + x_[static_cast<std::size_t>(n[1])] +
                      x_[static_cast<std::size_t>(n[2])] + x_[static_cast<std::size_t>(n[3])] +
                      x_[static_cast<std::size_t>(n[4])] + x_[static_cast<std::size_t>(n[5])];
      for (int t = c.boundary_start[vi]; t < c.boundary_start[vi + 1]; ++t) {
        const auto& [g, factor] = c.boundary[static_cast<std::size_t>(t)];
        around += factor * u[static_cast<std::size_t>(g)];
      }
      u[static_cast<std::size_t>(c.faces[vi])] = x_[vi] + alpha * (around - c.weight[vi] * x_[vi]);
    }
  });
}

int diffuse(FlowGrid& grid, const DiffusionSettings& settings) {
  ViscousDiffusion diffusion;
  return diffusion.diffuse(grid, settings);
}

}  // namespace viscera::sim::fluid
