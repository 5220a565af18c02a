#include "simulator/dynamics/teschner_terms.h"

namespace viscera::sim {
namespace {

Mat3 skew(const Vec3& a) {
  Mat3 s;
  s << 0.0, -a.z(), a.y(), a.z(), 0.0, -a.x(), -a.y(), a.x(), 0.0;
  return s;
}

}  // namespace

TeschnerVolumeTerm::TeschnerVolumeTerm(std::shared_ptr<const BodyModel> model,
                                       const SimulationState& state)
    : BodyTerm(std::move(model)) {
  initialise(state);
}

void TeschnerVolumeTerm::build(const SimulationState& state, int first) {
  const BodyModel& m = model();
  const std::span<const Vec3> rest = state.range(state.rest_positions, m.body);
  terms_ = {};
  slots_for_ = 0;
  for (std::size_t t = 0; t < m.mesh.tets.size(); ++t) {
    const auto& tet = m.mesh.tets[t];
    const double v0 = core::signed_volume(rest[tet[0]], rest[tet[1]], rest[tet[2]], rest[tet[3]]);
    terms_.tets.push_back({first + tet[0], first + tet[1], first + tet[2], first + tet[3]});
    terms_.rest_volume.push_back(v0);
    terms_.stiffness.push_back(m.material_of(static_cast<int>(t)).volume_stiffness * v0);
  }
}

void TeschnerVolumeTerm::shift(int delta) {
  for (auto& t : terms_.tets)
    for (int& n : t)
      n += delta;
  slots_for_ = 0;
}

double TeschnerVolumeTerm::energy(std::span<const Vec3> x) const {
  return volume_energy(x, terms_);
}

double TeschnerVolumeTerm::add_forces(std::span<const Vec3> x, std::span<const Vec3>,
                                      std::span<Vec3> f) const {
  return add_volume_forces(x, terms_, f);
}

void TeschnerVolumeTerm::declare_blocks(BlockPattern& pattern) const {
  if (pattern.covers_tet_edges(&model().mesh)) return;  // the distance term declared them
  for (const auto& t : terms_.tets)
    pattern.add_clique(t);
}

void TeschnerVolumeTerm::add_stiffness(std::span<const Vec3> x, double scale, bool project,
                                       BlockSparseMatrix& m) const {
  const auto& slot = slots(m);
  const auto add = [&](std::size_t t, int a, int b, const Mat3& value) {
    m.block(slot[t][static_cast<std::size_t>(4 * a + b)]) += value;
    if (a != b) m.block(slot[t][static_cast<std::size_t>(4 * b + a)]) += value.transpose();
  };
  for (std::size_t t = 0; t < terms_.tets.size(); ++t) {
    const auto& n = terms_.tets[t];
    const Vec3 e1 = x[n[1]] - x[n[0]], e2 = x[n[2]] - x[n[0]], e3 = x[n[3]] - x[n[0]];
    // g_a = ∂(6V)/∂p_a; C = 6V/(6V0) − 1, ∇C = g / (6V0).
    Vec3 g[4];
    g[1] = e2.cross(e3);
    g[2] = e3.cross(e1);
    g[3] = e1.cross(e2);
    g[0] = -(g[1] + g[2] + g[3]);
    const double inverse6 = 1.0 / (6.0 * terms_.rest_volume[t]);
    const double k = terms_.stiffness[t];
    const double c = e1.dot(g[1]) * inverse6 - 1.0;
    // With the collapse barrier E = k (½ C² + b(J)), J = C + 1: Gauss–Newton part
    // k (1 + b″) ∇C ∇Cᵀ (b″ ≥ 0), curvature part k (C + b′) ∇²C.
    const CollapseBarrier barrier = collapse_barrier(c + 1.0);
    const double normal = scale * k * (1.0 + barrier.second) * inverse6 * inverse6;
    for (int a = 0; a < 4; ++a)
      for (int b = a; b < 4; ++b)
        add(t, a, b, normal * (g[a] * g[b].transpose()));
    if (project) continue;
    // Curvature part k C ∇²C: ∂g_a/∂p_b among nodes 1..3 are skew matrices of the edges
    // (∂(a×b)/∂a = −[b]×), rows and columns of node 0 by translation invariance.
    Mat3 h[4][4];
    h[1][1] = h[2][2] = h[3][3] = Mat3::Zero();
    h[1][2] = -skew(e3);
    h[1][3] = skew(e2);
    h[2][3] = -skew(e1);
    h[2][1] = h[1][2].transpose();
    h[3][1] = h[1][3].transpose();
    h[3][2] = h[2][3].transpose();
    for (int a = 1; a < 4; ++a)
      h[a][0] = -(h[a][1] + h[a][2] + h[a][3]);
    for (int b = 1; b < 4; ++b)
      h[0][b] = h[b][0].transpose();
    h[0][0] = -(h[0][1] + h[0][2] + h[0][3]);
    const double curvature = scale * k * (c + barrier.first) * inverse6;
    for (int a = 0; a < 4; ++a)
      for (int b = a; b < 4; ++b)
        add(t, a, b, curvature * h[a][b]);
  }
}

int TeschnerVolumeTerm::first_inverted(std::span<const Vec3> x, double fraction) const {
  for (std::size_t t = 0; t < terms_.tets.size(); ++t) {
    const auto& n = terms_.tets[t];
    if (core::signed_volume(x[n[0]], x[n[1]], x[n[2]], x[n[3]]) < -fraction * terms_.rest_volume[t])
      return static_cast<int>(t);
  }
  return -1;
}

const std::vector<std::array<int, 16>>& TeschnerVolumeTerm::slots(
    const BlockSparseMatrix& m) const {
  if (slots_for_ != m.pattern_id() || slots_.size() != terms_.tets.size()) {
    slots_.assign(terms_.tets.size(), {});
    for (std::size_t t = 0; t < terms_.tets.size(); ++t)
      for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b)
          slots_[t][static_cast<std::size_t>(4 * a + b)] =
              m.slot(terms_.tets[t][a], terms_.tets[t][b]);
    slots_for_ = m.pattern_id();
  }
  return slots_;
}

}  // namespace viscera::sim
