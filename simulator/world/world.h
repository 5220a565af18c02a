#pragma once
/// The simulated world of a scenario (DESIGN.md §5): a facade over the simulation core of
/// simulator/dynamics — one SimulationState holding every body's nodes, the force terms built
/// from the scenario, and one integrator. Single-threaded and in a fixed order, so the same
/// scenario gives the same state bit for bit (the deterministic mode of sessions and replays).

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/scenario/scenario.h"
#include "simulator/dynamics/body_topology.h"
#include "simulator/dynamics/contact_term.h"
#include "simulator/dynamics/integrator.h"
#include "simulator/dynamics/proxy_spring_term.h"
#include "simulator/world/body_view.h"

namespace viscera::sim {

class ConnectionSpringTerm;
class AttachmentTerm;
class GravityTerm;

/// Energies of the world in J.
struct BodyEnergies {
  double kinetic = 0.0;
  double elastic = 0.0;        ///< every internal, connection, attachment and contact term
  double gravitational = 0.0;  ///< relative to the rest configuration
  double total() const { return kinetic + elastic + gravitational; }
};

/// Which integrator steps the world.
enum class IntegratorKind {
  Automatic,       ///< backward Euler when any body has Teschner energies, else explicit Verlet
  ExplicitVerlet,  ///< the reference, with spectral sub-steps
  BackwardEuler    ///< implicit, no sub-steps
};

class World {
 public:
  /// Builds a node range and force terms for every object whose body kind is a tet mesh
  /// (Teschner distance/area/volume, each tet with the material of its wall layer) or a
  /// mass-spring net (KisMo springs): connections of a pathology object become barycentric
  /// attachments of its nodes to the host's tets, other connections linear springs; with two
  /// or more bodies and a positive scenario.session.contact_stiffness, body–body contact;
  /// gravity. Throws core::InputError for a missing material, an invalid body or a connection
  /// naming an object without a body or a node it does not have.
  explicit World(const core::Scenario& scenario,
                 IntegratorKind integrator = IntegratorKind::Automatic);
  ~World();
  World(const World&) = delete;
  World& operator=(const World&) = delete;

  /// Advances by one physics step (time_step() seconds). Throws core::SimulationError (body,
  /// node, step, likely cause) for a non-finite state, and — unless set_inversion_errors(false)
  /// — for a tet turned inside out (TeschnerVolumeTerm::first_inverted).
  void step();
  /// Whether an everted tet is an error. On by default: the volume terms' collapse barrier
  /// (teschner_energies.h) keeps every tet of the implicit integrator above zero volume under
  /// any finite load, so a tet that still turns inside out is a real failure (a tangled input,
  /// or a time step the explicit integrator cannot hold). Off only for reports that count
  /// everted tets (everted_tets()) instead of stopping at the first.
  void set_inversion_errors(bool on) { inversion_errors_ = on; }
  /// Tets now turned inside out (signed volume below −V0), for reports.
  int everted_tets() const;

  double time() const { return static_cast<double>(steps_) * time_step_; }
  long long steps() const { return steps_; }
  double time_step() const { return time_step_; }
  /// Sub-steps per step: 1 for the implicit integrator.
  int substeps() const;
  /// Largest stable explicit sub-step in s (infinite for the implicit integrator).
  double stable_step() const;
  const core::Vec3& gravity() const { return gravity_; }
  const std::vector<BodyView>& bodies() const { return views_; }
  std::vector<BodyView>& bodies() { return views_; }
  /// The body named `name`, or −1.
  int body_index(const std::string& name) const;

  const SimulationState& state() const { return state_; }
  SimulationState& state() { return state_; }
  const Integrator& integrator() const { return *integrator_; }
  const StepStatistics& last_step_statistics() const { return statistics_; }
  /// Every force term in evaluation order.
  const std::vector<std::unique_ptr<ForceTerm>>& terms() const { return terms_; }
  /// Adds a force term (e.g. motility, plasticity) evaluated after the built-in ones; the
  /// integrator's structure is rebuilt before it is next used (terms added in a row: once).
  void add_term(std::unique_ptr<ForceTerm> term);
  const std::vector<std::shared_ptr<BodyModel>>& models() const { return models_; }
  /// Call after changing a term's coefficients in place (coagulated tissue stiffening): the
  /// integrator plans its step anew (the explicit one its stable sub-step) and the world wakes
  /// — with `body` ≥ 0 (the body whose tissue changed) only that body's explicit island, the
  /// other sleeping islands sleep on; with −1 every island.
  void stiffness_changed(int body = -1);

  /// Puts a haptic instrument into the world: a proxy point over the surfaces of EVERY body with
  /// a proxy–tip spring of `stiffness` N/m (seed 000 §8.2); `body` is the body the session
  /// judges (perforation). The tip starts at `tip`. Throws core::UsageError for a body index out
  /// of range.
  void attach_instrument(int body, double stiffness, const core::Vec3& tip);
  /// Moves the instrument tip (m); takes effect at the next step.
  void set_instrument_tip(const core::Vec3& tip);
  /// Force in N that the tissue puts on the instrument (zero without contact or instrument).
  core::Vec3 instrument_force() const;
  bool instrument_in_contact() const;
  /// Where the proxy touches: the triangle of surface_faces() of instrument_touched_body().
  ProxyContact instrument_contact() const;
  /// The body the proxy touches, or −1.
  int instrument_touched_body() const;
  /// The proxy point on the surface (m), or the tip when free.
  core::Vec3 instrument_proxy() const;
  /// Index of the body the instrument was attached for, or −1.
  int instrument_body() const { return instrument_body_; }
  const core::Vec3& instrument_tip() const { return tool_tip_; }

  /// Contacts between bodies at the last step's detection.
  const ContactStatistics& contacts() const { return contacts_; }
  /// Largest penetration in m seen so far.
  double max_penetration() const { return max_penetration_; }

  /// Energies at the current state.
  BodyEnergies energies() const;

  /// Brings a scene authored at rest to its static equilibrium under its terms before a session
  /// starts — the wall's sag under gravity, a pathology hanging on its wall, bodies pressed
  /// together — so the trainee does not watch the patient sag into place. Backward Euler steps
  /// of `h` s with the velocities zeroed after each (a damped Newton descent on the potential
  /// energy, each step regularised by M/h²) until no node moves more than `tolerance` m in a
  /// step, or `max_steps`; the scene then starts there at rest and the clock stays at zero.
  /// Only when every body is held — a fixed node, or an attachment or connection to another
  /// body: a free body has no rest to settle to. An implicit world settles only without
  /// motility or a pulse, whose driven motion has no rest either. An explicit world (KisMo
  /// nets) settles with a backward Euler of its own under every term but the pulse (zero
  /// between its wave fronts), with motility held at the session's start: its undriven islands
  /// then start at rest instead of ringing down from the authored shape.
  /// Per node of `body`, 1 for a node that holds it in place: a fixed node, a node attached to
  /// another body's tets (a pathology on its wall), or a node of a connection spring to another
  /// body. What settle() requires of every body, and what a cut piece needs to stay the
  /// patient's (severed_pieces.h).
  std::vector<std::uint8_t> held_nodes(int body) const;
  struct Settling {
    int steps = 0;  ///< settle steps taken (0: not settled at all)
    /// the last step moved no node more than the tolerance and left no nodal force residual
    /// above the integrator's tolerance
    bool at_rest = false;
    double last_move = 0.0;  ///< m, the largest node move of the last step
  };
  /// Each settle step takes at most kSettleNewtonIterations Newton iterations of at most
  /// kSettleCgIterations CG iterations: the steps are a descent, not a motion. At rest needs
  /// the largest nodal force residual within the integrator's tolerance (1 µN) as well as no
  /// node moving more than `tolerance`. A world that settled at rest with sleeping on
  /// (set_sleep_threshold, no term driving, a tolerance within the sleep threshold) starts
  /// asleep.
  Settling settle(double h = 0.05, int max_steps = 30, double tolerance = 1e-7);
  static constexpr int kSettleNewtonIterations = 2;
  static constexpr int kSettleCgIterations = 25;

  /// Sleeping (the deactivation of rigid-body engines): once no node has moved more than
  /// `threshold` m per step for kCalmStepsToSleep steps and the instrument touches nothing, the
  /// world stops integrating (velocities set to zero) until the proxy meets a surface again.
  /// 0 disables (the default); sessions enable it.
  /// The explicit integrator's islands sleep with the same threshold (explicit_verlet.h).
  void set_sleep_threshold(double threshold);
  bool asleep() const { return asleep_; }
  /// Wakes a sleeping world: something outside the terms' view moved (e.g. the hydrometra's
  /// target shape after a pressure change), so the next step integrates again.
  void wake();
  static constexpr int kCalmStepsToSleep = 200;
  /// A term drives the bodies from outside the state (ForceTerm::drives: a grasper's jaws, a
  /// closing clip): the world does not sleep while one does.
  bool driven() const;

  /// Replaces the topology of `body` (cutting): its node range, rest model and every cache that
  /// depends on it — force terms, contact hash, proxy surface, attachments, the integrator's
  /// structure. Per-node masses come from topology.rest_mesh.node_mass or, when empty, are
  /// carried by `origin`; velocities are carried by `origin`. Throws core::InputError for an
  /// invalid mesh.
  void topology_changed(int body, const BodyTopology& topology);

  /// SHA-256 (hex) of every node's position and velocity: equal hashes mean bit-identical states.
  std::string state_hash() const;

 private:
  void build_terms(const core::Scenario& scenario);
  void refresh_views();
  std::vector<ForceTerm*> term_pointers() const;
  void check_state() const;
  void update_sleep();

  SimulationState state_;
  std::vector<std::shared_ptr<BodyModel>> models_;
  std::vector<BodyView> views_;
  std::vector<std::unique_ptr<ForceTerm>> terms_;
  std::unique_ptr<Integrator> integrator_;
  /// Terms were added since the integrator last saw them.
  mutable bool integrator_stale_ = false;
  /// Lets the integrator see the terms added since it last did.
  void refresh_integrator() const;
  BodyContactTerm* contact_ = nullptr;
  ProxySpringTerm* proxy_ = nullptr;
  core::Vec3 gravity_;
  double time_step_ = 1.0e-3;
  double contact_stiffness_ = 0.0;
  long long steps_ = 0;
  int instrument_body_ = -1;
  core::Vec3 tool_tip_ = core::Vec3::Zero();
  ContactStatistics contacts_;
  StepStatistics statistics_;
  double max_penetration_ = 0.0;
  double sleep_threshold_ = 0.0;
  int calm_steps_ = 0;
  bool asleep_ = false;
  bool inversion_errors_ = true;
};

}  // namespace viscera::sim
