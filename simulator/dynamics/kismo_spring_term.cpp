#include "simulator/dynamics/kismo_spring_term.h"

#include <algorithm>
#include <cmath>

#include "simulator/dynamics/spring_hessian.h"
#include "simulator/dynamics/tet_edge_groups.h"

namespace viscera::sim {

KismoSpringTerm::KismoSpringTerm(std::shared_ptr<const BodyModel> model,
                                 const SimulationState& state)
    : BodyTerm(std::move(model)) {
  initialise(state);
}

void KismoSpringTerm::build(const SimulationState& state, int first) {
  const BodyModel& m = model();
  const std::span<const Vec3> rest = state.range(state.rest_positions, m.body);
  // Per edge: the share-weighted coefficients of the tets around it, summed in tet order over
  // edges in sorted order.
  struct TetShare {
    double share = 0.0, damping = 0.0;
    std::array<double, 3> c{};  ///< (c1, c2, c3) in Pa
  };
  std::vector<TetShare> per_tet(m.mesh.tets.size());
  for (std::size_t t = 0; t < m.mesh.tets.size(); ++t) {
    const auto& tet = m.mesh.tets[t];
    const core::Material& material = m.material_of(static_cast<int>(t));
    const bool cubic = material.stress_strain && material.stress_strain->cubic.size() == 4;
    per_tet[t].share =
        core::signed_volume(rest[tet[0]], rest[tet[1]], rest[tet[2]], rest[tet[3]]) / 6.0;
    per_tet[t].damping = material.distance_damping;
    per_tet[t].c = cubic ? std::array<double, 3>{material.stress_strain->cubic[1],
                                                 material.stress_strain->cubic[2],
                                                 material.stress_strain->cubic[3]}
                         : std::array<double, 3>{material.distance_stiffness, 0.0, 0.0};
  }
  const TetEdgeGroups groups = tet_edge_groups(m.mesh.tets, static_cast<int>(rest.size()));
  springs_ = {};
  for (std::size_t e = 0; e < groups.edges.size(); ++e) {
    const auto edge = groups.edges[e];
    double damping = 0.0;
    std::array<double, 3> stress{};  // Σ share × (c1, c2, c3) in Pa·m³
    for (int k = groups.first[e]; k < groups.first[e + 1]; ++k) {
      const TetShare& s = per_tet[groups.tets[k]];
      damping += s.damping * s.share;
      for (int n = 0; n < 3; ++n)
        stress[n] += s.c[n] * s.share;
    }
    const double l0 = (rest[edge[1]] - rest[edge[0]]).norm();
    // k_n = c_n × cross-section, cross-section = share / l0 (seed 001 §3.2).
    springs_.knots.push_back({first + edge[0], first + edge[1]});
    springs_.rest_length.push_back(l0);
    springs_.coefficients.push_back({stress[0] / l0, stress[1] / l0, stress[2] / l0});
    springs_.damping.push_back(damping / (l0 * l0));
  }
}

void KismoSpringTerm::shift(int delta) {
  for (auto& k : springs_.knots)
    k = {k[0] + delta, k[1] + delta};
}

double KismoSpringTerm::energy(std::span<const Vec3> x) const {
  return cubic_spring_energy(x, springs_);
}

double KismoSpringTerm::add_forces(std::span<const Vec3> x, std::span<const Vec3> v,
                                   std::span<Vec3> f) const {
  return add_damped_cubic_spring_forces(x, v, springs_, f);
}

void KismoSpringTerm::declare_blocks(BlockPattern& pattern) const {
  for (const auto& [i, j] : springs_.knots)
    pattern.add(i, j);
}

void KismoSpringTerm::add_stiffness(std::span<const Vec3> x, double scale, bool project,
                                    BlockSparseMatrix& m) const {
  for (std::size_t s = 0; s < springs_.knots.size(); ++s) {
    const auto [i, j] = springs_.knots[s];
    const Vec3 d = x[j] - x[i];
    const double length = d.norm();
    if (length <= 0.0) continue;
    const double l0 = springs_.rest_length[s];
    const double e = (length - l0) / l0;
    const auto& k = springs_.coefficients[s];
    const double force = k[0] * e + k[1] * e * std::abs(e) + k[2] * e * e * e;
    const double slope = (k[0] + 2.0 * k[1] * std::abs(e) + 3.0 * k[2] * e * e) / l0;
    add_pair_block(m, i, j, radial_hessian(d / length, length, force, slope, project), scale);
  }
}

void KismoSpringTerm::add_damping(std::span<const Vec3> x, double scale,
                                  BlockSparseMatrix& m) const {
  for (std::size_t s = 0; s < springs_.damping.size(); ++s) {
    const auto [i, j] = springs_.knots[s];
    const Vec3 d = x[j] - x[i];
    const double length = d.norm();
    if (length <= 0.0) continue;
    const Vec3 unit = d / length;
    add_pair_block(m, i, j, springs_.damping[s] * (unit * unit.transpose()), scale);
  }
}

}  // namespace viscera::sim
