#include "simulator/session/session_runner.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "core/error.h"
#include "core/json_eigen.h"
#include "core/mesh/surface_embedding.h"
#include "core/scenario/procedure.h"
#include "core/scenario/scenario_json.h"
#include "core/sha256.h"
#include "simulator/session/simulation_check.h"
#include "simulator/session/tissue_follow.h"
#include "simulator/session/urethra_tissue.h"
#include "simulator/session/world_tissue.h"

namespace viscera::sim {

struct SessionRunner::Monitor {
  TaskMonitor task;
  int step = -1;  ///< procedure step index, −1 for loose tasks
};

namespace {

double wall_clock() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

/// The landmarks of a scenario by id. Read through the scenario's JSON, so the session works
/// with any scenario that carries them ("landmarks": [{"id", "position", "normal"}, …]).
std::map<std::string, TaskTarget> landmarks_of(const core::Scenario& scenario) {
  std::map<std::string, TaskTarget> out;
  const nlohmann::json json = core::scenario_to_json(scenario);
  for (const auto& mark : json.value("landmarks", nlohmann::json::array())) {
    TaskTarget target;
    target.position = mark.at("position").get<core::Vec3>();
    if (mark.contains("normal")) target.normal = mark["normal"].get<core::Vec3>();
    target.object = mark.value("object", std::string());
    out[mark.at("id").get<std::string>()] = target;
  }
  return out;
}

/// The tissue under the instrument: the urethra lattice named by `instrument_body` (or the first
/// one when the scenario has no World body), else the named (or first) World body.
std::unique_ptr<InstrumentTissue> make_tissue(const core::Scenario& scenario, World& world,
                                              const HeadlessRunOptions& options,
                                              const InstrumentState& start,
                                              double perforation_depth) {
  for (const auto& lattice : scenario.urethra_lattices) {
    if (lattice.object == options.instrument_body ||
        (options.instrument_body.empty() && world.bodies().empty()))
      return std::make_unique<UrethraTissue>(lattice, start);
  }
  for (std::size_t b = 0; b < world.bodies().size(); ++b) {
    if (options.instrument_body.empty() || world.bodies()[b].name() == options.instrument_body) {
      return std::make_unique<WorldTissue>(world, static_cast<int>(b), options.instrument_stiffness,
                                           start.tip, perforation_depth);
    }
  }
  throw core::InputError("the scenario has no simulated object \"" + options.instrument_body +
                         "\" for the instrument");
}

bool needs_target(const std::string& kind) {
  return kind == "reach" || kind == "centre-target" || kind == "withdraw";
}

/// Tasks of the laparoscopic tools judge a site: a landmark, or a named object.
bool needs_site(const core::TaskSpec& task) {
  const bool tool = task.kind == "grasp" || task.kind == "pull" || task.kind == "clip" ||
                    task.kind == "coagulate" || task.kind == "cut";
  return tool && !(task.parameters.is_object() && task.parameters.contains("object"));
}

}  // namespace

SessionRunner::SessionRunner(const core::Scenario& scenario, const HeadlessRunOptions& options)
    : scenario_(scenario),
      options_(options),
      world_(scenario),
      instrument_(scenario.session.instrument) {
  if (!(options.duration > 0.0)) throw core::UsageError("session duration must be positive");
  world_.set_sleep_threshold(options.sleep_threshold);
  started_wall_clock_ = wall_clock();
  time_limit_ = std::min(options.duration, scenario.session.duration_limit);
  force_warning_ =
      options.force_warning > 0.0 ? options.force_warning : scenario.session.force_warning;
  perforation_depth_ = options.perforation_depth > 0.0 ? options.perforation_depth
                                                       : scenario.session.perforation_depth;
  report_.package = options.package;
  report_.procedure = scenario.session.procedure_definition;
  report_.instrument = instrument_.kind;
  report_.time_step = world_.time_step();
  report_.time_limit = time_limit_;
  report_.force_warning = force_warning_;
  total_steps_ = static_cast<long long>(std::llround(time_limit_ / world_.time_step()));
  sample_every_ =
      std::max<long long>(1, std::llround(options.sample_interval / world_.time_step()));
  look_every_ = std::max<long long>(1, std::llround(options.camera_interval / world_.time_step()));

  std::string surface_object;
  if (options.instrument != nullptr) {
    state_ = input_ = options.instrument->state(0, 0.0);
    tissue_ = make_tissue(scenario, world_, options, state_, perforation_depth_);
    if (options.record_inputs) report_.inputs.emplace_back(0, state_);
    report_.metrics.start_at(state_.tip);
    report_.has_instrument = true;
    if (scenario.fluid.enabled) fluid_.emplace(scenario.fluid);
    if (tissue_->body() != nullptr) surface_object = tissue_->name();
    if (scenario.session.instrument.kind == "resectoscope") start_resection(scenario);
    if (scenario.session.instrument.kind == "laparoscope") {
      start_tools(scenario);
      irrigation_ = std::make_unique<SuctionIrrigation>(world_);
    }
    if (fluid_) start_cavity_flow(scenario);
    if (resection_) start_tears(resection_->bodies());
    if (tools_) start_tears(tools_->bodies());
  }
  if (options.settle) {
    const World::Settling settling = world_.settle();
    report_.settle_steps = settling.steps;
    report_.settled_at_rest = settling.at_rest;
  }

  // The camera observes the surface the instrument works in, restricted to the region the
  // first inspect-surface task on it names.
  std::string region_problem, attribute;
  double value = 1.0;
  if (!surface_object.empty()) {
    const core::SceneObject* object = scenario.find_object(surface_object);
    for (const core::TaskSpec* task : core::all_tasks(scenario.session)) {
      if (task->kind == "inspect-surface" &&
          task->parameters.value("object", surface_object) == surface_object) {
        attribute = task->parameters.value("region_attribute", std::string());
        value = task->parameters.value("region_value", 1.0);
        break;
      }
    }
    core::SurfaceMesh surface;
    if (object != nullptr && !object->surface.triangles.empty()) {
      surface = object->surface;
    } else {
      surface.vertices.assign(tissue_->body()->positions().begin(),
                              tissue_->body()->positions().end());
      surface.triangles = tissue_->body()->surface_faces();
    }
    try {
      coverage_ = std::make_unique<SurfaceCoverage>(surface, attribute, value);
    } catch (const core::InputError& e) {
      region_problem = e.reason();
      coverage_ = std::make_unique<SurfaceCoverage>(surface);
    }
  }

  // Task monitors: loose tasks first, then the procedure's, step by step.
  const auto landmarks = landmarks_of(scenario);
  const auto make_monitor = [&](const core::TaskSpec& task, int step, const std::string& step_id,
                                const std::string& substep_id) {
    std::optional<TaskTarget> target;
    std::string missing;
    if (task.parameters.contains("position")) {
      TaskTarget t;
      t.position = task.parameters["position"].get<core::Vec3>();
      if (task.parameters.contains("normal"))
        t.normal = task.parameters["normal"].get<core::Vec3>();
      target = t;
    } else if (task.parameters.contains("landmark")) {
      const std::string id = task.parameters["landmark"].get<std::string>();
      if (const auto it = landmarks.find(id); it != landmarks.end()) {
        target = it->second;
      } else if (needs_target(task.kind) || needs_site(task)) {
        missing = "the scenario has no landmark \"" + id + "\"";
      }
    } else if (needs_target(task.kind) || needs_site(task)) {
      missing = "the task names neither a landmark nor a position";
    }
    if (task.kind == "inspect-surface") {
      if (coverage_ == nullptr)
        missing = "the session has no instrument camera to inspect with";
      else if (task.parameters.value("object", surface_object) != surface_object)
        missing =
            "only the surface the instrument works in (\"" + surface_object + "\") is observed";
      else if (!region_problem.empty())
        missing = region_problem;
      else if (task.parameters.value("region_attribute", std::string()) != attribute ||
               task.parameters.value("region_value", 1.0) != value)
        missing =
            "only one region of the surface is observed, that of the first inspect-surface "
            "task (\"" +
            attribute + "\" = " + std::to_string(value) + ")";
    }
    if ((task.kind == "touch" || task.kind == "centre-target" || task.kind == "reach" ||
         task.kind == "withdraw" || task.kind == "resect") &&
        options.instrument == nullptr && missing.empty()) {
      missing = "the session has no instrument";
    }
    if (task.kind == "resect" && missing.empty()) {
      const auto named =
          task.parameters.is_object() ? task.parameters.find("object") : task.parameters.end();
      const std::string object =
          named != task.parameters.end() && named->is_string() ? named->get<std::string>() : "";
      if (resection_ == nullptr)
        missing = "needs a resectoscope's loop; the session's instrument is a " + instrument_.kind;
      else if (report_.cutting->find(object) == nullptr)
        missing = "names \"" + object + "\", which is not a pathology body the loop can cut";
    }
    monitors_.push_back({TaskMonitor(task, step_id, substep_id, target, missing, instrument_.kind,
                                     tools_ != nullptr),
                         step});
  };
  for (const auto& task : scenario.session.tasks)
    make_monitor(task, -1, "", "");
  for (std::size_t s = 0; s < scenario.session.steps.size(); ++s) {
    const auto& step = scenario.session.steps[s];
    report_.procedure_steps.push_back({step.id, step.name, -1.0, -1.0, {}, std::nullopt, ""});
    for (const auto& substep : step.substeps) {
      for (const auto& task : substep.tasks)
        make_monitor(task, static_cast<int>(s), step.id, substep.id);
    }
  }
  if (!report_.procedure_steps.empty()) open_step(0);
  sample();
  if (coverage_ != nullptr && options.instrument != nullptr) look();
}

SessionRunner::~SessionRunner() = default;

void SessionRunner::open_step(int index) {
  current_ = index;
  StepResult& step = report_.procedure_steps[static_cast<std::size_t>(index)];
  step.started_at = world_.time();
  step.metrics.start_at(state_.tip);
  step.metrics.set_coverage(coverage_ ? coverage_->fraction_seen() : 0.0,
                            coverage_ ? coverage_->fraction_seen() : 0.0);
  report_.events.push_back(
      {world_.time(), "step-started", step.name.empty() ? step.id : step.name});
}

void SessionRunner::close_step(int index) {
  StepResult& step = report_.procedure_steps[static_cast<std::size_t>(index)];
  if (step.started_at < 0.0 || step.ended_at >= 0.0) return;
  step.ended_at = world_.time();
  int completed = 0, available = 0;
  for (const auto& m : monitors_) {
    if (m.step != index) continue;
    if (m.task.result().status != "unavailable") ++available;
    if (m.task.result().status == "completed") ++completed;
  }
  step.metrics.set_tasks(completed, available);
  const PeriodScore score = period_score(step.metrics, force_warning_, resection_share(index));
  step.score = score.value;
  step.score_reason = score.reason;
}

void SessionRunner::advance_steps() {
  const int count = static_cast<int>(report_.procedure_steps.size());
  while (current_ >= 0 && current_ < count) {
    // A step is done when every task of it that can be assessed is completed; a task that
    // cannot be assessed never counts as done, so a step with none never completes by itself
    // (a later step's completed task still moves the session on).
    bool all_done = true, later_completed = false;
    int assessable = 0;
    for (const auto& m : monitors_) {
      const std::string& status = m.task.result().status;
      if (m.step == current_ && status != "unavailable") {
        ++assessable;
        if (status != "completed") all_done = false;
      }
      if (m.step > current_ && status == "completed") later_completed = true;
    }
    if ((!all_done || assessable == 0) && !later_completed) return;
    const double seen = coverage_ ? coverage_->fraction_seen() : 0.0;
    auto& metrics = report_.procedure_steps[static_cast<std::size_t>(current_)].metrics;
    metrics.set_coverage(metrics.coverage_start(), seen);
    close_step(current_);
    if (current_ + 1 >= count) {
      current_ = count;  // past the last step
      // Complete only when every task was assessable: a procedure with a task this runtime
      // cannot judge is never reported as completed; the session runs on to its end.
      int unassessable = 0;
      for (const auto& m : monitors_)
        if (m.step >= 0 && m.task.result().status == "unavailable") ++unassessable;
      if (unassessable > 0) {
        report_.events.push_back(
            {world_.time(), "procedure-unassessable",
             "every task that can be assessed is done, but " + std::to_string(unassessable) +
                 " cannot be assessed by this runtime, so the procedure is not complete"});
      } else if (options_.end_when_complete) {
        end("completed", "every step of the procedure is done");
      }
      return;
    }
    open_step(current_ + 1);
  }
}

std::string SessionRunner::state_hash() const {
  const std::string own = tissue_ ? tissue_->state_hash() : std::string();
  return own.empty() ? world_.state_hash() : core::sha256_hex(world_.state_hash() + own);
}

void SessionRunner::step(const InstrumentState& input) {
  if (finished_) return;
  const bool has_instrument = options_.instrument != nullptr;
  if (has_instrument) {
    if (options_.record_inputs && !(input == input_))
      report_.inputs.emplace_back(world_.steps() + 1, input);
    if (!(input == input_)) instrument_moved_ = true;
    input_ = input;
    state_ = followed(input, world_.bodies(), tissue_->body());
    move_tissue();
    move_second_port();
  }
  step_world();
  const double now = world_.time();
  if (resection_ != nullptr) {
    resection_->follow(state_, world_, now, *report_.cutting, report_.events);
    retrieval_->follow(state_, world_, *resection_, now, *report_.cutting, report_.events);
    gauge_wall_cut(now);
    if (state_.coagulation) coagulate(now);
  }
  if (tools_) follow_tools(now);
  if (tears_) tears_->follow(world_, now, report_.events);
  if (has_instrument) {
    const core::Vec3 force = instrument_force();
    const bool contact = tissue_->in_contact();
    const double dt = world_.time_step();
    report_.metrics.record(state_.tip, force, contact, dt, state_.inflow);
    balance_fluid(dt);
    flow_cavity(dt);
    if (current_ >= 0 && current_ < static_cast<int>(report_.procedure_steps.size())) {
      report_.procedure_steps[static_cast<std::size_t>(current_)].metrics.record(
          state_.tip, force, contact, dt, state_.inflow);
    }
    for (const TissueEvent& warning : tissue_->warnings())
      report_.events.push_back({now, warning.kind, warning.message});
    if (const auto complication = tissue_->complication())
      end(complication->kind, complication->message);
    const bool excessive = force_warning_ > 0.0 && force.norm() > force_warning_;
    if (excessive && !over_force_) {
      report_.events.push_back({now, "excessive-force",
                                "force " + std::to_string(force.norm()) + " N above the " +
                                    std::to_string(force_warning_) + " N warning level"});
    }
    over_force_ = excessive;
  }
  if (irrigation_) irrigate(world_.time_step());
  const long long s = world_.steps();
  if (options_.checkpoint_interval > 0 && s % options_.checkpoint_interval == 0) {
    const long long index = s / options_.checkpoint_interval;
    if (checkpoint_series_.due(index))  // the hash is only worth computing when it is kept
      checkpoint_series_.offer(report_.checkpoints, index, {s, state_hash()});
  }
  if (coverage_ != nullptr && has_instrument && s % look_every_ == 0) look();
  if (s % sample_every_ == 0 || s >= total_steps_ || finished_) sample();
  if (!finished_ && has_instrument && state_.abort) end("abort", "the trainee ended the session");
  if (!finished_ && s >= total_steps_) {
    const bool limit = time_limit_ < options_.duration;
    end(limit ? "time-limit" : "duration",
        limit ? "the procedure's time limit of " + std::to_string(time_limit_) + " s is reached"
              : "end of the session");
  }
}

std::optional<double> SessionRunner::resection_share(int step) const {
  if (!report_.cutting) return std::nullopt;
  double sum = 0.0;
  int tasks = 0;
  for (const auto& m : monitors_) {
    const core::TaskSpec& task = m.task.spec();
    if (task.kind != "resect" || (step != -2 && m.step != step)) continue;
    if (!task.parameters.is_object()) continue;
    const auto o = task.parameters.find("object"), f = task.parameters.find("fraction");
    const std::string object =
        o != task.parameters.end() && o->is_string() ? o->get<std::string>() : "";
    const double required = f != task.parameters.end() && f->is_number() ? f->get<double>() : 0.9;
    if (const BodyResection* b = report_.cutting->find(object))
      sum += std::min(1.0, b->resected_fraction() / std::max(required, 1e-9));
    ++tasks;
  }
  if (tasks == 0) return std::nullopt;
  return sum / tasks;
}

void SessionRunner::step_world() {
  try {
    world_.step();
  } catch (const core::SimulationError&) {
    throw;
  } catch (const core::Error& e) {
    // Whatever the physics reported, the state says where it went wrong.
    const long long step = world_.steps() + 1;
    const double time = static_cast<double>(step) * world_.time_step();
    if (const auto fault = find_state_fault(world_)) throw simulation_error(*fault, step, time);
    throw simulation_error(e.reason(), tissue_ != nullptr ? tissue_->name() : std::string(), step,
                           time);
  }
}

void SessionRunner::look() {
  const BodyView& body = *tissue_->body();
  const core::SceneObject* object = scenario_.find_object(body.name());
  if (body.max_displacement() > 1e-6) {
    if (object != nullptr && !object->surface.triangles.empty()) {
      if (!object->embedding.empty()) {
        coverage_->refit(
            core::embedded_positions(object->embedding, object->body.tets, body.positions()));
      }
    } else {
      coverage_->refit(body.positions());
    }
  }
  const CameraSample sample = coverage_->observe(camera_pose(state_), instrument_);
  last_view_distance_ = sample.centre_distance;
  const bool good = sample.centre_distance >= instrument_.min_view_distance &&
                    sample.centre_distance <= instrument_.max_view_distance &&
                    !tissue_->in_contact();
  const double dt = options_.camera_interval;
  report_.metrics.record_view(good, dt);
  if (current_ >= 0 && current_ < static_cast<int>(report_.procedure_steps.size())) {
    report_.procedure_steps[static_cast<std::size_t>(current_)].metrics.record_view(good, dt);
  }
}

void SessionRunner::sample() {
  const BodyEnergies e = world_.energies();
  if (!std::isfinite(e.kinetic + e.elastic + e.gravitational)) {
    // A state gone non-finite without an error from the world: name it here.
    if (const auto fault = find_state_fault(world_))
      throw simulation_error(*fault, world_.steps(), world_.time());
    throw simulation_error("the bodies' energy is not finite",
                           tissue_ != nullptr ? tissue_->name() : std::string(), world_.steps(),
                           world_.time());
  }
  double displacement = 0.0;
  for (const auto& body : world_.bodies())
    displacement = std::max(displacement, body.max_displacement());
  const long long index = world_.steps() / sample_every_;
  const bool last = finished_ || world_.steps() >= total_steps_;
  energy_series_.offer(report_.samples, index,
                       {world_.time(), e.kinetic, e.elastic, e.gravitational, displacement,
                        world_.contacts().colliding_points, world_.contacts().max_penetration},
                       last);
  report_.max_displacement = std::max(report_.max_displacement, displacement);
  if (fluid_ && (last || fluid_series_.due(index))) {
    const FluidTotals& f = fluid_->totals();
    fluid_series_.offer(report_.fluid_series, index,
                        {world_.time(), fluid_->pressure(), f.deficit(), f.bled, f.intravasated},
                        last);
  }
  const bool has_instrument = options_.instrument != nullptr;
  if (has_instrument && (last || path_series_.due(index))) {
    PathSample p;
    p.time = world_.time();
    p.tip = state_.tip;
    p.force = instrument_force().norm();
    p.in_contact = tissue_->in_contact();
    p.step = current_ < static_cast<int>(report_.procedure_steps.size()) ? current_ : -1;
    if (coverage_ != nullptr) p.wall_distance = coverage_->bvh().nearest(state_.tip).distance;
    path_series_.offer(report_.path, index, p, last);
  }
  TaskContext context;
  context.time = world_.time();
  context.state = state_;
  const InstrumentState optics = camera_pose(state_);
  context.eye = optics.tip;
  context.view = view_direction(optics, instrument_.optics_angle);
  context.in_contact = tissue_ != nullptr && tissue_->in_contact();
  if (context.in_contact) context.contact_object = tissue_->name();
  context.force = instrument_force().norm();
  context.kinetic_energy = e.kinetic;
  context.camera = coverage_.get();
  context.fraction_seen = coverage_ ? coverage_->fraction_seen() : 0.0;
  context.instrument_moved = instrument_moved_;
  context.cutting = report_.cutting ? &*report_.cutting : nullptr;
  if (tools_) {
    context.laparoscopy = &*report_.laparoscopy;
    // What a grasper holds: the working port's, or else the second port's.
    for (int port = 0; port < kInstrumentPorts && context.grasped_rest.empty(); ++port)
      for (const NodeReference& r : tools_->grasp(port).held()) {
        context.grasped_object = world_.models()[static_cast<std::size_t>(r.body)]->name;
        context.grasped_rest.push_back(r.rest);
      }
    context.grasp_stretch = tools_->grasp_stretch(world_);
  }
  for (auto& m : monitors_) {
    const bool watched = m.step < 0 || m.step == current_ || m.step == current_ + 1;
    if (!watched || m.task.done()) continue;
    m.task.update(context);
    if (m.task.result().status != "completed") continue;
    const TaskResult& r = m.task.result();
    report_.events.push_back({r.completed_at, "task-completed", r.name.empty() ? r.id : r.name});
    report_.metrics.add_milestone(r.completed_tip);
    if (m.step >= 0)
      report_.procedure_steps[static_cast<std::size_t>(std::min(m.step, std::max(current_, 0)))]
          .metrics.add_milestone(r.completed_tip);
  }
  if (!finished_) advance_steps();
}

void SessionRunner::end(const std::string& reason, const std::string& message) {
  if (finished_) return;
  finished_ = true;
  report_.end_reason = reason;
  if (reason != "duration" && reason != "completed")
    report_.events.push_back({world_.time(), reason, message});
}

SessionReport SessionRunner::finish() {
  if (current_ >= 0 && current_ < static_cast<int>(report_.procedure_steps.size())) {
    auto& metrics = report_.procedure_steps[static_cast<std::size_t>(current_)].metrics;
    const double seen = coverage_ ? coverage_->fraction_seen() : 0.0;
    metrics.set_coverage(metrics.coverage_start(), seen);
    close_step(current_);
  }
  report_.tasks.clear();
  int completed = 0, available = 0;
  for (const auto& m : monitors_) {
    report_.tasks.push_back(m.task.result());
    if (m.task.result().status != "unavailable") ++available;
    if (m.task.result().status == "completed") ++completed;
  }
  report_.metrics.set_coverage(0.0, coverage_ ? coverage_->fraction_seen() : 0.0);
  report_.metrics.set_tasks(completed, available);
  if (options_.instrument == nullptr) {
    report_.score.reset();
    report_.score_reason =
        "the session has no instrument, so nothing of a trainee's work can be assessed";
  } else {
    const PeriodScore score = period_score(report_.metrics, force_warning_, resection_share(-2));
    report_.score = score.value;
    report_.score_reason = score.reason;
  }
  for (StepResult& step : report_.procedure_steps) {
    if (step.started_at >= 0.0) continue;
    step.score.reset();
    step.score_reason = "the session ended before this step began";
  }
  report_.steps = world_.steps();
  report_.substeps = world_.substeps();  // after attach_instrument, whose spring may add some
  report_.simulated_time = world_.time();
  report_.final_state_hash = state_hash();
  if (fluid_) {
    report_.fluid = fluid_->totals();
    report_.final_cavity_pressure = fluid_->pressure();
  }
  if (bleeding_) report_.bleeding = bleeding_->sources();
  if (cavity_) {
    CavityFlowSummary& f = *report_.cavity_flow;
    f.flow_steps = cavity_->flow_steps();
    f.relabellings = cavity_->relabellings();
    f.mean_pressure_iterations =
        f.flow_steps > 0 ? static_cast<double>(pressure_iterations_) / f.flow_steps : 0.0;
    f.blood_released = cavity_->released_blood();
    f.blood_in_cavity = cavity_->particles().carried_volume() +
                        cavity_->particles().pending_volume() +
                        cavity_->blood().total_volume(cavity_->grid());
    f.blood_drained = cavity_->blood().drained_volume();
    f.blood_lost = cavity_->particles().lost_volume();
    f.particles = static_cast<int>(cavity_->particles().size());
    f.air_bubbles_admitted = cavity_->bubbles().admitted();
    f.air_bubbles_flushed = cavity_->bubbles().flushed();
    f.air_bubbles_at_end = static_cast<int>(cavity_->bubbles().size());
    f.debris_released = cavity_->debris().admitted();
    f.debris_flushed = cavity_->debris().flushed();
    f.debris_at_end = static_cast<int>(cavity_->debris().size());
  }
  report_.max_penetration = world_.max_penetration();
  report_.contact_stiffness =
      world_.bodies().size() > 1 ? scenario_.session.contact_stiffness : 0.0;
  report_.bodies.clear();
  for (const auto& body : world_.bodies()) {
    BodySummary summary;
    summary.name = body.name();
    summary.nodes = body.node_count();
    summary.edges = body.edge_count();
    summary.tets = body.tets().size();
    summary.surface_triangles = body.surface_faces().size();
    summary.max_displacement = body.max_displacement();
    const core::Vec3 down = world_.gravity().norm() > 0.0
                                ? core::Vec3(world_.gravity().normalized())
                                : core::Vec3::Zero();
    summary.centre_of_mass_drop = down.dot(body.centre_of_mass() - body.rest_centre_of_mass());
    report_.bodies.push_back(summary);
  }
  report_.wall_time = wall_clock() - started_wall_clock_;
  return report_;
}

}  // namespace viscera::sim
