#include "simulator/session/headless_session.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "core/error.h"
#include "simulator/world/world.h"

namespace viscera::sim {
namespace {

/// Watches one "settle" task: at rest once kinetic energy stays below a bound long enough.
struct SettleWatch {
  std::size_t task = 0;
  double kinetic_bound = 1e-6;  ///< J
  double hold_time = 0.1;       ///< s
  double calm_since = -1.0;     ///< s, or −1 while moving
};

}  // namespace

SessionReport run_headless(const core::Scenario& scenario, const HeadlessRunOptions& options, core::Progress& progress) {
  if (!(options.duration > 0.0)) throw core::UsageError("session duration must be positive");
  const auto started = std::chrono::steady_clock::now();
  World world(scenario);

  SessionReport report;
  report.package = options.package;
  report.time_step = world.time_step();
  report.substeps = world.substeps();

  std::vector<SettleWatch> settles;
  for (std::size_t t = 0; t < scenario.session.tasks.size(); ++t) {
    const auto& task = scenario.session.tasks[t];
    TaskResult result{task.id, task.kind, "not-completed", -1.0, ""};
    if (task.kind == "settle") {
      settles.push_back({t, task.parameters.value("kinetic_energy_below", 1e-6), task.parameters.value("hold_time", 0.1), -1.0});
    } else {
      result.status = "unavailable";
      result.note = "tasks of kind \"" + task.kind + "\" need the session runtime of a later release";
    }
    report.tasks.push_back(result);
  }

  int instrument_body = -1;
  if (options.instrument != nullptr) {
    for (std::size_t b = 0; b < world.bodies().size(); ++b) {
      if (world.bodies()[b].name() == options.instrument_body) instrument_body = static_cast<int>(b);
    }
    if (instrument_body < 0) {
      throw core::InputError("the scenario has no simulated object \"" + options.instrument_body + "\" for the instrument");
    }
    const core::Vec3 start = options.instrument->tip(0, 0.0);
    world.attach_instrument(instrument_body, options.instrument_stiffness, start);
    if (options.record_inputs) report.inputs.push_back(start);  // inputs[s] is the tip of step s
    report.has_instrument = true;
  }

  const auto total_steps = static_cast<long long>(std::llround(options.duration / world.time_step()));
  const long long sample_every = std::max<long long>(1, std::llround(options.sample_interval / world.time_step()));
  progress.begin_stage("simulating", total_steps);
  const auto sample = [&] {
    const BodyEnergies e = world.energies();
    double displacement = 0.0;
    for (const auto& body : world.bodies()) displacement = std::max(displacement, body.max_displacement());
    report.samples.push_back({world.time(), e.kinetic, e.elastic, e.gravitational, displacement,
                              world.contacts().colliding_points, world.contacts().max_penetration});
    report.max_displacement = std::max(report.max_displacement, displacement);
    for (auto& watch : settles) {
      auto& result = report.tasks[watch.task];
      if (result.status == "completed") continue;
      if (e.kinetic < watch.kinetic_bound) {
        if (watch.calm_since < 0.0) watch.calm_since = world.time();
        if (world.time() - watch.calm_since >= watch.hold_time) {
          result.status = "completed";
          result.completed_at = world.time();
        }
      } else {
        watch.calm_since = -1.0;
      }
    }
  };
  sample();
  bool over_force = false;
  for (long long s = 1; s <= total_steps; ++s) {
    if (options.instrument != nullptr) {
      const core::Vec3 tip = options.instrument->tip(s, world.time() + world.time_step());
      world.set_instrument_tip(tip);
      if (options.record_inputs) report.inputs.push_back(tip);
    }
    world.step();
    bool perforated = false;
    if (options.instrument != nullptr) {
      const core::Vec3 force = world.instrument_force();
      report.metrics.record(world.instrument_tip(), force, world.instrument_in_contact(), world.time_step());
      // The proxy stays on the surface: its distance to the tip is how deep the tool pushes.
      const double depth = force.norm() / options.instrument_stiffness;
      if (options.perforation_depth > 0.0 && depth > options.perforation_depth) {
        report.events.push_back({world.time(), "perforation",
                                 "the tool went " + std::to_string(depth * 1000.0) + " mm into the wall, past its " +
                                     std::to_string(options.perforation_depth * 1000.0) + " mm"});
        report.end_reason = "perforation";
        perforated = true;
      }
      const bool excessive = options.force_warning > 0.0 && force.norm() > options.force_warning;
      if (excessive && !over_force) {
        report.events.push_back({world.time(), "excessive-force",
                                 "force " + std::to_string(force.norm()) + " N above the " +
                                     std::to_string(options.force_warning) + " N warning level"});
      }
      over_force = excessive;
    }
    if (options.checkpoint_interval > 0 && s % options.checkpoint_interval == 0) {
      report.checkpoints.emplace_back(s, world.state_hash());
    }
    if (s % sample_every == 0 || s == total_steps || perforated) sample();
    progress.step();
    if (perforated) break;
  }

  report.steps = world.steps();
  report.simulated_time = world.time();
  report.final_state_hash = world.state_hash();
  report.max_penetration = world.max_penetration();
  report.contact_stiffness = world.bodies().size() > 1 ? scenario.session.contact_stiffness : 0.0;
  for (const auto& body : world.bodies()) {
    BodySummary summary;
    summary.name = body.name();
    summary.nodes = body.node_count();
    summary.edges = body.distance_terms().edges.size();
    summary.tets = body.volume_terms().tets.size();
    summary.surface_triangles = body.area_terms().triangles.size();
    summary.max_displacement = body.max_displacement();
    const core::Vec3 down = world.gravity().norm() > 0.0 ? core::Vec3(world.gravity().normalized()) : core::Vec3::Zero();
    summary.centre_of_mass_drop = down.dot(body.centre_of_mass() - body.rest_centre_of_mass());
    report.bodies.push_back(summary);
  }
  report.wall_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return report;
}

nlohmann::json report_to_json(const SessionReport& r) {
  nlohmann::json series = {{"time", nlohmann::json::array()},          {"kinetic", nlohmann::json::array()},
                           {"elastic", nlohmann::json::array()},       {"gravitational", nlohmann::json::array()},
                           {"total", nlohmann::json::array()},         {"max_displacement", nlohmann::json::array()}};
  nlohmann::json contacts = {{"colliding_points", nlohmann::json::array()}, {"max_penetration", nlohmann::json::array()}};
  for (const auto& s : r.samples) {
    series["time"].push_back(s.time);
    series["kinetic"].push_back(s.kinetic);
    series["elastic"].push_back(s.elastic);
    series["gravitational"].push_back(s.gravitational);
    series["total"].push_back(s.total());
    series["max_displacement"].push_back(s.max_displacement);
    contacts["colliding_points"].push_back(s.colliding_points);
    contacts["max_penetration"].push_back(s.max_penetration);
  }
  contacts["max_penetration_overall"] = r.max_penetration;
  contacts["stiffness"] = r.contact_stiffness;
  nlohmann::json bodies = nlohmann::json::array();
  for (const auto& b : r.bodies) {
    bodies.push_back({{"name", b.name}, {"nodes", b.nodes}, {"edges", b.edges}, {"tets", b.tets},
                      {"surface_triangles", b.surface_triangles}, {"max_displacement", b.max_displacement},
                      {"centre_of_mass_drop", b.centre_of_mass_drop}});
  }
  nlohmann::json tasks = nlohmann::json::array();
  for (const auto& t : r.tasks) {
    nlohmann::json task = {{"id", t.id}, {"kind", t.kind}, {"status", t.status}};
    if (t.completed_at >= 0.0) task["completed_at"] = t.completed_at;
    if (!t.note.empty()) task["note"] = t.note;
    tasks.push_back(task);
  }
  nlohmann::json events = nlohmann::json::array();
  for (const auto& e : r.events) events.push_back({{"time", e.time}, {"kind", e.kind}, {"message", e.message}});
  return {{"format", "viscera-session-report"},
          {"version", 1},
          {"package", r.package},
          {"steps", r.steps},
          {"simulated_time", r.simulated_time},
          {"wall_time", r.wall_time},
          {"time_step", r.time_step},
          {"substeps", r.substeps},
          {"real_time_factor", r.wall_time > 0.0 ? r.simulated_time / r.wall_time : 0.0},
          {"units", {{"time", "s"}, {"energy", "J"}, {"length", "m"}}},
          {"energy", series},
          {"max_displacement", r.max_displacement},
          {"contacts", contacts},
          {"bodies", bodies},
          {"tasks", tasks},
          {"instrument", r.has_instrument ? r.metrics.to_json() : nlohmann::json(nullptr)},
          {"end_reason", r.end_reason},
          {"events", events},
          {"checkpoints", r.checkpoints.size()},
          {"final_state_hash", r.final_state_hash}};
}

}  // namespace viscera::sim
