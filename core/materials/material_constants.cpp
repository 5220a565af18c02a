#include "core/materials/material_constants.h"

#include <cmath>
#include <sstream>

#include "core/error.h"
#include "core/materials/cubic_stress_fit.h"

namespace viscera::core {

double linearised_modulus(const std::array<double, 4>& c, double w) {
  if (!(w > 0.0)) throw UsageError("the working strain must be positive");
  // E = ∫σ ε dε / ∫ε² dε over [0, w].
  return c[1] + 0.75 * c[2] * w + 0.6 * c[3] * w * w;
}

TeschnerConstants teschner_constants(const std::array<double, 4>& cubic, double working_strain,
                                     const ElasticityOptions& options) {
  const double nu = options.poisson_ratio;
  if (!(nu >= 0.25 && nu < 0.5)) {
    throw UsageError(
        "Poisson's ratio must be in [0.25, 0.5) for an edge network with volume terms");
  }
  if (!(options.membrane_thickness >= 0.0))
    throw UsageError("the membrane thickness must not be negative");
  if (!(working_strain > 0.0)) throw UsageError("the working strain must be positive");

  // The tangent c1 + 2 c2 ε + 3 c3 ε² is a quadratic in ε ≥ 0: check the ends and its vertex.
  double lowest =
      std::min(cubic_tangent_modulus(cubic, 0.0), cubic_tangent_modulus(cubic, working_strain));
  if (cubic[3] != 0.0) {
    const double vertex = -cubic[2] / (3.0 * cubic[3]);
    if (vertex > 0.0 && vertex < working_strain)
      lowest = std::min(lowest, cubic_tangent_modulus(cubic, vertex));
  }
  if (!(lowest > 0.0)) {
    std::ostringstream message;
    message << "the fitted cubic is not stiffening monotonically up to strain " << working_strain
            << " (its tangent modulus falls to " << lowest
            << " Pa); measure further or fit a narrower range";
    throw ValidationError(message.str());
  }

  TeschnerConstants k;
  k.working_strain = working_strain;
  k.linear_modulus = linearised_modulus(cubic, working_strain);
  k.shear_modulus = k.linear_modulus / (2.0 * (1.0 + nu));
  k.lame_lambda = k.linear_modulus * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
  k.distance_stiffness = 15.0 * k.shear_modulus;
  k.volume_stiffness = k.lame_lambda - k.shear_modulus;
  k.area_stiffness = k.linear_modulus * options.membrane_thickness / (2.0 * (1.0 - nu));
  return k;
}

double strain_at_stress(const std::array<double, 4>& cubic, double stress, double limit) {
  if (cubic_stress(cubic, limit) <= stress) return limit;
  double lo = 0.0, hi = limit;
  for (int i = 0; i < 100 && hi - lo > 1e-12 * limit; ++i) {
    const double mid = 0.5 * (lo + hi);
    (cubic_stress(cubic, mid) < stress ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

Material material_from_measured_curve(const StressStrainCurve& measured,
                                      const ElasticityOptions& options, Material base) {
  const StressStrainCurve fitted = with_cubic_fit(measured);
  const std::array<double, 4> cubic = {fitted.cubic[0], fitted.cubic[1], fitted.cubic[2],
                                       fitted.cubic[3]};
  double max_strain = 0.0;
  for (const double e : fitted.strain)
    max_strain = std::max(max_strain, std::abs(e));
  const double working = options.working_strain > 0.0 ? options.working_strain : max_strain;
  const TeschnerConstants k = teschner_constants(cubic, working, options);
  base.distance_stiffness = k.distance_stiffness;
  base.volume_stiffness = k.volume_stiffness;
  base.area_stiffness = k.area_stiffness;
  base.stress_strain = fitted;
  return base;
}

}  // namespace viscera::core
