#include <algorithm>
#include <map>

#include "simulator/dynamics/teschner_terms.h"

namespace viscera::sim {
namespace {

Mat3 skew(const Vec3& a) {
  Mat3 s;
  s << 0.0, -a.z(), a.y(), a.z(), 0.0, -a.x(), -a.y(), a.x(), 0.0;
  return s;
}

}  // namespace

TeschnerAreaTerm::TeschnerAreaTerm(std::shared_ptr<const BodyModel> model,
                                   const SimulationState& state)
    : BodyTerm(std::move(model)) {
  initialise(state);
}

void TeschnerAreaTerm::build(const SimulationState& state, int first) {
  const BodyModel& m = model();
  const std::span<const Vec3> rest = state.range(state.rest_positions, m.body);
  terms_ = {};
  bool any = false;
  for (const auto& material : m.materials)
    any = any || material.area_stiffness > 0.0;
  if (!any) return;
  // The material of a surface triangle is that of the tet it bounds.
  std::map<std::array<int, 3>, int> owner;
  const auto key = [](int a, int b, int c) {
    std::array<int, 3> k{a, b, c};
    std::sort(k.begin(), k.end());
    return k;
  };
  for (std::size_t t = 0; t < m.mesh.tets.size(); ++t) {
    const auto& n = m.mesh.tets[t];
    for (int skip = 0; skip < 4; ++skip) {
      int f[3], c = 0;
      for (int a = 0; a < 4; ++a)
        if (a != skip) f[c++] = n[a];
      owner.emplace(key(f[0], f[1], f[2]), static_cast<int>(t));
    }
  }
  for (const auto& f : m.surface) {
    const double a0 = 0.5 * (rest[f[1]] - rest[f[0]]).cross(rest[f[2]] - rest[f[0]]).norm();
    if (!(a0 > 0.0)) continue;
    const auto it = owner.find(key(f[0], f[1], f[2]));
    const core::Material& material = it != owner.end() ? m.material_of(it->second) : m.materials[0];
    if (!(material.area_stiffness > 0.0)) continue;
    terms_.triangles.push_back({first + f[0], first + f[1], first + f[2]});
    terms_.rest_area.push_back(a0);
    terms_.stiffness.push_back(material.area_stiffness * a0);
  }
}

void TeschnerAreaTerm::shift(int delta) {
  for (auto& t : terms_.triangles)
    for (int& n : t)
      n += delta;
}

double TeschnerAreaTerm::energy(std::span<const Vec3> x) const {
  return area_energy(x, terms_);
}

double TeschnerAreaTerm::add_forces(std::span<const Vec3> x, std::span<const Vec3>,
                                    std::span<Vec3> f) const {
  return add_area_forces(x, terms_, f);
}

void TeschnerAreaTerm::declare_blocks(BlockPattern& pattern) const {
  for (const auto& t : terms_.triangles)
    pattern.add_clique(t);
}

void TeschnerAreaTerm::add_stiffness(std::span<const Vec3> x, double scale, bool project,
                                     BlockSparseMatrix& m) const {
  for (std::size_t t = 0; t < terms_.triangles.size(); ++t) {
    const auto& p = terms_.triangles[t];
    const Vec3 a = x[p[0]], b = x[p[1]], c = x[p[2]];
    const Vec3 n = (b - a).cross(c - a);
    const double twice = n.norm();
    if (twice <= 0.0) continue;
    const Vec3 unit = n / twice;
    // n = a×b + b×c + c×a: ∂n/∂a = [c − b]×, ∂n/∂b = [a − c]×, ∂n/∂c = [b − a]×.
    const Mat3 jac[3] = {skew(c - b), skew(a - c), skew(b - a)};
    // ∇A = ½ Jᵀ n̂; C = (A − A0)/A0.
    Vec3 grad[3];
    for (int k = 0; k < 3; ++k)
      grad[k] = 0.5 * jac[k].transpose() * unit;
    const double a0 = terms_.rest_area[t], k = terms_.stiffness[t];
    const double constraint = (0.5 * twice - a0) / a0;
    for (int i = 0; i < 3; ++i)
      for (int j = i; j < 3; ++j)
        m.add_symmetric(p[i], p[j], (scale * k / (a0 * a0)) * (grad[i] * grad[j].transpose()));
    if (project) continue;
    // ∇²A = ½ (Jᵀ (I − n̂n̂ᵀ) J / |n| + N), N_ab = −[n̂]× for (a,b) cyclic (ab, bc, ca).
    const Mat3 across = (Mat3::Identity() - unit * unit.transpose()) / twice;
    const double curvature = scale * k * constraint / a0;
    for (int i = 0; i < 3; ++i) {
      for (int j = i; j < 3; ++j) {
        Mat3 h = 0.5 * jac[i].transpose() * across * jac[j];
        if (j == i + 1) h += -0.5 * skew(unit);       // (a,b), (b,c)
        if (i == 0 && j == 2) h += 0.5 * skew(unit);  // (a,c) = (c,a)ᵀ
        m.add_symmetric(p[i], p[j], curvature * h);
      }
    }
  }
}

}  // namespace viscera::sim
