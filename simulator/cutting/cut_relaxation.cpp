#include "simulator/cutting/cut_relaxation.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/mesh/surface_embedding.h"
#include "core/mesh/tet_mesh.h"
#include "simulator/cutting/cut_classification.h"

namespace viscera::sim::cutting {
namespace {

using core::Vec3;

// Largest cosine of the six dihedral angles (1 for a flat tet), or 2 for an inverted one.
double worst_cos(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  if (core::signed_volume(a, b, c, d) <= 0.0) return 2.0;
  return max_cos_dihedral(a, b, c, d);
}

// Largest worst_cos over the star of `node`, with per-tet values cached (NaN = not known).
double star_worst(const RelaxationMesh& m, int node, const std::vector<Vec3>& x,
                  std::vector<double>& cache) {
  double worst = -1.0;
  for (int k = (*m.star_offset)[node]; k < (*m.star_offset)[node + 1]; ++k) {
    const int id = (*m.star_tets)[k];
    if (std::isnan(cache[id])) {
      const auto& t = (*m.tets)[id];
      cache[id] = worst_cos(x[t[0]], x[t[1]], x[t[2]], x[t[3]]);
    }
    worst = std::max(worst, cache[id]);
  }
  return worst;
}

// True when no tet of the star is worse than `limit` (stops at the first that is).
bool star_within(const RelaxationMesh& m, int node, const std::vector<Vec3>& x, double limit) {
  for (int k = (*m.star_offset)[node]; k < (*m.star_offset)[node + 1]; ++k) {
    const auto& t = (*m.tets)[(*m.star_tets)[k]];
    if (worst_cos(x[t[0]], x[t[1]], x[t[2]], x[t[3]]) > limit) return false;
  }
  return true;
}

std::vector<NodeSource> sources_of(const RelaxationMesh& m, int node) {
  const auto& o = (*m.origin)[node];
  if (o.empty()) return {NodeSource{node, 1.0}};
  return o;
}

// Tries to move `node` by d; keeps the move when both configurations stay at least as good.
bool try_move(const RelaxationMesh& m, int node, const Vec3& d, double before_x,
              double before_rest) {
  std::vector<Vec3>& x = *m.current;
  std::vector<Vec3>& rest = *m.rest;
  const Vec3 old_x = x[node], old_rest = rest[node];
  const Vec3 target = old_x + d;
  // The star tet holding the target (deformed config) carries the move to the rest config.
  int host = -1;
  std::array<double, 4> weights{};
  double best = -1e300;
  for (int k = (*m.star_offset)[node]; k < (*m.star_offset)[node + 1]; ++k) {
    const auto& t = (*m.tets)[(*m.star_tets)[k]];
    const auto w = core::barycentric(target, x[t[0]], x[t[1]], x[t[2]], x[t[3]]);
    const double low = std::min({w[0], w[1], w[2], w[3]});
    if (low > best) best = low, host = (*m.star_tets)[k], weights = w;
  }
  if (host < 0 || best < -1e-12) return false;
  const auto& t = (*m.tets)[host];
  Vec3 new_rest = Vec3::Zero();
  for (int i = 0; i < 4; ++i)
    new_rest += weights[i] * rest[t[i]];
  x[node] = target;
  rest[node] = new_rest;
  if (!star_within(m, node, x, before_x) || !star_within(m, node, rest, before_rest)) {
    x[node] = old_x;
    rest[node] = old_rest;
    return false;
  }
  // Compose the sources: the new place is a barycentric mix of the host's corners.
  std::vector<NodeSource> mixed;
  for (int i = 0; i < 4; ++i) {
    if (weights[i] <= 0.0) continue;
    for (const NodeSource& s : sources_of(m, t[i])) {
      mixed.push_back({s.old_node, s.weight * weights[i]});
    }
  }
  std::sort(mixed.begin(), mixed.end(),
            [](const NodeSource& a, const NodeSource& b) { return a.old_node < b.old_node; });
  std::vector<NodeSource> merged;
  double total = 0.0;
  for (const NodeSource& s : mixed) {
    if (!merged.empty() && merged.back().old_node == s.old_node) {
      merged.back().weight += s.weight;
    } else {
      merged.push_back(s);
    }
  }
  std::erase_if(merged, [](const NodeSource& s) { return s.weight < 1e-15; });
  for (const NodeSource& s : merged)
    total += s.weight;
  for (NodeSource& s : merged)
    s.weight /= total;
  (*m.origin)[node] = std::move(merged);
  return true;
}

}  // namespace

int relax_cut_neighbourhood(const RelaxationMesh& m, const std::vector<RelaxedNode>& nodes,
                            const RelaxationOptions& options) {
  std::vector<Vec3>& x = *m.current;
  const std::size_t count = nodes.size();
  std::vector<Vec3> velocity(count, Vec3::Zero());
  std::vector<double> r0(count, 0.0);
  std::vector<std::vector<int>> neighbours(count);
  for (std::size_t i = 0; i < count; ++i) {
    const int node = nodes[i].node;
    auto& nb = neighbours[i];
    for (int k = (*m.star_offset)[node]; k < (*m.star_offset)[node + 1]; ++k) {
      for (int v : (*m.tets)[(*m.star_tets)[k]]) {
        if (v != node) nb.push_back(v);
      }
    }
    std::sort(nb.begin(), nb.end());
    nb.erase(std::unique(nb.begin(), nb.end()), nb.end());
    double sum = 0.0;
    for (int v : nb)
      sum += (x[v] - x[node]).norm();
    r0[i] = nb.empty() ? 0.0 : sum / nb.size();
  }
  std::vector<std::uint8_t> moved(count, 0);
  constexpr double kUnknown = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> cache_x(m.tets->size(), kUnknown), cache_rest(m.tets->size(), kUnknown);
  for (int iteration = 0; iteration < options.iterations; ++iteration) {
    for (std::size_t i = 0; i < count; ++i) {
      const int node = nodes[i].node;
      if (neighbours[i].empty() || !(r0[i] > 0.0)) continue;
      Vec3 force = Vec3::Zero();  // in units of ε / r0
      for (int v : neighbours[i]) {
        const Vec3 delta = x[node] - x[v];
        const double r = delta.norm();
        if (!(r > 0.0)) continue;
        const double rho = r0[i] / r;  // (r0 / r)
        const double rho6 = std::pow(rho, 6);
        const double magnitude = std::clamp(12.0 * rho * (rho6 * rho6 - rho6), -4.0, 4.0);
        force += magnitude * delta / r;
      }
      const double eta = 0.5 / (72.0 * static_cast<double>(neighbours[i].size()));
      Vec3 step = options.damping * velocity[i] + eta * r0[i] * force;
      const Vec3& n = nodes[i].slide_normal;
      if (n.squaredNorm() > 0.0) step -= step.dot(n) * n;
      const double limit = options.max_step_fraction * r0[i];
      if (step.norm() > limit) step *= limit / step.norm();
      if (step.norm() < 1e-6 * r0[i]) {
        velocity[i].setZero();
        continue;
      }
      const double before_x = star_worst(m, node, x, cache_x);
      const double before_rest = star_worst(m, node, *m.rest, cache_rest);
      if (try_move(m, node, step, before_x, before_rest) ||
          try_move(m, node, 0.5 * step, before_x, before_rest)) {
        velocity[i] = step;
        moved[i] = 1;
        for (int k = (*m.star_offset)[node]; k < (*m.star_offset)[node + 1]; ++k) {
          cache_x[(*m.star_tets)[k]] = cache_rest[(*m.star_tets)[k]] = kUnknown;
        }
      } else {
        velocity[i].setZero();
      }
    }
  }
  return static_cast<int>(std::count(moved.begin(), moved.end(), 1));
}

}  // namespace viscera::sim::cutting
