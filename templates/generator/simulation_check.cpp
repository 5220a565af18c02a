#include "templates/generator/simulation_check.h"

#include <cmath>
#include <span>
#include <sstream>

#include "core/error.h"
#include "core/random.h"
#include "simulator/physics/cell_agent_tissue.h"
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

std::vector<sim::CellType> cell_types_of(const core::CellTissueSpec& spec) {
  std::vector<sim::CellType> types;
  for (const auto& t : spec.types) {
    sim::CellType c;
    c.mass = t.mass;
    c.radius = t.radius;
    c.home_stiffness = t.home_stiffness;
    c.connection_stiffness = t.connection_stiffness;
    c.damping = t.damping;
    c.collision_efficiency = t.collision_efficiency;
    c.tear_strain = t.tear_strain;
    c.yield_strain = t.yield_strain;
    types.push_back(c);
  }
  return types;
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
    for (const auto& spec : scenario.cell_tissues) {
      if (!check.passed) break;
      const core::SceneObject* object = scenario.find_object(spec.object);
      if (object == nullptr) {
        check.passed = false;
        check.detail = "cell tissue names a missing object " + spec.object;
        break;
      }
      sim::CellAgentTissue tissue(object->body.nodes, cell_types_of(spec), spec.cell_types,
                                  spec.neighbour_radius, spec.max_neighbours, spec.planar);
      const double limit = bounds.max_displacement_fraction * diagonal(object->body.nodes);
      // The same perturbation as the bodies': a first-step push that moves each cell by up to
      // bounds.perturbation per axis (Δx = h² F / m).
      for (std::size_t c = 0; c < tissue.positions().size(); ++c) {
        const double mass = spec.types.at(static_cast<std::size_t>(spec.cell_types.at(c))).mass;
        core::Vec3 offset(rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0));
        if (spec.planar) offset.z() = 0.0;
        tissue.push(static_cast<int>(c), mass * bounds.perturbation / (h * h) * offset);
      }
      for (long long s = 1; s <= steps && check.passed; ++s) {
        tissue.step(h);
        if (s % 10 != 0 && s != steps) continue;
        judge(spec.object, motion_of(tissue.positions(), {}, object->body.nodes), limit);
        for (const auto& v : tissue.velocities())
          worst_speed = std::max(worst_speed, v.norm());
        if (worst_speed > bounds.max_speed) {
          check.passed = false;
          check.detail = "cells of " + spec.object + " move faster than the bound";
        }
      }
    }
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
