#pragma once
/// The validation of the flow solver: the 2D lid-driven cavity — a unit square of fluid, its lid
/// sliding at unit speed, the other walls at rest — run to steady state and compared with the
/// centre-line tables of Ghia, Ghia & Shin 1982 (J. Comput. Phys. 48, 387–411; Table I: u along
/// the vertical centre line, Table II: v along the horizontal one) at Re = 100 and 400.
///
/// Lengths and velocities are in units of the side and the lid speed (so ν = 1/Re). Steady
/// state: the largest change of any face velocity per unit time falls below `steady_rate`.
/// Points on the walls (the tables' first and last rows) take the wall's velocity, the no-slip
/// condition the solver imposes there; the others are interpolated from the faces.

#include <nlohmann/json.hpp>
#include <vector>

#include "core/progress.h"

namespace viscera::sim::fluid {

struct CavityRun {
  double reynolds = 100.0;
  int grid = 128;                      ///< cells along each side
  bool second_order = true;            ///< MacCormack advection
  double cfl = 1.0;                    ///< Δt = cfl · h / U
  double steady_rate = 1e-4;           ///< U²/L: max |Δu|/Δt below this is steady
  double max_time = 100.0;             ///< L/U of simulated time before giving up
  double divergence_tolerance = 1e-6;  ///< U/L, per projection
  int threads = 0;
};

struct CentreLinePoint {
  double position = 0.0;   ///< y on the vertical line, x on the horizontal one
  double computed = 0.0;   ///< u resp. v / U
  double reference = 0.0;  ///< Ghia et al. 1982
};

struct CavityResult {
  CavityRun run;
  int steps = 0;
  double simulated_time = 0.0;  ///< L/U
  bool steady = false;
  double final_rate = 0.0;  ///< the last step's max |Δu|/Δt, U²/L
  double max_divergence = 0.0;
  int pressure_iterations = 0;  ///< summed over all steps
  std::vector<CentreLinePoint> u_vertical, v_horizontal;
  double u_rms_error = 0.0, v_rms_error = 0.0;  ///< RMS over the table points, in U
};

/// Reynolds numbers with reference tables.
std::vector<double> ghia_reynolds_numbers();

/// Runs the cavity. Throws core::UsageError for a Reynolds number without a table, a grid
/// below 8 cells or a non-positive CFL number; CancelledError through `progress`.
CavityResult run_lid_driven_cavity(const CavityRun& run,
                                   core::Progress& progress = core::Progress::none());

/// {"format": "viscera-cavity-validation", "reynolds", "grid", …, "u_vertical": [{"y",
/// "u", "ghia"}…], "v_horizontal": [{"x", "v", "ghia"}…], "u_rms_error", "v_rms_error"}.
nlohmann::json to_json(const CavityResult& result);

}  // namespace viscera::sim::fluid
