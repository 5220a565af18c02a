#include "exporters/sofa_material.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

#include "core/error.h"

namespace viscera::exporters {

SofaElasticity sofa_elasticity(const core::Material& material) {
  if (!(material.distance_stiffness > 0.0)) {
    throw core::InputError("distance stiffness must be positive to map the material to SOFA",
                           {"", "", "material " + material.id});
  }
  const double mu = material.distance_stiffness / 15.0;
  const double lambda =
      material.distance_stiffness / 15.0 + std::max(material.volume_stiffness, 0.0);
  SofaElasticity result;
  result.young_modulus = mu * (3.0 * lambda + 2.0 * mu) / (lambda + mu);
  result.poisson_ratio = std::min(lambda / (2.0 * (lambda + mu)), kMaxPoissonRatio);
  result.rayleigh_stiffness = rayleigh_stiffness(material, false);
  return result;
}

double kismo_linear_coefficient(const core::Material& material) {
  const bool cubic = material.stress_strain && material.stress_strain->cubic.size() == 4;
  const double c1 = cubic ? material.stress_strain->cubic[1] : material.distance_stiffness;
  if (!(c1 > 0.0)) {
    throw core::InputError("the linear spring coefficient must be positive to map it to SOFA",
                           {"", "", "material " + material.id});
  }
  return c1;
}

double rayleigh_stiffness(const core::Material& material, bool mass_spring) {
  const double stiffness =
      mass_spring ? kismo_linear_coefficient(material) : material.distance_stiffness;
  if (!(stiffness > 0.0)) {
    throw core::InputError("distance stiffness must be positive to map the material to SOFA",
                           {"", "", "material " + material.id});
  }
  return std::max(material.distance_damping, 0.0) / stiffness;
}

const core::Material& tet_material(const core::Scenario& scenario, const core::SceneObject& object,
                                   std::size_t t) {
  std::string id = object.material;
  if (t < object.body.tet_labels.size()) {
    const auto layer = object.layer_materials.find(object.body.tet_labels[t]);
    if (layer != object.layer_materials.end()) id = layer->second;
  }
  static const core::Material kDefault{};
  if (id.empty()) return kDefault;
  const auto it = scenario.materials.find(id);
  if (it == scenario.materials.end()) {
    throw core::InputError("unknown material id \"" + id + "\"", {"", "", "object " + object.id});
  }
  return it->second;
}

std::vector<SofaSpring> kismo_springs(const core::Scenario& scenario,
                                      const core::SceneObject& object) {
  const core::TetMesh& body = object.body;
  // Each tet gives V/6 of its volume to each of its six edges (deformable_body.cpp), weighted
  // here by the tet's own material.
  std::map<std::array<int, 2>, std::array<double, 2>> weighted;  // {c₁ share, s_d share}
  for (std::size_t t = 0; t < body.tets.size(); ++t) {
    const core::Material& material = tet_material(scenario, object, t);
    const double share = core::signed_volume(body, static_cast<int>(t)) / 6.0;
    const double c1 = kismo_linear_coefficient(material);
    const double sd = std::max(material.distance_damping, 0.0);
    const auto& tet = body.tets[t];
    for (int a = 0; a < 4; ++a) {
      for (int b = a + 1; b < 4; ++b) {
        auto& w = weighted[{std::min(tet[a], tet[b]), std::max(tet[a], tet[b])}];
        w[0] += c1 * share;
        w[1] += sd * share;
      }
    }
  }
  std::vector<SofaSpring> springs;
  springs.reserve(weighted.size());
  for (const auto& [edge, w] : weighted) {
    const double rest = (body.nodes[static_cast<std::size_t>(edge[1])] -
                         body.nodes[static_cast<std::size_t>(edge[0])])
                            .norm();
    springs.push_back({edge[0], edge[1], w[0] / (rest * rest), w[1] / (rest * rest), rest});
  }
  return springs;
}

std::optional<double> uniform_tetrahedra_stiffness(const std::vector<SofaSpring>& springs,
                                                   double relative_tolerance) {
  if (springs.empty()) return std::nullopt;
  double low = springs.front().stiffness * springs.front().rest_length, high = low;
  for (const auto& s : springs) {
    low = std::min(low, s.stiffness * s.rest_length);
    high = std::max(high, s.stiffness * s.rest_length);
  }
  const double mid = 0.5 * (low + high);
  if (high - mid > relative_tolerance * mid) return std::nullopt;
  return mid;
}

}  // namespace viscera::exporters
