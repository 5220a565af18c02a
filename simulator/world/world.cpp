#include "simulator/world/world.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "core/sha256.h"

namespace viscera::sim {

World::World(const core::Scenario& scenario)
    : gravity_(scenario.session.gravity), time_step_(scenario.session.time_step) {
  if (!(time_step_ > 0.0))
    throw core::InputError("session time step must be positive",
                           {"", "/scenario/session/time_step", ""});
  for (const auto& object : scenario.objects) {
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
    bodies_.emplace_back(object.id, object.body, material,
                         object.body_kind == core::BodyKind::MassSpring ? BodyModel::KismoMassSpring
                                                                        : BodyModel::Teschner);
  }
  contact_stiffness_ = bodies_.size() > 1 ? scenario.session.contact_stiffness : 0.0;
  if (contact_stiffness_ > 0.0)
    contact_ = std::make_unique<ContactResponse>(bodies_, contact_stiffness_);
  connections_ = ConnectionSprings(scenario, bodies_);
  choose_substeps();
}

void World::choose_substeps() {
  // Every surface node may meet a contact; the instrument's proxy spring may press on any
  // surface node of its body (k w wᵀ over a triangle is bounded by k on each of its nodes).
  const auto surface_stiffness = [&](std::size_t b) {
    double k = contact_stiffness_;
    if (instrument_ && static_cast<std::size_t>(instrument_->body) == b)
      k += instrument_->proxy.stiffness();
    return k;
  };
  std::vector<int> offsets;
  std::vector<double> inverse_mass;
  for (const auto& body : bodies_) {
    offsets.push_back(static_cast<int>(inverse_mass.size()));
    inverse_mass.insert(inverse_mass.end(), body.inverse_masses().begin(),
                        body.inverse_masses().end());
  }
  RankOneSystem stiffness(inverse_mass.size()), damping(inverse_mass.size());
  double stable = time_step_;
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    const DeformableBody& body = bodies_[b];
    if (!body.add_linearised_terms(stiffness, damping, offsets[b])) {
      // A KisMo net: its own integrator, its own per-node bound.
      std::vector<double> extra(body.node_count(), 0.0);
      connections_.add_node_stiffness(static_cast<int>(b), extra);
      stable = std::min(stable, body.stable_time_step(surface_stiffness(b), extra));
    }
    const double k = surface_stiffness(b);
    if (k > 0.0) {
      std::vector<char> on_surface(body.node_count(), 0);
      for (const auto& f : body.surface_faces())
        for (const int v : f) on_surface[static_cast<std::size_t>(v)] = 1;
      for (std::size_t i = 0; i < on_surface.size(); ++i)
        if (on_surface[i]) stiffness.add_diagonal(offsets[b] + static_cast<int>(i), k);
    }
  }
  connections_.add_linearised_terms(stiffness, offsets);
  const double omega_squared = largest_eigenvalue(stiffness, inverse_mass);
  const double damping_rate = largest_eigenvalue(damping, inverse_mass);
  stable = std::min(stable, kStableStepSafety * verlet_stable_step(omega_squared, damping_rate));
  stable_step_ = stable;
  substeps_ = std::max(1, static_cast<int>(std::ceil(time_step_ / stable - 1e-12)));
}

void World::step() {
  const double h = time_step_ / substeps_;
  if (asleep_) {
    // Nothing moves until the instrument touches: only the proxy follows the tip.
    if (instrument_) {
      DeformableBody& body = bodies_[static_cast<std::size_t>(instrument_->body)];
      instrument_->proxy.update(tool_tip_, instrument_->surface, body.positions());
      instrument_->proxy.recapture(instrument_->surface, body.positions());
      asleep_ = !instrument_->proxy.in_contact();
    }
    if (asleep_) {
      ++steps_;
      return;
    }
    calm_substeps_ = 0;
  }
  for (int s = 0; s < substeps_; ++s) {
    if (instrument_) {
      DeformableBody& body = bodies_[static_cast<std::size_t>(instrument_->body)];
      instrument_->proxy.update(tool_tip_, instrument_->surface, body.positions());
      // The wall may have swung over the tip since the last sub-step (it overshoots when
      // pushed and springs back): that is a contact the path test alone misses.
      instrument_->proxy.recapture(instrument_->surface, body.positions());
    }
    for (auto& body : bodies_)
      body.compute_forces(gravity_, h);
    connections_.apply(bodies_);
    if (contact_) {
      contacts_ = contact_->apply(bodies_);
      max_penetration_ = std::max(max_penetration_, contacts_.max_penetration);
    }
    if (instrument_) {
      // The instrument presses on the tissue with the opposite of the force it feels.
      DeformableBody& body = bodies_[static_cast<std::size_t>(instrument_->body)];
      if (instrument_->proxy.in_contact()) {
        const auto& contact = instrument_->proxy.contact();
        const auto& triangle =
            instrument_->surface.faces()[static_cast<std::size_t>(contact.triangle)];
        for (const auto& [node, force] :
             distribute_to_triangle(triangle, contact.barycentric, -instrument_->proxy.force())) {
          body.add_force(node, force);
        }
      }
    }
    for (auto& body : bodies_) {
      try {
        body.integrate(h);
      } catch (const core::Error& e) {
        // The body names itself and the node; only the world knows when it happened.
        throw core::Error(e.reason() + " at step " + std::to_string(steps_ + 1) + " (t = " +
                              std::to_string(static_cast<double>(steps_ + 1) * time_step_) + " s)",
                          e.location());
      }
    }
    if (sleep_threshold_ > 0.0) update_sleep();
  }
  ++steps_;
}

void World::update_sleep() {
  double moved = 0.0;
  for (const auto& body : bodies_) {
    const auto& x = body.positions();
    const auto& previous = body.previous_positions();
    for (std::size_t n = 0; n < x.size(); ++n)
      moved = std::max(moved, (x[n] - previous[n]).squaredNorm());
  }
  const bool touched = instrument_ && instrument_->proxy.in_contact();
  calm_substeps_ = std::sqrt(moved) < sleep_threshold_ && !touched ? calm_substeps_ + 1 : 0;
  if (calm_substeps_ >= kCalmSubstepsToSleep) {
    // At rest: stop the last sub-nanometre motion so the state stays exactly still.
    for (auto& body : bodies_)
      body.previous_positions() = body.positions();
    asleep_ = true;
  }
}

void World::attach_instrument(int body, double stiffness, const core::Vec3& tip) {
  if (body < 0 || body >= static_cast<int>(bodies_.size())) {
    throw core::UsageError("no body " + std::to_string(body) + " to attach the instrument to");
  }
  instrument_ = std::make_unique<Instrument>(
      Instrument{body, ProxySurface(bodies_[static_cast<std::size_t>(body)].surface_faces()),
                 HapticProxy(stiffness)});
  instrument_->proxy.reset(tip);
  tool_tip_ = tip;
  choose_substeps();
}

BodyEnergies World::energies() const {
  BodyEnergies sum;
  const double h = time_step_ / substeps_;
  for (const auto& body : bodies_) {
    const BodyEnergies e = body.energies(gravity_, h);
    sum.kinetic += e.kinetic;
    sum.elastic += e.elastic;
    sum.gravitational += e.gravitational;
  }
  sum.elastic += connections_.energy(bodies_);
  return sum;
}

std::string World::state_hash() const {
  core::Sha256 hash;
  const auto add = [&hash](const std::vector<core::Vec3>& points) {
    hash.update(std::as_bytes(std::span<const core::Vec3>(points)));
  };
  for (const auto& body : bodies_) {
    add(body.positions());
    add(body.previous_positions());
  }
  return hash.hex_digest();
}

}  // namespace viscera::sim
