#include <algorithm>

#include "simulator/dynamics/spring_hessian.h"
#include "simulator/dynamics/teschner_terms.h"
#include "simulator/dynamics/tet_edge_groups.h"

namespace viscera::sim {

TeschnerDistanceTerm::TeschnerDistanceTerm(std::shared_ptr<const BodyModel> model,
                                           const SimulationState& state)
    : BodyTerm(std::move(model)) {
  initialise(state);
}

void TeschnerDistanceTerm::build(const SimulationState& state, int first) {
  const BodyModel& m = model();
  const std::span<const Vec3> rest = state.range(state.rest_positions, m.body);
  // Edges in sorted order, each summing the stiffness and damping of its tets in tet order
  // (each tet with its material), so the force sum runs the same way on every machine.
  std::vector<double> share(m.mesh.tets.size());
  for (std::size_t t = 0; t < m.mesh.tets.size(); ++t) {
    const auto& tet = m.mesh.tets[t];
    share[t] = core::signed_volume(rest[tet[0]], rest[tet[1]], rest[tet[2]], rest[tet[3]]) / 6.0;
  }
  const TetEdgeGroups groups = tet_edge_groups(m.mesh.tets, static_cast<int>(rest.size()));
  terms_ = {};
  slots_for_ = 0;
  terms_.edges.reserve(groups.edges.size());
  for (std::size_t e = 0; e < groups.edges.size(); ++e) {
    const auto [a, b] = groups.edges[e];
    double stiffness = 0.0, damping = 0.0;
    for (int k = groups.first[e]; k < groups.first[e + 1]; ++k) {
      const int t = groups.tets[k];
      const core::Material& material = m.material_of(t);
      stiffness += material.distance_stiffness * share[t];
      damping += material.distance_damping * share[t];
    }
    terms_.edges.push_back({first + a, first + b});
    terms_.rest_length.push_back((rest[b] - rest[a]).norm());
    terms_.stiffness.push_back(stiffness);
    terms_.damping.push_back(damping);
  }
}

void TeschnerDistanceTerm::shift(int delta) {
  for (auto& e : terms_.edges)
    e = {e[0] + delta, e[1] + delta};
  slots_for_ = 0;
}

double TeschnerDistanceTerm::energy(std::span<const Vec3> x) const {
  return distance_energy(x, terms_);
}

double TeschnerDistanceTerm::add_forces(std::span<const Vec3> x, std::span<const Vec3> v,
                                        std::span<Vec3> f) const {
  return add_distance_forces(x, v, terms_, f);
}

void TeschnerDistanceTerm::declare_blocks(BlockPattern& pattern) const {
  for (const auto& [i, j] : terms_.edges)
    pattern.add(i, j);
  pattern.cover_tet_edges(&model().mesh);  // every edge of the body's tets (build())
}

void TeschnerDistanceTerm::add_stiffness(std::span<const Vec3> x, double scale, bool project,
                                         BlockSparseMatrix& m) const {
  const auto& slot = slots(m);
  for (std::size_t e = 0; e < terms_.edges.size(); ++e) {
    const auto [i, j] = terms_.edges[e];
    const Vec3 d = x[j] - x[i];
    const double length = d.norm();
    if (length <= 0.0) continue;
    // E = ½ k C², C = (l − D0)/D0: dE/dl = k C / D0, d²E/dl² = k / D0².
    const double d0 = terms_.rest_length[e], k = terms_.stiffness[e];
    const double c = (length - d0) / d0;
    const Mat3 h = scale * radial_hessian(d / length, length, k * c / d0, k / (d0 * d0), project);
    m.block(slot[e][0]) += h;
    m.block(slot[e][1]) += h;
    m.block(slot[e][2]) -= h;
    m.block(slot[e][3]) -= h;
  }
}

void TeschnerDistanceTerm::add_damping(std::span<const Vec3> x, double scale,
                                       BlockSparseMatrix& m) const {
  const auto& slot = slots(m);
  for (std::size_t e = 0; e < terms_.edges.size(); ++e) {
    const auto [i, j] = terms_.edges[e];
    const Vec3 d = x[j] - x[i];
    const double length = d.norm();
    if (length <= 0.0 || terms_.damping[e] == 0.0) continue;
    // f_j = −k_d (∇C_j · (v_j − v_i)) ∇C_j with ∇C_j = d / (|d| D0): D = k_d/D0² d̂d̂ᵀ.
    const double d0 = terms_.rest_length[e];
    const Vec3 unit = d / length;
    const Mat3 h = (scale * terms_.damping[e] / (d0 * d0)) * (unit * unit.transpose());
    m.block(slot[e][0]) += h;
    m.block(slot[e][1]) += h;
    m.block(slot[e][2]) -= h;
    m.block(slot[e][3]) -= h;
  }
}

const std::vector<std::array<int, 4>>& TeschnerDistanceTerm::slots(
    const BlockSparseMatrix& m) const {
  if (slots_for_ != m.pattern_id() || slots_.size() != terms_.edges.size()) {
    slots_.clear();
    for (const auto& [i, j] : terms_.edges)
      slots_.push_back({m.diagonal_slot(i), m.diagonal_slot(j), m.slot(i, j), m.slot(j, i)});
    slots_for_ = m.pattern_id();
  }
  return slots_;
}

}  // namespace viscera::sim
