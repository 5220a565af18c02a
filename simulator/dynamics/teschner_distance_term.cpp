#include <algorithm>
#include <map>

#include "simulator/dynamics/spring_hessian.h"
#include "simulator/dynamics/teschner_terms.h"

namespace viscera::sim {

TeschnerDistanceTerm::TeschnerDistanceTerm(std::shared_ptr<const BodyModel> model,
                                           const SimulationState& state)
    : BodyTerm(std::move(model)) {
  initialise(state);
}

void TeschnerDistanceTerm::build(const SimulationState& state, int first) {
  const BodyModel& m = model();
  const std::span<const Vec3> rest = state.range(state.rest_positions, m.body);
  // Edges in sorted order (std::map) so the force sum runs the same way on every machine; each
  // edge collects the stiffness and damping of the tets around it, each tet with its material.
  std::map<std::array<int, 2>, std::array<double, 2>> edge;
  for (std::size_t t = 0; t < m.mesh.tets.size(); ++t) {
    const auto& tet = m.mesh.tets[t];
    const double share =
        core::signed_volume(rest[tet[0]], rest[tet[1]], rest[tet[2]], rest[tet[3]]) / 6.0;
    const core::Material& material = m.material_of(static_cast<int>(t));
    for (int a = 0; a < 4; ++a) {
      for (int b = a + 1; b < 4; ++b) {
        auto& k = edge[{std::min(tet[a], tet[b]), std::max(tet[a], tet[b])}];
        k[0] += material.distance_stiffness * share;
        k[1] += material.distance_damping * share;
      }
    }
  }
  terms_ = {};
  slots_for_ = 0;
  for (const auto& [e, k] : edge) {
    terms_.edges.push_back({first + e[0], first + e[1]});
    terms_.rest_length.push_back((rest[e[1]] - rest[e[0]]).norm());
    terms_.stiffness.push_back(k[0]);
    terms_.damping.push_back(k[1]);
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
