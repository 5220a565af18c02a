#include "templates/generator/simulation_check.h"

#include <cmath>
#include <span>
#include <sstream>

#include "core/error.h"
#include "core/random.h"
#include "simulator/world/world.h"

namespace viscera::templates {
namespace {

double diagonal(std::span<const core::Vec3> points) {
  core::BoundingBox box;
  for (const auto& p : points)
    box.add(p);
  return points.empty() ? 0.0 : (box.max - box.min).norm();
}

/// Largest displacement from `rest` and largest speed (m/s) of a body; not finite when a
/// position is not finite.
struct Motion {
  double displacement = 0.0, speed = 0.0;
  bool finite = true;
};

Motion motion_of(std::span<const core::Vec3> x, std::span<const core::Vec3> velocity,
                 std::span<const core::Vec3> rest) {
  Motion m;
  for (std::size_t n = 0; n < x.size(); ++n) {
    if (!x[n].allFinite()) {
      m.finite = false;
      return m;
    }
    m.displacement = std::max(m.displacement, (x[n] - rest[n]).norm());
    if (!velocity.empty()) m.speed = std::max(m.speed, velocity[n].norm());
  }
  return m;
}

}  // namespace

ValidationCheck simulate_one_second(const core::Scenario& scenario,
                                    const SimulationBounds& bounds) {
  ValidationCheck check{"simulation", true, "", {}};
  const double h = scenario.session.time_step;
  const long long steps = std::llround(bounds.duration / h);
  double worst_displacement = 0.0, worst_speed = 0.0;
  const auto judge = [&](const std::string& body, const Motion& m, double limit) {
    worst_displacement = std::max(worst_displacement, m.displacement);
    worst_speed = std::max(worst_speed, m.speed);
    std::ostringstream why;
    if (!m.finite) {
      why << "body " << body << " reached a non-finite position";
    } else if (m.displacement > limit) {
      why << "body " << body << " moved " << m.displacement * 1000.0 << " mm from rest (at most "
          << limit * 1000.0 << " mm)";
    } else if (m.speed > bounds.max_speed) {
      why << "body " << body << " reached " << m.speed << " m/s (at most " << bounds.max_speed
          << " m/s)";
    }
    if (why.str().empty()) return true;
    check.passed = false;
    check.detail = why.str();
    return false;
  };
  try {
    sim::World world(scenario);
    // A check of the patient's limits: a tet turned inside out is a failure, not a load case.
    world.set_inversion_errors(true);
    core::Rng rng(1);
    for (auto& body : world.bodies()) {
      const auto x = body.positions();
      for (std::size_t n = 0; n < x.size(); ++n) {
        if (body.inverse_masses()[n] == 0.0) continue;
        const core::Vec3 offset(rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0),
                                rng.uniform(-1.0, 1.0));
        x[n] += bounds.perturbation * offset;
      }
    }
    std::vector<double> limits;
    for (const auto& body : world.bodies())
      limits.push_back(bounds.max_displacement_fraction * diagonal(body.rest_positions()));
    for (long long s = 1; s <= steps && check.passed; ++s) {
      world.step();
      if (s % 10 != 0 && s != steps) continue;
      for (std::size_t b = 0; b < world.bodies().size() && check.passed; ++b) {
        const auto& body = world.bodies()[b];
        judge(body.name(), motion_of(body.positions(), body.velocities(), body.rest_positions()),
              limits[b]);
      }
    }
    check.measures["substeps"] = world.substeps();
    check.measures["bodies"] = world.bodies().size();
    if (check.passed) {
      const double kinetic = world.energies().kinetic;
      check.measures["kinetic_energy"] = kinetic;
      if (!std::isfinite(kinetic)) {
        check.passed = false;
        check.detail = "kinetic energy is not finite";
      }
    }
    // Cell-agent tissues are bodies of the world (seed 003 §V), judged with the others above.
  } catch (const core::CancelledError&) {
    throw;
  } catch (const core::Error& e) {
    check.passed = false;
    check.detail = e.what();
  }
  check.measures["steps"] = steps;
  check.measures["simulated_seconds"] = static_cast<double>(steps) * h;
  check.measures["max_displacement"] = worst_displacement;
  check.measures["max_speed"] = worst_speed;
  return check;
}

}  // namespace viscera::templates
