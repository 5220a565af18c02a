#pragma once
/// Tissue materials (DESIGN.md §3). Stiffnesses are densities so that a material behaves the
/// same at any mesh resolution; the simulator turns them into the per-element constants k of
/// Teschner et al. 2004 (seed 000 §3, eq. 3–7) by multiplying with the element's rest measure.

#include <optional>
#include <string>
#include <vector>

namespace viscera::core {

/// A measured uniaxial stress-strain curve and its cubic fit σ(ε) = c1 ε + c2 ε² + c3 ε³
/// (seed 001 §3.2). Strain dimensionless, stress in Pa.
struct StressStrainCurve {
  std::vector<double> strain;
  std::vector<double> stress;  ///< Pa
  std::vector<double> cubic;   ///< {c0, c1, c2, c3} in Pa, empty until fitted
  double fit_rms_error = 0.0;  ///< Pa
  double fit_max_error = 0.0;  ///< Pa, largest absolute residual of the fit

  bool operator==(const StressStrainCurve&) const = default;
};

/// Mechanical parameters of one tissue.
struct Material {
  std::string id;
  std::string name;
  double density = 1000.0;             ///< kg/m³
  double distance_stiffness = 3000.0;  ///< Pa; k_D of an edge = this × the edge's volume share
  double area_stiffness = 0.0;         ///< N/m; k_A of a surface triangle = this × rest area
  double volume_stiffness = 3000.0;    ///< Pa; k_V of a tet = this × rest volume
  double distance_damping = 5.0;       ///< Pa·s; k_d of an edge = this × the edge's volume share
  double tearing_threshold = 0.5;      ///< strain at which tissue tears
  double plastic_yield = 0.3;          ///< strain beyond which rest lengths change
  std::optional<StressStrainCurve> stress_strain;
  std::string source;  ///< where the numbers come from

  bool operator==(const Material&) const = default;
};

}  // namespace viscera::core
