#pragma once
/// Least-squares cubic fit of a measured stress-strain curve (seed 001 §3.2: the curves "have
/// been recorded and approximated by polynomials third degree, which were used to set up the
/// spring constants correctly").
///
/// The model is the force law of the simulator's KisMo springs (simulator/physics/
/// kismo_mass_spring.h): σ(ε) = c1 ε + c2 ε|ε| + c3 ε³ in Pa. It passes through the origin,
/// because a spring at rest length carries no force, and its quadratic term is odd, so a
/// compression pushes as hard as the same stretch pulls; on tension data (ε ≥ 0) it is the
/// ordinary cubic c1 ε + c2 ε² + c3 ε³. The coefficients are stored as {0, c1, c2, c3}
/// (StressStrainCurve::cubic), which is exactly what the simulator reads.

#include <array>

#include "core/scenario/material.h"

namespace viscera::core {

/// The fitted coefficients and how well they match the samples.
struct CubicStressFit {
  std::array<double, 4> cubic = {0.0, 0.0, 0.0, 0.0};  ///< {c0 = 0, c1, c2, c3} in Pa
  double rms_error = 0.0;                              ///< Pa, root mean square of the residuals
  double max_error = 0.0;                              ///< Pa, largest absolute residual
  std::size_t max_error_sample = 0;  ///< index of the sample with the largest residual
  double r_squared = 1.0;            ///< 1 − SS_res / SS_tot about the mean stress
  double max_strain = 0.0;           ///< largest |ε| among the samples
};

/// σ(ε) of the model for coefficients {c0, c1, c2, c3} (c0 is ignored: always zero).
double cubic_stress(const std::array<double, 4>& cubic, double strain);
/// dσ/dε in Pa.
double cubic_tangent_modulus(const std::array<double, 4>& cubic, double strain);

/// Fits the model to `curve.strain`/`curve.stress` by linear least squares (column-scaled
/// Householder QR, so strains of 1e-3 and stresses of 1e6 Pa are solved alike). Throws
/// UsageError when the arrays differ in length or hold fewer than 4 samples, and InputError
/// when fewer than 3 distinct non-zero |strain| values leave the coefficients undetermined.
CubicStressFit fit_cubic_stress(const StressStrainCurve& curve);

/// `curve` with its cubic, RMS and maximum error filled in from `fit_cubic_stress`.
StressStrainCurve with_cubic_fit(StressStrainCurve curve);

}  // namespace viscera::core
