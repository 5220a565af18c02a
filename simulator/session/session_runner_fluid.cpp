// The session runner's operative part: the resectoscope's loop on the pathology bodies, the
// bleeding its cuts start, the coagulation pedal, and the distension-fluid balance that carries
// both (issue 17 §4, issue 18 §3-4). The rest of SessionRunner is in session_runner.cpp.
#include <cstdio>
#include <string>
#include <vector>

#include "simulator/session/session_runner.h"

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

  bleeding_.emplace();
  report_.bleeding.emplace();
  hosted_trees_.assign(world_.models().size(), {});
  for (const core::VesselTree& tree : scenario.vessel_trees) {
    for (const auto& model : world_.models()) {
      if (model->name == tree.host_object)
        hosted_trees_[static_cast<std::size_t>(model->body)].push_back(tree);
    }
  }
  resection_->on_cut([this](int body, const cutting::TopologyChange& change, double time) {
    start_bleeding(body, change, time);
  });
}

void SessionRunner::start_bleeding(int body, const cutting::TopologyChange& change, double time) {
  std::vector<core::Triangle> cut_triangles;
  cut_triangles.reserve(change.cut_surface_faces.size());
  for (const int f : change.cut_surface_faces)
    cut_triangles.push_back(change.mesh.surface_faces[static_cast<std::size_t>(f)]);
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
  if (bleeding) bleeding_->record_step(fluid_->last_step_volumes());
  const double used = fluid_->totals().used - used_before;
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

}  // namespace viscera::sim
