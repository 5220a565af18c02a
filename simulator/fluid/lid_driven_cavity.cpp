#include "simulator/fluid/lid_driven_cavity.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.h"
#include "simulator/fluid/stable_fluids.h"

namespace viscera::sim::fluid {
namespace {

struct GhiaTable {
  double reynolds;
  std::vector<double> u;  ///< at kGhiaY
  std::vector<double> v;  ///< at kGhiaX
};

// Ghia, Ghia & Shin 1982, Table I (y, u) and Table II (x, v), as published. (The Re = 400 v at
// x = 0.9063, −0.23827, breaks the smooth profile around it and may be a misprint; it is kept.)
const std::vector<double> kGhiaY{1.0000, 0.9766, 0.9688, 0.9609, 0.9531, 0.8516,
                                 0.7344, 0.6172, 0.5000, 0.4531, 0.2813, 0.1719,
                                 0.1016, 0.0703, 0.0625, 0.0547, 0.0000};
const std::vector<double> kGhiaX{1.0000, 0.9688, 0.9609, 0.9531, 0.9453, 0.9063,
                                 0.8594, 0.8047, 0.5000, 0.2344, 0.2266, 0.1563,
                                 0.0938, 0.0781, 0.0703, 0.0625, 0.0000};
const std::vector<GhiaTable> kGhia{
    {100.0,
     {1.00000, 0.84123, 0.78871, 0.73722, 0.68717, 0.23151, 0.00332, -0.13641, -0.20581, -0.21090,
      -0.15662, -0.10150, -0.06434, -0.04775, -0.04192, -0.03717, 0.00000},
     {0.00000, -0.05906, -0.07391, -0.08864, -0.10313, -0.16914, -0.22445, -0.24533, 0.05454,
      0.17527, 0.17507, 0.16077, 0.12317, 0.10890, 0.10091, 0.09233, 0.00000}},
    {400.0,
     {1.00000, 0.75837, 0.68439, 0.61756, 0.55892, 0.29093, 0.16256, 0.02135, -0.11477, -0.17119,
      -0.32726, -0.24299, -0.14612, -0.10338, -0.09266, -0.08186, 0.00000},
     {0.00000, -0.12146, -0.15663, -0.19254, -0.22847, -0.23827, -0.44993, -0.38598, 0.05186,
      0.30174, 0.30203, 0.28124, 0.22965, 0.20920, 0.19713, 0.18360, 0.00000}},
};

const GhiaTable& table_for(double reynolds) {
  for (const auto& table : kGhia)
    if (table.reynolds == reynolds) return table;
  throw core::UsageError("the lid-driven cavity has reference tables for Re = 100 and 400, not " +
                         std::to_string(reynolds));
}

double rms(const std::vector<CentreLinePoint>& points) {
  double sum = 0.0;
  for (const auto& p : points)
    sum += (p.computed - p.reference) * (p.computed - p.reference);
  return std::sqrt(sum / static_cast<double>(points.size()));
}

}  // namespace

std::vector<double> ghia_reynolds_numbers() {
  std::vector<double> numbers;
  for (const auto& table : kGhia)
    numbers.push_back(table.reynolds);
  return numbers;
}

CavityResult run_lid_driven_cavity(const CavityRun& run, core::Progress& progress) {
  const GhiaTable& table = table_for(run.reynolds);
  if (run.grid < 8) throw core::UsageError("the cavity needs a grid of at least 8 cells a side");
  if (!(run.cfl > 0.0)) throw core::UsageError("the cavity's CFL number must be positive");
  const int n = run.grid;
  const double h = 1.0 / n;
  // The unit square inside a ring of wall cells; the top ring slides at the lid's speed.
  FlowGrid grid(n + 2, n + 2, 1, h, core::Vec3(-h, -h, 0.0));
  for (int i = 0; i < n + 2; ++i) {
    grid.set_cell(i, 0, 0, FlowCell::Solid);
    grid.set_cell(i, n + 1, 0, FlowCell::Solid, core::Vec3(1.0, 0.0, 0.0));
  }
  for (int j = 1; j <= n; ++j) {
    grid.set_cell(0, j, 0, FlowCell::Solid);
    grid.set_cell(n + 1, j, 0, FlowCell::Solid);
  }
  grid.update_faces();

  FlowSettings settings;
  settings.viscosity = 1.0 / run.reynolds;
  settings.time_step = run.cfl * h;
  settings.second_order = run.second_order;
  settings.divergence_tolerance = run.divergence_tolerance;
  settings.max_pressure_iterations = 20 * n;
  settings.threads = run.threads;

  CavityResult result;
  result.run = run;
  const int max_steps = static_cast<int>(std::ceil(run.max_time / settings.time_step));
  progress.begin_stage("lid-driven cavity at Re " + std::to_string(static_cast<int>(run.reynolds)),
                       max_steps);
  std::vector<double> before_u, before_v;
  FlowSolver solver;
  for (int s = 0; s < max_steps && !result.steady; ++s) {
    before_u = grid.velocity(0);
    before_v = grid.velocity(1);
    const FlowStepReport report = solver.step(grid, settings);
    result.pressure_iterations += report.pressure_iterations;
    double change = 0.0;
    for (std::size_t f = 0; f < before_u.size(); ++f)
      change = std::max(change, std::abs(grid.velocity(0)[f] - before_u[f]));
    for (std::size_t f = 0; f < before_v.size(); ++f)
      change = std::max(change, std::abs(grid.velocity(1)[f] - before_v[f]));
    result.final_rate = change / settings.time_step;
    result.steady = result.final_rate < run.steady_rate;
    ++result.steps;
    progress.step();
  }
  result.simulated_time = result.steps * settings.time_step;
  result.max_divergence = grid.max_divergence();

  for (std::size_t p = 0; p < kGhiaY.size(); ++p) {
    const double y = kGhiaY[p];
    const bool wall = y == 0.0 || y == 1.0;
    const double u = wall ? (y == 1.0 ? 1.0 : 0.0) : grid.sample(0, core::Vec3(0.5, y, 0.5 * h));
    result.u_vertical.push_back({y, u, table.u[p]});
  }
  for (std::size_t p = 0; p < kGhiaX.size(); ++p) {
    const double x = kGhiaX[p];
    const bool wall = x == 0.0 || x == 1.0;
    const double v = wall ? 0.0 : grid.sample(1, core::Vec3(x, 0.5, 0.5 * h));
    result.v_horizontal.push_back({x, v, table.v[p]});
  }
  result.u_rms_error = rms(result.u_vertical);
  result.v_rms_error = rms(result.v_horizontal);
  return result;
}

nlohmann::json to_json(const CavityResult& result) {
  nlohmann::json u = nlohmann::json::array(), v = nlohmann::json::array();
  for (const auto& p : result.u_vertical)
    u.push_back({{"y", p.position}, {"u", p.computed}, {"ghia", p.reference}});
  for (const auto& p : result.v_horizontal)
    v.push_back({{"x", p.position}, {"v", p.computed}, {"ghia", p.reference}});
  return {{"format", "viscera-cavity-validation"},
          {"reference", "Ghia, Ghia & Shin 1982, J. Comput. Phys. 48:387-411, Tables I-II"},
          {"reynolds", result.run.reynolds},
          {"grid", result.run.grid},
          {"advection", result.run.second_order ? "maccormack" : "semi-lagrangian"},
          {"time_step", result.run.cfl / result.run.grid},
          {"steps", result.steps},
          {"simulated_time", result.simulated_time},
          {"steady", result.steady},
          {"final_rate", result.final_rate},
          {"steady_rate", result.run.steady_rate},
          {"max_divergence", result.max_divergence},
          {"divergence_tolerance", result.run.divergence_tolerance},
          {"pressure_iterations", result.pressure_iterations},
          {"u_vertical", u},
          {"v_horizontal", v},
          {"u_rms_error", result.u_rms_error},
          {"v_rms_error", result.v_rms_error}};
}

}  // namespace viscera::sim::fluid
