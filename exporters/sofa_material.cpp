#include "exporters/sofa_material.h"

#include <algorithm>
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
  result.rayleigh_stiffness =
      std::max(material.distance_damping, 0.0) / material.distance_stiffness;
  return result;
}

SofaSprings sofa_springs(const core::Material& material, const core::TetMesh& body) {
  // The same edge shares as simulator/physics/deformable_body.cpp: each tet gives V/6 to each
  // of its six edges.
  std::map<std::array<int, 2>, double> share;
  for (std::size_t t = 0; t < body.tets.size(); ++t) {
    const double volume = core::signed_volume(body, static_cast<int>(t));
    const auto& tet = body.tets[t];
    for (int a = 0; a < 4; ++a) {
      for (int b = a + 1; b < 4; ++b)
        share[{std::min(tet[a], tet[b]), std::max(tet[a], tet[b])}] += volume / 6.0;
    }
  }
  const bool cubic = material.stress_strain && material.stress_strain->cubic.size() == 4;
  const double linear = cubic ? material.stress_strain->cubic[1] : material.distance_stiffness;
  SofaSprings result;
  if (share.empty()) return result;
  for (const auto& [edge, volume_share] : share) {
    const double rest = (body.nodes[static_cast<std::size_t>(edge[1])] -
                         body.nodes[static_cast<std::size_t>(edge[0])])
                            .squaredNorm();
    result.stiffness += linear * volume_share / rest;
    result.damping += material.distance_damping * volume_share / rest;
  }
  result.stiffness /= static_cast<double>(share.size());
  result.damping /= static_cast<double>(share.size());
  return result;
}

}  // namespace viscera::exporters
