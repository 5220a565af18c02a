#include "simulator/physics/deformable_body.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "core/error.h"
#include "simulator/physics/verlet.h"

namespace viscera::sim {

DeformableBody::DeformableBody(std::string name, const core::TetMesh& mesh, const core::Material& material,
                               BodyModel model)
    : name_(std::move(name)), model_(model), rest_(mesh.nodes), positions_(mesh.nodes), previous_(mesh.nodes) {
  core::check_tet_mesh(mesh, "body " + name_);
  const std::size_t n = mesh.nodes.size();
  mass_ = mesh.node_mass.empty() ? core::lumped_node_masses(mesh, material.density) : mesh.node_mass;
  inverse_mass_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const bool fixed = !mesh.fixed.empty() && mesh.fixed[i] != 0;
    if (!fixed && !(mass_[i] > 0.0)) {
      throw core::InputError("free node has no positive mass", {"body " + name_, "", "node " + std::to_string(i)});
    }
    inverse_mass_[i] = fixed ? 0.0 : 1.0 / mass_[i];
  }
  velocities_.assign(n, core::Vec3::Zero());
  forces_.assign(n, core::Vec3::Zero());

  // Edges in sorted order (std::map) so the force sum runs the same way on every machine.
  std::map<std::array<int, 2>, double> volume_share;
  volume_.tets = mesh.tets;
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
    const double v0 = core::signed_volume(mesh, static_cast<int>(t));
    volume_.rest_volume.push_back(v0);
    volume_.stiffness.push_back(material.volume_stiffness * v0);
    const auto& tet = mesh.tets[t];
    for (int a = 0; a < 4; ++a) {
      for (int b = a + 1; b < 4; ++b) volume_share[{std::min(tet[a], tet[b]), std::max(tet[a], tet[b])}] += v0 / 6.0;
    }
  }
  for (const auto& [edge, share] : volume_share) {
    distance_.edges.push_back(edge);
    distance_.rest_length.push_back((mesh.nodes[edge[1]] - mesh.nodes[edge[0]]).norm());
    distance_.stiffness.push_back(material.distance_stiffness * share);
    distance_.damping.push_back(material.distance_damping * share);
  }
  if (model_ == BodyModel::KismoMassSpring) build_springs(material, volume_share);
  surface_faces_ = mesh.surface_faces.empty() ? core::boundary_faces(mesh.tets) : mesh.surface_faces;
  if (material.area_stiffness > 0.0) {
    for (const auto& f : surface_faces_) {
      const double a0 = 0.5 * (mesh.nodes[f[1]] - mesh.nodes[f[0]]).cross(mesh.nodes[f[2]] - mesh.nodes[f[0]]).norm();
      if (!(a0 > 0.0)) continue;
      area_.triangles.push_back(f);
      area_.rest_area.push_back(a0);
      area_.stiffness.push_back(material.area_stiffness * a0);
    }
  }
}

void DeformableBody::build_springs(const core::Material& material, const std::map<std::array<int, 2>, double>& volume_share) {
  const std::size_t n = positions_.size();
  knots_.mass = mass_;
  knots_.damping.assign(n, 0.0);
  knots_.bound.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint8_t moves = inverse_mass_[i] == 0.0 ? 0 : 1;
    knots_.bound[i] = {moves, moves, moves};
  }
  const bool has_cubic = material.stress_strain && material.stress_strain->cubic.size() == 4;
  for (const auto& [edge, share] : volume_share) {
    const double l0 = (rest_[edge[1]] - rest_[edge[0]]).norm();
    const double cross_section = share / l0;
    springs_.knots.push_back(edge);
    springs_.rest_length.push_back(l0);
    springs_.coefficients.push_back(
        has_cubic ? spring_coefficients_from_cubic({material.stress_strain->cubic[1], material.stress_strain->cubic[2],
                                                    material.stress_strain->cubic[3]},
                                                   cross_section)
                  : std::array<double, 3>{material.distance_stiffness * cross_section, 0.0, 0.0});
    // The damping element of each spring; the knots' own damping d_i (eq. 1) stays zero, as
    // damping absolute velocity would also brake slow, rigid motion such as sagging.
    springs_.damping.push_back(material.distance_damping * share / (l0 * l0));
  }
}

double DeformableBody::compute_forces(const core::Vec3& gravity, double h) {
  for (std::size_t i = 0; i < positions_.size(); ++i) forces_[i] = mass_[i] * gravity;
  if (model_ == BodyModel::KismoMassSpring) {
    add_spring_damping_forces(positions_, velocities_, springs_, forces_);
    return add_cubic_spring_forces(positions_, springs_, forces_);
  }
  verlet_velocities(positions_, previous_, h, velocities_);
  double energy = add_distance_forces(positions_, velocities_, distance_, forces_);
  energy += add_area_forces(positions_, area_, forces_);
  energy += add_volume_forces(positions_, volume_, forces_);
  return energy;
}

void DeformableBody::integrate(double h) {
  bool finite = true;
  if (model_ == BodyModel::KismoMassSpring) {
    previous_ = positions_;
    kismo_step(positions_, velocities_, forces_, knots_, core::Vec3::Zero(), h);  // gravity is in the forces
    for (const auto& p : positions_) finite = finite && p.allFinite();
  } else {
    finite = verlet_step(positions_, previous_, forces_, inverse_mass_, h);
  }
  if (!finite) {
    for (std::size_t i = 0; i < positions_.size(); ++i) {
      if (!positions_[i].allFinite()) {
        throw core::Error("simulation became unstable (non-finite position)", {"body " + name_, "", "node " + std::to_string(i)});
      }
    }
  }
}

BodyEnergies DeformableBody::energies(const core::Vec3& gravity, double h) const {
  BodyEnergies e;
  for (std::size_t i = 0; i < positions_.size(); ++i) {
    const core::Vec3 v = model_ == BodyModel::KismoMassSpring ? velocities_[i] : core::Vec3((positions_[i] - previous_[i]) / h);
    e.kinetic += 0.5 * mass_[i] * v.squaredNorm();
    e.gravitational -= mass_[i] * gravity.dot(positions_[i] - rest_[i]);
  }
  if (model_ == BodyModel::KismoMassSpring) {
    std::vector<core::Vec3> scratch(positions_.size(), core::Vec3::Zero());
    e.elastic = add_cubic_spring_forces(positions_, springs_, scratch);
    return e;
  }
  e.elastic = distance_energy(positions_, distance_) + area_energy(positions_, area_) + volume_energy(positions_, volume_);
  return e;
}

double DeformableBody::stable_time_step(double contact_stiffness,
                                        std::span<const double> node_stiffness) const {
  // Gershgorin bound of M⁻¹K per node: a term of stiffness k with constraint gradient g
  // contributes k |g_i| Σ_j |g_j| to row i. Damping bounds the step by m / c.
  const std::size_t n = positions_.size();
  std::vector<double> stiffness(n, 0.0), damping(n, 0.0);
  for (std::size_t e = 0; e < distance_.edges.size(); ++e) {
    const double d0 = distance_.rest_length[e];
    const double k = 2.0 * distance_.stiffness[e] / (d0 * d0);
    const double c = 2.0 * distance_.damping[e] / (d0 * d0);
    for (const int i : distance_.edges[e]) {
      stiffness[i] += k;
      damping[i] += c;
    }
  }
  for (std::size_t t = 0; t < volume_.tets.size(); ++t) {
    const auto [i, j, k, l] = volume_.tets[t];
    const core::Vec3 e1 = rest_[j] - rest_[i], e2 = rest_[k] - rest_[i], e3 = rest_[l] - rest_[i];
    const core::Vec3 g[4] = {-(e2.cross(e3) + e3.cross(e1) + e1.cross(e2)) / 6.0, e2.cross(e3) / 6.0,
                             e3.cross(e1) / 6.0, e1.cross(e2) / 6.0};
    double norm_sum = 0.0;
    for (const auto& gi : g) norm_sum += gi.norm();
    const double v0 = volume_.rest_volume[t];
    const int nodes[4] = {i, j, k, l};
    for (int a = 0; a < 4; ++a) stiffness[nodes[a]] += volume_.stiffness[t] / (v0 * v0) * g[a].norm() * norm_sum;
  }
  for (std::size_t t = 0; t < area_.triangles.size(); ++t) {
    const double a0 = area_.rest_area[t];
    const auto& tri = area_.triangles[t];
    // |∂A/∂p| ≤ half the longest edge; a coarse but safe bound.
    double longest = 0.0;
    for (int e = 0; e < 3; ++e) longest = std::max(longest, (rest_[tri[e]] - rest_[tri[(e + 1) % 3]]).norm());
    const double g = 0.5 * longest;
    for (const int i : tri) stiffness[i] += area_.stiffness[t] / (a0 * a0) * g * 3.0 * g;
  }
  if (model_ == BodyModel::KismoMassSpring) {
    // Springs replace the energies: a linearised stiffness k1/l0 per spring, and knot damping.
    std::fill(stiffness.begin(), stiffness.end(), 0.0);
    std::fill(damping.begin(), damping.end(), 0.0);
    for (std::size_t s = 0; s < springs_.knots.size(); ++s) {
      const auto& k = springs_.coefficients[s];
      const double linear = 2.0 * (std::abs(k[0]) + std::abs(k[1]) + std::abs(k[2])) / springs_.rest_length[s];
      for (const int i : springs_.knots[s]) stiffness[i] += linear;
    }
    for (std::size_t s = 0; s < springs_.knots.size(); ++s) {
      for (const int i : springs_.knots[s]) damping[i] += 2.0 * springs_.damping[s];
    }
  }
  if (contact_stiffness > 0.0) {
    std::vector<char> on_surface(n, 0);
    for (const auto& f : surface_faces_)
      for (const int v : f) on_surface[v] = 1;
    for (std::size_t i = 0; i < n; ++i) stiffness[i] += on_surface[i] ? contact_stiffness : 0.0;
  }
  if (!node_stiffness.empty()) {
    if (node_stiffness.size() != n)
      throw core::UsageError("stable_time_step needs one extra stiffness per node of " + name_);
    for (std::size_t i = 0; i < n; ++i) stiffness[i] += node_stiffness[i];
  }
  // Per node, the undamped limit 2/ω and the explicit-damping limit 2m/c combine harmonically:
  // each alone is the exact bound when the other vanishes, and together this stays below both.
  double h = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < n; ++i) {
    if (inverse_mass_[i] == 0.0) continue;
    const double rate = 0.5 * std::sqrt(stiffness[i] * inverse_mass_[i]) + 0.5 * damping[i] * inverse_mass_[i];
    if (rate > 0.0) h = std::min(h, 1.0 / rate);
  }
  return 0.9 * h;
}

bool DeformableBody::add_linearised_terms(RankOneSystem& stiffness, RankOneSystem& damping,
                                          int offset) const {
  if (model_ == BodyModel::KismoMassSpring) return false;
  // Distance: C = (|d| − D0)/D0, ∇C = ±û/D0 at the two ends.
  for (std::size_t e = 0; e < distance_.edges.size(); ++e) {
    const auto [i, j] = distance_.edges[e];
    const double d0 = distance_.rest_length[e];
    const core::Vec3 g = (rest_[j] - rest_[i]) / (d0 * d0);
    const int nodes[2] = {offset + i, offset + j};
    const core::Vec3 gradient[2] = {-g, g};
    stiffness.add_term(nodes, gradient, distance_.stiffness[e]);
    damping.add_term(nodes, gradient, distance_.damping[e]);
  }
  // Volume: C = (V − V0)/V0, ∇C = ∂V/∂p / V0.
  for (std::size_t t = 0; t < volume_.tets.size(); ++t) {
    const auto [i, j, k, l] = volume_.tets[t];
    const core::Vec3 e1 = rest_[j] - rest_[i], e2 = rest_[k] - rest_[i], e3 = rest_[l] - rest_[i];
    const double v0 = volume_.rest_volume[t];
    const core::Vec3 gj = e2.cross(e3) / (6.0 * v0), gk = e3.cross(e1) / (6.0 * v0),
                     gl = e1.cross(e2) / (6.0 * v0);
    const int nodes[4] = {offset + i, offset + j, offset + k, offset + l};
    const core::Vec3 gradient[4] = {-(gj + gk + gl), gj, gk, gl};
    stiffness.add_term(nodes, gradient, volume_.stiffness[t]);
  }
  // Area: C = (A − A0)/A0, ∂A/∂a = ½ n̂ × (c − b), cyclically.
  for (std::size_t t = 0; t < area_.triangles.size(); ++t) {
    const auto [a, b, c] = area_.triangles[t];
    const double a0 = area_.rest_area[t];
    const core::Vec3 unit = (rest_[b] - rest_[a]).cross(rest_[c] - rest_[a]).normalized();
    const int nodes[3] = {offset + a, offset + b, offset + c};
    const core::Vec3 gradient[3] = {0.5 * unit.cross(rest_[c] - rest_[b]) / a0,
                                    0.5 * unit.cross(rest_[a] - rest_[c]) / a0,
                                    0.5 * unit.cross(rest_[b] - rest_[a]) / a0};
    stiffness.add_term(nodes, gradient, area_.stiffness[t]);
  }
  return true;
}

double DeformableBody::max_displacement() const {
  double largest = 0.0;
  for (std::size_t i = 0; i < positions_.size(); ++i) largest = std::max(largest, (positions_[i] - rest_[i]).norm());
  return largest;
}

core::Vec3 DeformableBody::centre_of_mass() const {
  core::Vec3 sum = core::Vec3::Zero();
  double total = 0.0;
  for (std::size_t i = 0; i < positions_.size(); ++i) {
    sum += mass_[i] * positions_[i];
    total += mass_[i];
  }
  return total > 0.0 ? core::Vec3(sum / total) : sum;
}

core::Vec3 DeformableBody::rest_centre_of_mass() const {
  core::Vec3 sum = core::Vec3::Zero();
  double total = 0.0;
  for (std::size_t i = 0; i < rest_.size(); ++i) {
    sum += mass_[i] * rest_[i];
    total += mass_[i];
  }
  return total > 0.0 ? core::Vec3(sum / total) : sum;
}

}  // namespace viscera::sim
