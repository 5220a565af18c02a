#include "simulator/world/world.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.h"
#include "core/sha256.h"
#include "simulator/dynamics/authored_terms.h"
#include "simulator/dynamics/backward_euler.h"
#include "simulator/dynamics/explicit_verlet.h"
#include "simulator/dynamics/gravity_term.h"
#include "simulator/dynamics/teschner_terms.h"

namespace viscera::sim {

World::World(const core::Scenario& scenario, IntegratorKind integrator)
    : gravity_(scenario.session.gravity), time_step_(scenario.session.time_step) {
  if (!(time_step_ > 0.0))
    throw core::InputError("session time step must be positive",
                           {"", "/scenario/session/time_step", ""});
  bool any_teschner = false;
  for (const auto& object : scenario.objects) {
    if (object.body_kind == core::BodyKind::CellAgent) {  // seed 003 §V: cells as nodes
      models_.push_back(add_cell_agent_body(scenario, object, state_));
      continue;
    }
    if (object.body_kind != core::BodyKind::TetMesh &&
        object.body_kind != core::BodyKind::MassSpring)
      continue;
    core::Material material;
    if (!object.material.empty()) {
      const auto it = scenario.materials.find(object.material);
      if (it == scenario.materials.end()) {
        throw core::InputError("unknown material id \"" + object.material + "\"",
                               {"", "", "object " + object.id});
      }
      material = it->second;
    }
    const core::TetMesh& mesh = object.body;
    core::check_tet_mesh(mesh, "body " + object.id);
    const std::vector<double> mass =
        mesh.node_mass.empty() ? core::lumped_node_masses(mesh, material.density) : mesh.node_mass;
    for (std::size_t i = 0; i < mass.size(); ++i) {
      const bool fixed = !mesh.fixed.empty() && mesh.fixed[i] != 0;
      if (!fixed && !(mass[i] > 0.0))
        throw core::InputError("free node has no positive mass",
                               {"body " + object.id, "", "node " + std::to_string(i)});
    }
    auto model = std::make_shared<BodyModel>();
    model->name = object.id;
    model->kind = object.body_kind == core::BodyKind::MassSpring ? BodyModelKind::KismoMassSpring
                                                                 : BodyModelKind::Teschner;
    any_teschner = any_teschner || model->kind == BodyModelKind::Teschner;
    model->mesh = mesh;
    model->surface =
        mesh.surface_faces.empty() ? core::boundary_faces(mesh.tets) : mesh.surface_faces;
    assign_layer_materials(*model, object, material, scenario.materials);
    model->body = state_.add_body(object.id, mesh.nodes, mass, mesh.fixed);
    models_.push_back(std::move(model));
  }
  contact_stiffness_ = models_.size() > 1 ? scenario.session.contact_stiffness : 0.0;
  build_terms(scenario);
  if (integrator == IntegratorKind::Automatic)
    integrator = any_teschner ? IntegratorKind::BackwardEuler : IntegratorKind::ExplicitVerlet;
  if (integrator == IntegratorKind::BackwardEuler)
    integrator_ = std::make_unique<BackwardEuler>();
  else
    integrator_ = std::make_unique<ExplicitVerlet>();
  integrator_->topology_changed(state_, term_pointers());
  refresh_views();
}

World::~World() = default;

void World::refresh_views() {
  views_.clear();
  for (const auto& m : models_)
    views_.emplace_back(&state_, m.get());
}

std::vector<ForceTerm*> World::term_pointers() const {
  std::vector<ForceTerm*> pointers;
  for (const auto& t : terms_)
    pointers.push_back(t.get());
  return pointers;
}

void World::set_sleep_threshold(double threshold) {
  sleep_threshold_ = threshold;
  if (auto* verlet = dynamic_cast<ExplicitVerlet*>(integrator_.get()))
    verlet->set_sleep_threshold(threshold);
}

void World::wake() {
  asleep_ = false;
  calm_steps_ = 0;
  if (auto* verlet = dynamic_cast<ExplicitVerlet*>(integrator_.get())) verlet->wake();
}

void World::refresh_integrator() const {
  if (!integrator_stale_) return;
  integrator_->topology_changed(state_, term_pointers());
  integrator_stale_ = false;
}

int World::substeps() const {
  refresh_integrator();
  const auto* verlet = dynamic_cast<const ExplicitVerlet*>(integrator_.get());
  return verlet != nullptr ? verlet->substeps(time_step_) : 1;
}

double World::stable_step() const {
  refresh_integrator();
  const auto* verlet = dynamic_cast<const ExplicitVerlet*>(integrator_.get());
  return verlet != nullptr ? verlet->stable_step() : std::numeric_limits<double>::infinity();
}

int World::body_index(const std::string& name) const {
  for (const auto& m : models_)
    if (m->name == name) return m->body;
  return -1;
}

void World::add_term(std::unique_ptr<ForceTerm> term) {
  terms_.push_back(std::move(term));
  integrator_stale_ = true;
}

void World::stiffness_changed(int body) {
  auto* verlet = dynamic_cast<ExplicitVerlet*>(integrator_.get());
  if (verlet != nullptr && body >= 0 && !integrator_stale_)
    verlet->stiffness_changed(state_, term_pointers(), body);
  else
    integrator_->topology_changed(state_, term_pointers());
  integrator_stale_ = false;
  // A term's forces changed: what rested may move.
  asleep_ = false;
  calm_steps_ = 0;
  if (verlet != nullptr) verlet->wake_body(body);
}

bool World::driven() const {
  return std::any_of(terms_.begin(), terms_.end(), [](const auto& t) { return t->drives(); });
}

void World::step() {
  const StepContext context{time(), time_step_, steps_ + 1};
  if (asleep_ && driven()) wake();
  if (asleep_) {
    // Nothing moves until the instrument touches: only the proxy follows the tip.
    if (proxy_ != nullptr) {
      proxy_->prepare(state_, context);
      asleep_ = !proxy_->proxy().in_contact();
    }
    if (asleep_) {
      ++steps_;
      return;
    }
    calm_steps_ = 0;
  }
  refresh_integrator();
  const std::vector<ForceTerm*> terms = term_pointers();
  statistics_ = integrator_->step(state_, terms, context);
  ++steps_;
  check_state();
  if (contact_ != nullptr) {
    contacts_ = contact_->statistics();
    max_penetration_ = std::max(max_penetration_, contacts_.max_penetration);
  }
  if (sleep_threshold_ > 0.0 && !drives_bodies(terms_)) update_sleep();
}

int World::everted_tets() const {
  int count = 0;
  for (const auto& term : terms_) {
    const auto* volume = dynamic_cast<const TeschnerVolumeTerm*>(term.get());
    if (volume == nullptr) continue;
    for (std::size_t t = 0; t < volume->terms().tets.size(); ++t) {
      const auto& n = volume->terms().tets[t];
      const auto& x = state_.positions;
      if (core::signed_volume(x[n[0]], x[n[1]], x[n[2]], x[n[3]]) < -volume->terms().rest_volume[t])
        ++count;
    }
  }
  return count;
}

void World::check_state() const {
  const double t = time();
  for (const auto& m : models_) {
    const BodyNodes& range = state_.body(m->body);
    for (int i = 0; i < range.count; ++i) {
      const auto g = static_cast<std::size_t>(range.first + i);
      if (!state_.positions[g].allFinite() || !state_.velocities[g].allFinite())
        throw core::SimulationError(
            "the simulation became unstable at step " + std::to_string(steps_) +
                " (t = " + std::to_string(t) + " s): node " + std::to_string(i) + " of body \"" +
                m->name + "\" has a non-finite position or velocity",
            m->name, i, steps_,
            "non-finite state (a non-finite input, or a time step too large for the material's "
            "stiffness and damping)");
    }
  }
  if (!inversion_errors_) return;
  for (const auto& term : terms_) {
    const auto* volume = dynamic_cast<const TeschnerVolumeTerm*>(term.get());
    if (volume == nullptr) continue;
    const int tet = volume->first_inverted(state_.positions);
    if (tet >= 0) {
      const auto& nodes = volume->model().mesh.tets[static_cast<std::size_t>(tet)];
      throw core::SimulationError(
          "the simulation became unstable at step " + std::to_string(steps_) +
              " (t = " + std::to_string(t) + " s): tet " + std::to_string(tet) + " of body \"" +
              volume->model().name + "\" turned inside out",
          volume->model().name, nodes[0], steps_,
          "inverted tets (the tool or a contact pressed harder than the material can hold)");
    }
  }
}

void World::update_sleep() {
  double fastest = 0.0;
  for (std::size_t i = 0; i < state_.node_count(); ++i)
    fastest = std::max(fastest, state_.velocities[i].squaredNorm());
  const double moved = std::sqrt(fastest) * time_step_;
  const bool touched = proxy_ != nullptr && proxy_->proxy().in_contact();
  calm_steps_ = moved < sleep_threshold_ && !touched && !driven() ? calm_steps_ + 1 : 0;
  if (calm_steps_ >= kCalmStepsToSleep) {
    // At rest: stop the last sub-nanometre motion so the state stays exactly still.
    for (auto& v : state_.velocities)
      v.setZero();
    asleep_ = true;
  }
}

void World::attach_instrument(int body, double stiffness, const core::Vec3& tip) {
  if (body < 0 || body >= static_cast<int>(models_.size()))
    throw core::UsageError("no body " + std::to_string(body) + " to attach the instrument to");
  if (proxy_ != nullptr) {
    terms_.erase(std::find_if(terms_.begin(), terms_.end(),
                              [&](const auto& t) { return t.get() == proxy_; }));
  }
  std::vector<std::shared_ptr<const BodyModel>> models(models_.begin(), models_.end());
  auto term = std::make_unique<ProxySpringTerm>(std::move(models), stiffness, state_, tip);
  proxy_ = term.get();
  instrument_body_ = body;
  tool_tip_ = tip;
  add_term(std::move(term));
}

void World::set_instrument_tip(const core::Vec3& tip) {
  tool_tip_ = tip;
  if (proxy_ != nullptr) proxy_->set_tip(tip);
}

core::Vec3 World::instrument_force() const {
  return proxy_ != nullptr ? proxy_->proxy().force() : core::Vec3::Zero();
}

bool World::instrument_in_contact() const {
  return proxy_ != nullptr && proxy_->proxy().in_contact();
}

ProxyContact World::instrument_contact() const {
  if (proxy_ == nullptr || !proxy_->proxy().in_contact()) return {};
  return {proxy_->touched_body_triangle(), proxy_->proxy().contact().barycentric};
}

int World::instrument_touched_body() const {
  return proxy_ != nullptr ? proxy_->touched_body() : -1;
}

core::Vec3 World::instrument_proxy() const {
  return proxy_ != nullptr ? proxy_->proxy().proxy() : tool_tip_;
}

BodyEnergies World::energies() const {
  BodyEnergies sum;
  for (std::size_t i = 0; i < state_.node_count(); ++i)
    sum.kinetic += 0.5 * state_.masses[i] * state_.velocities[i].squaredNorm();
  for (const auto& term : terms_) {
    if (term.get() == proxy_) continue;  // the hand's spring is input, not stored energy
    const double e = term->energy(state_.positions);
    if (dynamic_cast<const GravityTerm*>(term.get()) != nullptr)
      sum.gravitational += e;
    else
      sum.elastic += e;
  }
  return sum;
}

std::string World::state_hash() const {
  core::Sha256 hash;
  hash.update(std::as_bytes(std::span<const core::Vec3>(state_.positions)));
  hash.update(std::as_bytes(std::span<const core::Vec3>(state_.velocities)));
  return hash.hex_digest();
}

}  // namespace viscera::sim
