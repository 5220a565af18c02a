#pragma once
/// One training session stepped at the fixed physics step (DESIGN.md §5, seed 000 §11): the
/// world with its instrument, the procedure's steps and tasks, the metrics of every step, the
/// complications that end it (perforation, tear, time limit, abort) and the record that replays it.
/// The headless run and the interactive view both drive a SessionRunner, one step at a time.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/scenario/scenario.h"
#include "simulator/camera/surface_coverage.h"
#include "simulator/dynamics/fluid_drag.h"
#include "simulator/dynamics/hydrometra_forces.h"
#include "simulator/fluid/bleeding_sources.h"
#include "simulator/fluid/cavity_flow.h"
#include "simulator/fluid/distension_balance.h"
#include "simulator/session/chip_retrieval.h"
#include "simulator/session/instrument_input.h"
#include "simulator/session/instrument_tissue.h"
#include "simulator/session/laparoscopic_tools.h"
#include "simulator/session/loop_resection.h"
#include "simulator/session/series_thinning.h"
#include "simulator/session/session_report.h"
#include "simulator/session/suction_irrigation.h"
#include "simulator/session/tissue_tears.h"
#include "simulator/session/wall_cut_depth.h"
#include "simulator/world/world.h"

namespace viscera::sim {

class ProxySpringTerm;

/// Options of a session.
struct HeadlessRunOptions {
  double duration = 2.0;  ///< s the session may last at most (the scenario's limit also applies)
  double sample_interval = 0.02;  ///< s between path, energy and task samples
  double camera_interval = 0.1;   ///< s between looks through the optics for the surface seen
  std::string package;            ///< package path, recorded in the report
  /// When set, an instrument whose tip follows this input acts on object `instrument_body`
  /// (empty: the first simulated body, else the first urethra lattice): a World body it presses
  /// on with a proxy spring of `instrument_stiffness` N/m, or a urethra lattice whose seed-002
  /// force model it meets (see InstrumentTissue).
  const InstrumentInput* instrument = nullptr;
  std::string instrument_body;
  double instrument_stiffness = 200.0;
  long long checkpoint_interval = 100;  ///< physics steps between state hashes (for replay)
  bool record_inputs = false;           ///< keep the instrument states in the report
  /// Complications: the tool pushed further than this (m) into the wall perforates it and ends
  /// the session (0: the scenario's perforation depth, or else the local wall thickness).
  /// Forces above `force_warning` N (0: the scenario's level) are logged, one per episode.
  double perforation_depth = 0.0;
  double force_warning = 0.0;
  bool end_when_complete = true;  ///< end once every step of the procedure is done
  /// m per step below which a calm world goes to sleep until touched (World); 0: never. At
  /// 1e-7 m per 1 ms step (0.1 mm/s) it lies above the creep the implicit solver's residual
  /// tolerance leaves (a step whose residual is below 1 µN keeps its velocity: ~10⁻⁸–10⁻⁷ m
  /// per step on the wall's nodes), which a smaller threshold would never see end.
  double sleep_threshold = 1e-7;
  /// Start from the patient's static equilibrium (World::settle) rather than the authored rest
  /// shape sagging into it during the session.
  bool settle = true;
};

/// A session in progress.
class SessionRunner {
 public:
  /// Builds the world, the tissue under the instrument and the task monitors; throws
  /// core::InputError for an unknown instrument body and core::UsageError for a non-positive
  /// duration.
  SessionRunner(const core::Scenario& scenario, const HeadlessRunOptions& options);
  ~SessionRunner();

  /// Advances one physics step with the instrument in `state` (ignored without instrument).
  /// Throws core::SimulationError when the physics cannot go on (a non-finite state, …).
  void step(const InstrumentState& state);
  /// True once an end condition holds; the report's end_reason says which.
  bool finished() const { return finished_; }
  /// Ends the session now with `reason` (e.g. "abort" from a window being closed).
  void end(const std::string& reason, const std::string& message);

  /// The report so far; final once finished() (wall time and body summaries are filled in).
  SessionReport finish();

  const World& world() const { return world_; }
  const SessionReport& report() const { return report_; }
  const InstrumentState& instrument_state() const { return state_; }
  /// Force of the tissue on the instrument, N (zero without instrument): on its tip, plus what
  /// a grasper holds.
  core::Vec3 instrument_force() const;
  /// Force of the tissue on the second port's tool, N: on its jaws' hinge, plus what its
  /// grasper holds (zero while the port is empty).
  core::Vec3 second_port_force() const;
  /// The laparoscopic tools, or null when the instrument carries none.
  const LaparoscopicTools* tools() const { return tools_.get(); }
  /// The resection loop, or null without a resectoscope.
  const LoopResection* resection() const { return resection_.get(); }
  const ChipRetrieval* chip_retrieval() const { return retrieval_.get(); }
  /// The cut bodies' visible surfaces, or null when no instrument of the session cuts.
  const VisibleSurfaces* visible_surfaces() const { return visible_.get(); }
  /// The suction–irrigation cannula's jet and the pool, or null when the instrument carries no
  /// laparoscopic tools.
  const SuctionIrrigation* irrigation() const { return irrigation_.get(); }
  /// The tissue the instrument acts on, or null without instrument.
  const InstrumentTissue* tissue() const { return tissue_.get(); }
  const core::InstrumentSpec& instrument() const { return instrument_; }
  /// Stiffness of the instrument's proxy spring, N/m (HeadlessRunOptions).
  double instrument_stiffness() const { return options_.instrument_stiffness; }
  /// Index of the procedure step under way, −1 without steps.
  int current_step() const { return current_; }
  /// The camera's coverage of the instrument body's surface, or null without a surface.
  const SurfaceCoverage* coverage() const { return coverage_.get(); }
  double time_limit() const { return time_limit_; }
  /// The distension flow in the cavity with its blood, or null without one.
  const fluid::CavityFlow* cavity_flow() const { return cavity_.get(); }

 private:
  struct Monitor;
  void sample();
  /// The resection term of a step's score (−2: the whole session): see period_score.
  std::optional<double> resection_share(int step) const;
  /// Sets up the loop on every pathology body of the world (LoopResection).
  void start_resection(const core::Scenario& scenario);
  /// After the loop's sweep was cut: how deep it went into the wall; a perforation ends the
  /// session.
  void gauge_wall_cut(double time);
  void look();
  /// world_.step(), with any failure turned into a core::SimulationError naming body, node,
  /// step and likely cause (simulation_check.h).
  void step_world();
  void advance_steps();
  void open_step(int index);
  void close_step(int index);
  std::string state_hash() const;

  const core::Scenario& scenario_;
  HeadlessRunOptions options_;
  World world_;
  core::InstrumentSpec instrument_;
  SessionReport report_;
  InstrumentState input_;  ///< the input as given
  InstrumentState state_;  ///< the input with its tip where the tissue it follows is now
  std::unique_ptr<InstrumentTissue> tissue_;
  std::unique_ptr<SurfaceCoverage> coverage_;
  /// The resection loop, with a "resectoscope" instrument: it cuts the pathology bodies.
  std::unique_ptr<LoopResection> resection_;
  std::unique_ptr<ChipRetrieval> retrieval_;  ///< with the loop: its chips out through the cervix
  std::unique_ptr<WallCutGauge> wall_gauge_;  ///< with the loop: how deep it cut into the wall
  int gauged_sweeps_ = 0;                     ///< sweeps the wall gauge has measured
  std::unique_ptr<VisibleSurfaces> visible_;  ///< made by the first cutting instrument
  std::unique_ptr<TissueTears> tears_;        ///< with a cutting instrument
  std::vector<core::Vec3> coverage_rest_;     ///< visual vertices when the surface has no embedding
  std::vector<Monitor> monitors_;
  int current_ = -1;
  double time_limit_ = 0.0, force_warning_ = 0.0, perforation_depth_ = 0.0;
  long long total_steps_ = 0, sample_every_ = 1, look_every_ = 1;
  /// The report's series, bounded however long the session (SeriesThinning): 16,384 energy
  /// and path samples each (5.5 min at the default 50 Hz before the first thinning) and 8,192
  /// replay checkpoints (13.6 min at 1 ms steps and the default interval of 100 steps).
  SeriesThinning energy_series_{16384}, path_series_{16384}, checkpoint_series_{8192};
  SeriesThinning fluid_series_{16384};
  bool finished_ = false, over_force_ = false;
  bool instrument_moved_ = false;  ///< the input has changed the instrument's state
  double last_view_distance_ = -1.0;
  double started_wall_clock_ = 0.0;
  /// The cavity's distension fluid, when the scenario enables it and an instrument drives the
  /// valves.
  std::optional<DistensionBalance> fluid_;
  /// Bleeding from what the loop cuts (issue 18 §3): sources at each cut's opened vessels and
  /// cut surface, open paths of the fluid balance (or bleeding freely without one).
  std::optional<fluid::BleedingSources> bleeding_;
  /// Per world body, the vessel trees the scenario hosts in it.
  std::vector<std::vector<core::VesselTree>> hosted_trees_;
  /// Feeds the valves and the bleeding sources of one step of `dt` s to the fluid balance and
  /// ends the session on fluid overload.
  void balance_fluid(double dt);
  /// No bleeding yet, and the vessel trees each body hosts (for the cuts to open).
  void start_bleeding_sources(const core::Scenario& scenario);
  /// Starts the bleeding of a cut of world body `body` at `time` s.
  void start_bleeding(int body, const cutting::TopologyChange& change, double time);
  /// With the coagulation pedal down: seals the bleeding sources within reach of the loop.
  void coagulate(double time);
  /// Stops the pulse waves of the vessels coagulated at `time` s at their sites.
  void stop_pulse_at_sealed_vessels(double time);

  /// The laparoscopic tools in the working port (issue 19 §3), with a "laparoscope" instrument.
  std::unique_ptr<LaparoscopicTools> tools_;
  /// Sets up the tools, their report block and what clips, coagulation and cuts do to the
  /// bleeding and the pulse waves.
  void start_tools(const core::Scenario& scenario);
  /// Tears on `bodies` (those the instrument can cut) become cracks (tissue_tears.h).
  void start_tears(std::vector<int> bodies);
  /// Moves the instrument's contact point to state_ (a tool's jaws touch with their hinge).
  void move_tissue();
  /// The second port's tool touches every body through a proxy spring of its own (the
  /// instrument's stiffness), put into the world when a tool first enters the port; a tool
  /// taken out is drawn back along its shaft, out of the tissue.
  ProxySpringTerm* second_proxy_ = nullptr;
  core::Vec3 second_axis_ = core::Vec3::UnitZ();  ///< the second tool's shaft when last in
  bool second_withdrawn_ = false;                 ///< its proxy already drawn back out
  /// Moves the second port's contact point to state_.second (before the world steps).
  void move_second_port();
  /// The jet, the pool and the suction of the suction–irrigation cannula (issue 19 §3).
  std::unique_ptr<SuctionIrrigation> irrigation_;
  /// After a physics step of `dt` s and its bleeding: the jet flies, the pool fills with its
  /// water and the sources' blood, the suction draws off (session_runner_irrigation.cpp).
  void irrigate(double dt);
  /// Makes the arterial sources from `first` on pulse with their tree's authored pulse.
  void pulse_opened_arteries(std::size_t first);
  /// After a physics step: the tools follow the instrument.
  void follow_tools(double time);
  /// Seals the bleeding sources within `reach` m of `point` (m, current) at `time` s.
  void seal_bleeding_near(const core::Vec3& point, double reach, double time);
  /// Stops every pulse wave on `body` at `rest_point` (m) when a vessel of its tree runs within
  /// `reach` m; `what` names the cause in the event.
  void stop_pulse_near(int body, const core::Vec3& rest_point, double reach, double time,
                       const std::string& what);

  /// The flow in the cavity of the first body whose surface marks a "cavity" (issue 18 §2),
  /// with the distension fluid.
  std::unique_ptr<fluid::CavityFlow> cavity_;
  FluidDrag* chip_drag_ = nullptr;  ///< the flow's drag on the loop's chips, owned by world_
  int cavity_body_ = -1;
  const core::SceneObject* cavity_object_ = nullptr;
  std::vector<double> bled_seen_;  ///< per bleeding source, m³ already handed to the flow
  bool cut_since_flow_ = false;    ///< a pathology was cut since the last flow step
  std::vector<fluid::DebrisRelease> pending_debris_;  ///< shreds cut off since the last step
  double inflow_rate_ = 0.0;                          ///< m³/s the pump delivered in the last step
  long long pressure_iterations_ = 0;
  void start_cavity_flow(const core::Scenario& scenario);
  /// Hands the step's pump inflow, blood and surfaces to the flow; books the clouded view.
  void flow_cavity(double dt);
  /// The cavity wall's current surface positions, m.
  std::vector<core::Vec3> cavity_wall() const;
  /// The hydrometra of the cavity's organ (seed 000 §2.1), a term the world owns, or null when
  /// the package holds no pressure states: balance_fluid() hands it the pressure each step.
  HydrometraForces* hydrometra_ = nullptr;
};

}  // namespace viscera::sim
