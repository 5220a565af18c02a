#pragma once
/// The simulated world of a scenario: its deformable bodies stepped at a fixed time step
/// (DESIGN.md §5). Single-threaded and in a fixed order, so the same scenario gives the same
/// state bit for bit (the deterministic mode of sessions and replays).

#include <memory>
#include <string>
#include <vector>

#include "core/scenario/scenario.h"
#include "simulator/collision/contact_response.h"
#include "simulator/haptics/haptic_proxy.h"
#include "simulator/physics/connection_springs.h"
#include "simulator/physics/deformable_body.h"

namespace viscera::sim {

/// Bodies, gravity and the clock of one simulation.
class World {
 public:
  /// Builds a body for every object whose body kind is a tet mesh (Teschner energies) or a
  /// mass-spring net (KisMo springs on the mesh edges), with its material (or the
  /// default Material when it names none). The physics step is scenario.session.time_step,
  /// split into equal sub-steps when the bodies need a smaller step to stay stable: the stable
  /// step comes from the largest eigenvalues of the linearised stiffness and damping of all
  /// Teschner bodies, connection springs, contacts and the instrument together
  /// (physics/stable_step.h), times kStableStepSafety; KisMo nets keep their per-node bound. With two or
  /// more bodies, contacts between them get penalty forces of scenario.session.contact_stiffness.
  /// The scenario's connections hold their objects together with springs (ConnectionSprings).
  /// Throws core::InputError for a missing material, an invalid body or a connection that
  /// names an object without a body or a node it does not have.
  explicit World(const core::Scenario& scenario);

  /// Advances by one physics step (time_step() seconds).
  void step();

  double time() const { return static_cast<double>(steps_) * time_step_; }
  long long steps() const { return steps_; }
  double time_step() const { return time_step_; }
  int substeps() const { return substeps_; }
  const core::Vec3& gravity() const { return gravity_; }
  const std::vector<DeformableBody>& bodies() const { return bodies_; }
  std::vector<DeformableBody>& bodies() { return bodies_; }

  /// Puts a haptic instrument into the world: one proxy point on the surface of body `body`
  /// with a proxy–tip spring of `stiffness` N/m (seed 000 §8.2). The tip starts at `tip`.
  /// The spring enters the stable step (on every surface node of the body), so substeps() may grow.
  /// Throws core::UsageError for a body index out of range.
  void attach_instrument(int body, double stiffness, const core::Vec3& tip);
  /// Moves the instrument tip (m); takes effect at the next step.
  void set_instrument_tip(const core::Vec3& tip) { tool_tip_ = tip; }
  /// Force in N that the tissue puts on the instrument (zero without contact or instrument).
  core::Vec3 instrument_force() const {
    return instrument_ ? instrument_->proxy.force() : core::Vec3::Zero();
  }
  bool instrument_in_contact() const { return instrument_ && instrument_->proxy.in_contact(); }
  /// Where the instrument's proxy touches its body's surface (triangle of surface_faces()).
  ProxyContact instrument_contact() const {
    return instrument_ ? instrument_->proxy.contact() : ProxyContact{};
  }
  /// The proxy point on the surface (m), or the tip when free.
  core::Vec3 instrument_proxy() const {
    return instrument_ ? instrument_->proxy.proxy() : tool_tip_;
  }
  /// Index of the body the instrument works on, or −1.
  int instrument_body() const { return instrument_ ? instrument_->body : -1; }
  /// The tip position the instrument was last moved to, in m.
  const core::Vec3& instrument_tip() const { return tool_tip_; }

  /// Contacts of the last sub-step.
  const ContactStatistics& contacts() const { return contacts_; }
  /// Largest penetration in m seen in any sub-step so far.
  double max_penetration() const { return max_penetration_; }

  /// Springs of the scenario's connections between bodies.
  const ConnectionSprings& connections() const { return connections_; }

  /// Sum of the bodies' energies at the current state; connection springs count as elastic.
  BodyEnergies energies() const;

  /// Sleeping (the deactivation of rigid-body engines): once no node has moved more than
  /// `threshold` m per sub-step for kCalmSubstepsToSleep sub-steps and the instrument touches
  /// nothing, the world stops integrating (velocities set to zero) until the instrument's
  /// proxy meets a surface again. 0 disables (the default); sessions enable it.
  void set_sleep_threshold(double threshold) { sleep_threshold_ = threshold; }
  bool asleep() const { return asleep_; }
  static constexpr int kCalmSubstepsToSleep = 200;

  /// Largest stable sub-step in s found for the world (before splitting time_step() evenly).
  double stable_step() const { return stable_step_; }
  /// Fraction of the spectral stable step that sub-steps may use: margin for the power
  /// iteration approaching λ_max from below and for stiffening under large deformation.
  static constexpr double kStableStepSafety = 0.8;

  /// SHA-256 (hex) of every body's current and previous positions, in body order: equal hashes
  /// mean bit-identical states.
  std::string state_hash() const;

 private:
  std::vector<DeformableBody> bodies_;
  core::Vec3 gravity_;
  double time_step_ = 1.0e-3;
  int substeps_ = 1;
  double stable_step_ = 0.0;
  double contact_stiffness_ = 0.0;
  long long steps_ = 0;
  std::unique_ptr<ContactResponse> contact_;
  ConnectionSprings connections_;
  struct Instrument {
    int body;
    ProxySurface surface;
    HapticProxy proxy;
  };
  std::unique_ptr<Instrument> instrument_;
  core::Vec3 tool_tip_ = core::Vec3::Zero();
  ContactStatistics contacts_;
  double max_penetration_ = 0.0;
  double sleep_threshold_ = 0.0;
  int calm_substeps_ = 0;
  bool asleep_ = false;

  void update_sleep();
  /// Sets stable_step_ and substeps_ from the bodies, connections, contacts and instrument.
  void choose_substeps();
};

}  // namespace viscera::sim
