#include "simulator/app/fluid_command.h"

#include <iomanip>
#include <iostream>
#include <memory>

#include "simulator/fluid/lid_driven_cavity.h"

namespace fluid = viscera::sim::fluid;

void add_fluid_command(CLI::App& app, int& exit_code) {
  auto* group = app.add_subcommand("fluid", "Validate the distension flow solver");
  group->require_subcommand(1);
  auto run = std::make_shared<fluid::CavityRun>();
  auto as_json = std::make_shared<bool>(false);
  auto first_order = std::make_shared<bool>(false);
  auto* cavity = group->add_subcommand(
      "cavity",
      "Run the 2D lid-driven cavity to steady state and compare its centre lines with Ghia, "
      "Ghia & Shin 1982");
  cavity->add_option("--re", run->reynolds, "Reynolds number: 100 or 400")
      ->check(CLI::IsMember({100.0, 400.0}));
  cavity->add_option("--grid", run->grid, "Cells along each side (default 128)")
      ->check(CLI::Range(8, 1024));
  cavity->add_option("--cfl", run->cfl, "Time step in cell crossings of the lid (default 1)")
      ->check(CLI::PositiveNumber);
  cavity
      ->add_option("--max-time", run->max_time,
                   "Simulated time before giving up on steady state, in side/lid-speed units "
                   "(default 100)")
      ->check(CLI::PositiveNumber);
  cavity->add_flag("--first-order", *first_order,
                   "First-order semi-Lagrangian advection instead of MacCormack");
  cavity->add_flag("--json", *as_json, "Print the profiles and errors as JSON");
  cavity->callback([run, as_json, first_order, &exit_code] {
    run->second_order = !*first_order;
    const fluid::CavityResult result = fluid::run_lid_driven_cavity(*run);
    if (*as_json) {
      std::cout << fluid::to_json(result).dump(2) << "\n";
    } else {
      std::cout << std::fixed << std::setprecision(4) << "lid-driven cavity Re " << run->reynolds
                << " on " << run->grid << "x" << run->grid << ": "
                << (result.steady ? "steady" : "NOT steady") << " after " << result.steps
                << " steps (t = " << result.simulated_time << ")\n"
                << "RMS error against Ghia et al. 1982: u " << 100.0 * result.u_rms_error
                << " %, v " << 100.0 * result.v_rms_error << " % of the lid speed\n";
    }
    exit_code = result.steady ? 0 : 4;
  });
}
