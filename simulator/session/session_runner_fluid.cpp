// The session runner's operative part: the resectoscope's loop on the pathology bodies, the
// bleeding its cuts start, the coagulation pedal, and the distension-fluid balance that carries
// both (issue 17 §4, issue 18 §3-4), and the hydrometra the balance's pressure distends
// (issue 18 §1). The rest of SessionRunner is in session_runner.cpp.
#include <algorithm>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "core/mesh/surface_embedding.h"
#include "simulator/dynamics/fluid_drag.h"
#include "simulator/dynamics/pulse_waves.h"
#include "simulator/session/chip_drift.h"
#include "simulator/session/manual_control.h"
#include "simulator/session/session_runner.h"
#include "simulator/session/severed_pieces.h"

namespace viscera::sim {

void SessionRunner::start_resection(const core::Scenario& scenario) {
  std::vector<int> bodies;
  for (const auto& model : world_.models()) {
    const core::SceneObject* object = scenario.find_object(model->name);
    if (object != nullptr && object->role == core::ObjectRole::Pathology &&
        model->kind == BodyModelKind::Teschner && !model->mesh.tets.empty())
      bodies.push_back(model->body);
  }
  resection_ =
      std::make_unique<LoopResection>(world_, std::move(bodies), standard_resection_loop());
  report_.cutting.emplace();
  resection_->begin(world_, *report_.cutting);
  retrieval_ = std::make_unique<ChipRetrieval>(
      world_, starting_pose(scenario, scenario.session.instrument.optics_angle));
  for (const auto& model : world_.models()) {
    const core::SceneObject* object = scenario.find_object(model->name);
    if (object == nullptr || model->kind != BodyModelKind::Teschner) continue;
    CavitySurface cavity = cavity_surface(*object);
    if (cavity.empty()) continue;
    wall_gauge_ = std::make_unique<WallCutGauge>(model->body, std::move(cavity));
    report_.cutting->healthy_wall_removed = 0.0;
    break;
  }
  if (!visible_) visible_ = std::make_unique<VisibleSurfaces>(scenario, world_);
  resection_->cut_visible_surfaces(visible_.get());

  start_bleeding_sources(scenario);
  resection_->on_cut([this](int body, const cutting::TopologyChange& change, double time) {
    start_bleeding(body, change, time);
    cut_since_flow_ = true;
  });
}

void SessionRunner::gauge_wall_cut(double time) {
  CuttingSummary& cutting = *report_.cutting;
  if (wall_gauge_ == nullptr || cutting.sweeps == gauged_sweeps_) return;
  gauged_sweeps_ = cutting.sweeps;
  const auto cut = wall_gauge_->measure(world_, resection_->last_sweep());
  if (!cut) return;
  *cutting.healthy_wall_removed += cut->removed_volume;
  const bool deeper = !cutting.deepest_wall_cut || cut->perforated ||
                      cut->depth / cut->thickness >
                          *cutting.deepest_wall_cut / *cutting.wall_thickness_at_deepest_cut;
  if (deeper) {
    cutting.deepest_wall_cut = cut->depth;
    cutting.wall_thickness_at_deepest_cut = cut->thickness;
  }
  char text[160];
  std::snprintf(text, sizeof text, "the loop cut %.1f mm into the wall, %.0f %% of its %.1f mm",
                1e3 * cut->depth, 100.0 * cut->depth / cut->thickness, 1e3 * cut->thickness);
  if (cut->perforated) {
    std::snprintf(text, sizeof text, "the loop cut through the wall, %.1f mm thick there",
                  1e3 * cut->thickness);
    end("perforation", text);
    return;
  }
  report_.events.push_back({time, "wall-cut", text});
}

void SessionRunner::start_bleeding_sources(const core::Scenario& scenario) {
  bleeding_.emplace();
  report_.bleeding.emplace();
  hosted_trees_.assign(world_.models().size(), {});
  for (const core::VesselTree& tree : scenario.vessel_trees) {
    for (const auto& model : world_.models()) {
      if (model->name == tree.host_object)
        hosted_trees_[static_cast<std::size_t>(model->body)].push_back(tree);
    }
  }
}

void SessionRunner::start_bleeding(int body, const cutting::TopologyChange& change, double time) {
  // Blood comes from the side still fed by the patient: the cut faces of a piece cut off from
  // every hold (a loop's chip, a scissors' free fragment) do not bleed.
  const std::vector<std::uint8_t> excised =
      severed_nodes(change.mesh, world_.held_nodes(body),
                    resection_ != nullptr && resection_->lost_every_hold(world_, body));
  std::vector<core::Triangle> cut_triangles;
  cut_triangles.reserve(change.cut_surface_faces.size());
  for (const int f : change.cut_surface_faces) {
    const core::Triangle& t = change.mesh.surface_faces[static_cast<std::size_t>(f)];
    if (excised[static_cast<std::size_t>(t[0])] == 0) cut_triangles.push_back(t);
  }
  const std::size_t before = bleeding_->sources().size();
  bleeding_->add_cut(body, hosted_trees_[static_cast<std::size_t>(body)], change.mesh.nodes,
                     cut_triangles, time);
  const std::string& name = world_.models()[static_cast<std::size_t>(body)]->name;
  for (std::size_t i = before; i < bleeding_->sources().size(); ++i) {
    const fluid::BleedingSource& source = bleeding_->sources()[i];
    if (source.capillary) continue;
    char radius[32];
    std::snprintf(radius, sizeof radius, "%.2f", source.radius * 1e3);
    report_.events.push_back({time, "vessel-opened",
                              "the cut through " + name + " opened segment " +
                                  std::to_string(source.segment) + " of vessel tree \"" +
                                  source.vessel_tree + "\" (radius " + radius + " mm, " +
                                  std::to_string(source.level) + " bifurcation(s) from its root)"});
  }
}

void SessionRunner::coagulate(double time) {
  if (!bleeding_ || bleeding_->sources().empty()) return;
  // Coagulating current seals tissue about 1.5 mm around the wire (a stated choice: monopolar
  // loops coagulate 1-2 mm deep); the wire is the loop's sampled points.
  constexpr double kReach = 1.5e-3;
  std::vector<core::Vec3> sites;
  sites.reserve(bleeding_->sources().size());
  for (const fluid::BleedingSource& source : bleeding_->sources())
    sites.push_back(
        fluid::site_position(source, world_.state().range(world_.state().positions, source.body)));
  int sealed = 0;
  for (const core::Vec3& wire : cutting::loop_points(resection_->loop(), loop_pose(state_)))
    sealed += bleeding_->coagulate(wire, kReach, sites, time);
  if (sealed > 0) {
    report_.events.push_back(
        {time, "coagulated",
         "the loop coagulated " + std::to_string(sealed) + " bleeding source(s)"});
    stop_pulse_at_sealed_vessels(time);
  }
}

void SessionRunner::stop_pulse_at_sealed_vessels(double time) {
  // A coagulated vessel is closed: its pulse wave stops there (issue 19 §1, seed 001 §5.1.2).
  for (const fluid::BleedingSource& source : bleeding_->sources()) {
    if (source.capillary || source.stop != fluid::BleedingStop::Coagulated ||
        source.stopped_at != time)
      continue;
    const core::Vec3 rest_site = fluid::site_position(
        source, world_.state().range(world_.state().rest_positions, source.body));
    for (const auto& term : world_.terms()) {
      auto* pulse = dynamic_cast<PulseWaves*>(term.get());
      if (pulse == nullptr || pulse->vessel_tree() != source.vessel_tree) continue;
      pulse->occlude_at(source.segment, rest_site);
      report_.events.push_back({time, "pulse-stopped",
                                "the pulse of vessel tree \"" + source.vessel_tree +
                                    "\" stops at coagulated segment " +
                                    std::to_string(source.segment)});
    }
  }
}

void SessionRunner::balance_fluid(double dt) {
  const bool bleeding = bleeding_ && !bleeding_->sources().empty();
  if (!fluid_) {
    // No distension fluid (an open cavity): every source bleeds against no pressure.
    if (bleeding) {
      std::vector<double> volumes;
      for (const VesselOpening& opening : bleeding_->openings(world_.time()))
        volumes.push_back(opening.conductance * opening.pressure * dt);
      bleeding_->record_step(volumes);
    }
    return;
  }
  if (bleeding) fluid_->set_openings(bleeding_->openings(world_.time()));
  const double used_before = fluid_->totals().used;
  fluid_->step(state_.inflow, state_.outflow, dt);
  if (hydrometra_ != nullptr) {
    // The next step interpolates the wall's distended shape at this pressure; a sleeping
    // world wakes once that shape has moved as far as it sleeps below.
    const double moved = hydrometra_->set_pressure(fluid_->pressure());
    if (world_.asleep() && moved > options_.sleep_threshold) world_.wake();
  }
  if (bleeding) bleeding_->record_step(fluid_->last_step_volumes());
  const double used = fluid_->totals().used - used_before;
  inflow_rate_ = used / dt;
  report_.metrics.record_fluid(used);
  if (current_ >= 0 && current_ < static_cast<int>(report_.procedure_steps.size()))
    report_.procedure_steps[static_cast<std::size_t>(current_)].metrics.record_fluid(used);
  if (fluid_->overloaded() && !finished_) {
    end("fluid-overload", "the fluid deficit reached " +
                              std::to_string(fluid_->totals().deficit() * 1e6) +
                              " ml, the overload limit of " +
                              std::to_string(fluid_->fluid().overload_volume * 1e6) + " ml");
  }
}

std::vector<core::Vec3> SessionRunner::cavity_wall() const {
  const auto positions = world_.state().range(world_.state().positions, cavity_body_);
  if (cavity_object_->embedding.empty()) return {positions.begin(), positions.end()};
  return core::embedded_positions(cavity_object_->embedding, cavity_object_->body.tets, positions);
}

void SessionRunner::start_cavity_flow(const core::Scenario& scenario) {
  for (const auto& model : world_.models()) {
    const core::SceneObject* object = scenario.find_object(model->name);
    if (object == nullptr || object->surface.triangles.empty()) continue;
    const auto marks = object->surface.vertex_attributes.find("cavity");
    if (marks == object->surface.vertex_attributes.end()) continue;
    cavity_body_ = model->body;
    cavity_object_ = object;
    if (!object->hydrometra.empty()) {
      // The wall distends with the balance's pressure from the next step on.
      auto term = std::make_unique<HydrometraForces>(model, world_.state(), *object);
      hydrometra_ = term.get();
      world_.add_term(std::move(term));
    }
    fluid::CavityFlowSettings settings;
    settings.sheath_radius = 0.5 * instrument_.shaft_diameter;
    cavity_ = std::make_unique<fluid::CavityFlow>(cavity_wall(), object->surface.triangles,
                                                  marks->second, settings, 0x18f10dull);
    CavityFlowSummary& summary = report_.cavity_flow.emplace();
    summary.cell_size = cavity_->grid().cell_size();
    for (int k = 0; k < cavity_->grid().nz(); ++k)
      for (int j = 0; j < cavity_->grid().ny(); ++j)
        for (int i = 0; i < cavity_->grid().nx(); ++i)
          summary.fluid_cells += cavity_->grid().cell(i, j, k) == fluid::FlowCell::Fluid;
    summary.obscured_threshold = settings.obscured_transmission;
    if (resection_) {
      // The loop's chips drift with the flow (chip_drift.h); its shreds become debris.
      auto drag = std::make_unique<FluidDrag>();
      chip_drag_ = drag.get();
      world_.add_term(std::move(drag));
      resection_->shed_debris_below(kDebrisVolume, [this](const core::Vec3& centre, double radius) {
        pending_debris_.push_back({centre, radius});
      });
    }
    return;
  }
}

void SessionRunner::flow_cavity(double dt) {
  if (!cavity_) return;
  fluid::CavityInputs inputs;
  inputs.sheath = true;
  inputs.tip = state_.tip;
  inputs.axis = state_.axis;
  inputs.inflow_rate = inflow_rate_;
  if (world_.gravity().norm() > 0.0) inputs.up = -world_.gravity().normalized();
  if (bleeding_) {
    const auto& sources = bleeding_->sources();
    bled_seen_.resize(sources.size(), 0.0);
    for (std::size_t i = 0; i < sources.size(); ++i) {
      const fluid::BleedingSource& source = sources[i];
      const double volume = source.bled - bled_seen_[i];
      if (!(volume > 0.0)) continue;
      bled_seen_[i] = source.bled;
      const auto positions = world_.state().range(world_.state().positions, source.body);
      const core::Vec3 a = positions[static_cast<std::size_t>(source.nodes[0])];
      const core::Vec3 b = positions[static_cast<std::size_t>(source.nodes[1])];
      const core::Vec3 c = positions[static_cast<std::size_t>(source.nodes[2])];
      fluid::BloodRelease release;
      release.site = fluid::site_position(source, positions);
      // Out of the tissue: the site's triangle normal, turned away from the body's centre.
      core::Vec3 normal = (b - a).cross(c - a);
      core::Vec3 centre = core::Vec3::Zero();
      for (const core::Vec3& p : positions)
        centre += p;
      centre /= static_cast<double>(positions.size());
      if (normal.dot(release.site - centre) < 0.0) normal = -normal;
      release.normal = normal.norm() > 0.0 ? core::Vec3(normal.normalized()) : core::Vec3::UnitZ();
      // A vessel spurts at its mean speed Q/(πr²) (at most 0.3 m/s); ooze seeps at 5 mm/s.
      const double rate = volume / dt;
      release.speed =
          source.capillary
              ? 0.005
              : std::min(0.3, rate / (std::numbers::pi * source.radius * source.radius));
      release.volume = volume;
      inputs.blood.push_back(release);
    }
  }
  std::vector<core::Vec3> wall;
  if (cavity_->step_due(dt)) {
    wall = cavity_wall();
    inputs.wall = wall;
    for (const auto& model : world_.models()) {
      const core::SceneObject* object = scenario_.find_object(model->name);
      if (object == nullptr || object->role != core::ObjectRole::Pathology ||
          model->surface.empty())
        continue;
      inputs.obstacles.push_back(
          {world_.state().range(world_.state().positions, model->body), &model->surface});
    }
    inputs.obstacles_cut = cut_since_flow_;
    cut_since_flow_ = false;
  }
  inputs.debris.swap(pending_debris_);
  const long long before = cavity_->flow_steps();
  cavity_->advance(dt, inputs);
  if (cavity_->flow_steps() == before) return;
  pressure_iterations_ += cavity_->last_step().pressure_iterations;
  if (chip_drag_ != nullptr && !resection_->chips().empty()) {
    ChipDragSettings drag;
    drag.kinematic_viscosity = cavity_->settings().flow.viscosity;
    chip_drag_->set(chip_drag(resection_->chips(), world_.state(), cavity_->grid(), drag),
                    world_.state());
  }
  CavityFlowSummary& summary = *report_.cavity_flow;
  const double transmission = cavity_->view_transmission(
      camera_pose(state_).tip, view_direction(camera_pose(state_), instrument_.optics_angle));
  summary.lowest_transmission = std::min(summary.lowest_transmission, transmission);
  if (transmission < cavity_->settings().obscured_transmission)
    summary.view_obscured_time += cavity_->settings().interval;
}

}  // namespace viscera::sim
