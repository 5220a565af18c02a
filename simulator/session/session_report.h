#pragma once
/// The result of a session (seed 000 §11: "a comprehensive report summarizing the quantitative
/// metrics"): per step and in total, the tasks, the events, the tool path with its distance to
/// the wall (seed 000 Fig. 16), the body energies and the state hashes that prove a replay.
/// As JSON: format "viscera-session-report", version 3, schema docs/session-report.schema.json.
/// A score is absent (null) with its reason when nothing of the period could be assessed.

#include <algorithm>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "simulator/fluid/bleeding_sources.h"
#include "simulator/fluid/distension_balance.h"
#include "simulator/session/instrument_state.h"
#include "simulator/session/laparoscopy_summary.h"
#include "simulator/session/session_metrics.h"
#include "simulator/session/task_monitor.h"

namespace viscera::sim {

/// Something that happened during a session, at a time in s.
struct SessionEvent {
  double time = 0.0;
  std::string kind;  ///< "perforation", "tissue-tear", "excessive-force", "force-warning",
                     ///< "time-limit", "abort", "task-completed", "step-started"
  std::string message;
};

/// One energy sample. Energies in J, displacement in m.
struct EnergySample {
  double time = 0.0;
  double kinetic = 0.0;
  double elastic = 0.0;
  double gravitational = 0.0;
  double max_displacement = 0.0;
  int colliding_points = 0;      ///< vertices inside another body
  double max_penetration = 0.0;  ///< m, deepest colliding point of the last sub-step
  double total() const { return kinetic + elastic + gravitational; }
};

/// The tool at one sample of the session.
struct PathSample {
  double time = 0.0;  ///< s
  core::Vec3 tip = core::Vec3::Zero();
  double force = 0.0;           ///< N on the instrument
  double wall_distance = -1.0;  ///< m from the tip to the nearest wall point, −1 without a surface
  bool in_contact = false;
  int step = -1;  ///< index of the procedure step under way, −1 without steps
};

/// The distension fluid at one sample of the session (m³, Pa).
struct FluidSample {
  double time = 0.0;          ///< s
  double pressure = 0.0;      ///< Pa in the cavity
  double deficit = 0.0;       ///< used − drained so far
  double bled = 0.0;          ///< blood that entered the cavity so far
  double intravasated = 0.0;  ///< fluid that entered the circulation through opened vessels
};

/// One procedure step as the trainee did it.
struct StepResult {
  std::string id;
  std::string name;
  double started_at = -1.0;  ///< s, −1 when the session ended before it
  double ended_at = -1.0;    ///< s
  SessionMetrics metrics;
  std::optional<double> score;  ///< 0…100 (period_score), absent when not assessable
  std::string score_reason;     ///< why there is no score, "" with one
};

/// Per-body summary at the end of the run.
struct BodySummary {
  std::string name;
  std::size_t nodes = 0, edges = 0, tets = 0, surface_triangles = 0;
  double max_displacement = 0.0;     ///< m
  double centre_of_mass_drop = 0.0;  ///< m, along gravity
};

/// How a threaded window session kept time (RealtimeLoop), absent headless. Wall-clock
/// figures: they describe the run, not the simulation, and never enter the state hash.
struct RealtimeStats {
  double wall_time = 0.0;  ///< s the physics thread ran
  long long physics_steps = 0;
  long long late_steps = 0;          ///< steps that began more than one step late
  double max_lag = 0.0;              ///< s, largest delay of a step behind the wall clock
  long long frames = 0;              ///< frames the view rendered
  double view_fps = 0.0;             ///< frames per wall-clock second
  double render_scale = 1.0;         ///< scene resolution under the lens pass at the end (fraction)
  double lowest_render_scale = 1.0;  ///< the smallest the adaptive resolution went
  bool device = false;               ///< a haptic device drove the instrument
  long long device_poses = 0;        ///< poses received from it
  long long device_feedback = 0;     ///< feedback packets sent to it
  double feedback_rate = 0.0;        ///< feedback packets per wall-clock second
  bool device_real_time = false;     ///< the device thread ran at a real-time priority
  /// The same for the second port's device (the left hand, `--left-device`).
  bool left_device = false;
  long long left_device_poses = 0;
  long long left_device_feedback = 0;
  double left_feedback_rate = 0.0;  ///< feedback packets per wall-clock second
  bool left_device_real_time = false;
};

/// What one pathology lost to the resection loop (issue 17 §5).
struct BodyResection {
  std::string body;
  double initial_volume = 0.0;   ///< m³, rest volume at the start of the session
  double resected_volume = 0.0;  ///< m³, rest volume of its chips and debris (cut off)
  int chips = 0;                 ///< chips cut off and still in the cavity
  int debris = 0;  ///< shreds too small to be chips, handed to the flow as debris particles
  int chips_retrieved = 0;        ///< chips taken out through the cervix (chip_retrieval.h)
  double retrieved_volume = 0.0;  ///< m³, their rest volume
  double resected_fraction() const {
    return initial_volume > 0.0 ? std::min(1.0, resected_volume / initial_volume) : 0.0;
  }
};

/// The cuts of a session (issue 17 §5); absent when the instrument cannot cut.
struct CuttingSummary {
  int sweeps = 0;              ///< pedal presses with a sweep that moved
  int cuts = 0;                ///< bodies cut (one sweep through two bodies counts two)
  int released_in_tissue = 0;  ///< bodies a sweep ended inside: not cut (seed 000 §5.1)
  long long tets_created = 0;
  std::vector<double> cut_seconds;  ///< wall time of each cut, s (the run, not the state)
  double min_dihedral_before_degrees = 180.0;  ///< over the tets the cuts replaced
  double min_dihedral_after_degrees = 180.0;   ///< over the tets the cuts created
  double volume_before = 0.0;  ///< m³, rest volume of the cuttable bodies at the start
  double volume_after = 0.0;   ///< m³, the same now (a cut keeps it, to rounding)
  std::vector<BodyResection> bodies;
  /// The deepest any sweep went into the organ's wall below its cavity (wall_cut_depth.h), m,
  /// with the wall's thickness there; absent while no sweep entered the wall.
  std::optional<double> deepest_wall_cut;
  std::optional<double> wall_thickness_at_deepest_cut;
  /// m³ of healthy wall the sweeps took off (estimated on them, wall_cut_depth.h); absent when
  /// the organ has no cavity surface to gauge the sweeps against.
  std::optional<double> healthy_wall_removed;

  /// The resection of body `name`, or null when the loop cannot cut it.
  const BodyResection* find(const std::string& name) const {
    for (const BodyResection& b : bodies)
      if (b.body == name) return &b;
    return nullptr;
  }
};

/// The distension flow in the cavity over a session (issue 18 §2, §6): how the flow ran and how
/// much the blood in it clouded the optics (CavityFlow).
struct CavityFlowSummary {
  long long flow_steps = 0;
  long long relabellings = 0;  ///< times the wall or a pathology was labelled again
  double cell_size = 0.0;      ///< m
  int fluid_cells = 0;         ///< at the start
  double mean_pressure_iterations = 0.0;
  double view_obscured_time = 0.0;     ///< s with the line of sight's transmission below the
                                       ///< threshold
  double lowest_transmission = 1.0;    ///< 0…1, over the flow steps
  double obscured_threshold = 0.0;     ///< the transmission below which the view is obscured
  double blood_released = 0.0;         ///< m³ handed to the flow as particles
  double blood_in_cavity = 0.0;        ///< m³ at the end: in particles and in the field
  double blood_drained = 0.0;          ///< m³ carried out through the outflow
  double blood_lost = 0.0;             ///< m³ particles released into solid cells or off the grid
  int particles = 0;                   ///< alive at the end
  long long air_bubbles_admitted = 0;  ///< air bubbles the inflow brought in
  long long air_bubbles_flushed = 0;   ///< carried out through the outflow
  int air_bubbles_at_end = 0;          ///< in the cavity at the end
  long long debris_released = 0;       ///< resection shreds the flow took as debris particles
  long long debris_flushed = 0;        ///< carried out through the sheath's outflow
  int debris_at_end = 0;               ///< in the cavity at the end
};

/// The result of a session.
struct SessionReport {
  std::string package;
  std::string procedure;        ///< procedure definition name, or ""
  std::string instrument;       ///< kind of the simulated instrument
  long long steps = 0;          ///< physics steps
  double simulated_time = 0.0;  ///< s
  double wall_time = 0.0;       ///< s
  double time_step = 0.0;       ///< s
  int substeps = 1;
  /// Settling to the static equilibrium before the clock starts (World::settle): steps taken
  /// (0: not settled) and whether it came to rest.
  int settle_steps = 0;
  bool settled_at_rest = false;
  double time_limit = 0.0;     ///< s
  double force_warning = 0.0;  ///< N
  std::vector<EnergySample> samples;
  double max_displacement = 0.0;   ///< m, over the whole run
  double max_penetration = 0.0;    ///< m, deepest body–body contact over every sub-step
  double contact_stiffness = 0.0;  ///< N/m, 0 when the scene has fewer than two bodies
  std::vector<BodySummary> bodies;
  std::vector<TaskResult> tasks;
  std::vector<StepResult> procedure_steps;
  std::string final_state_hash;
  bool has_instrument = false;
  SessionMetrics metrics;       ///< of the whole session
  std::optional<double> score;  ///< 0…100 (period_score), absent when not assessable
  std::string score_reason;     ///< why there is no score, "" with one
  std::vector<PathSample> path;
  std::vector<std::pair<long long, std::string>> checkpoints;  ///< (step, state hash)
  /// The instrument states, as (step, state) at every step where the state changed (when
  /// recorded): enough to replay the session exactly.
  std::vector<std::pair<long long, InstrumentState>> inputs;
  std::vector<SessionEvent> events;
  /// The distension fluid's balance (m³, Pa), when the scenario simulates it.
  std::optional<FluidTotals> fluid;
  std::vector<FluidSample> fluid_series;  ///< at the energy samples' rate, thinned alike
  double final_cavity_pressure = 0.0;     ///< Pa
  std::optional<RealtimeStats> realtime;  ///< of a threaded window session
  std::optional<CuttingSummary> cutting;  ///< with a cutting instrument
  /// Every bleeding source the cuts opened, as the session left it (with a cutting instrument).
  std::optional<std::vector<fluid::BleedingSource>> bleeding;
  std::optional<CavityFlowSummary> cavity_flow;   ///< when the cavity's flow is simulated
  std::optional<LaparoscopySummary> laparoscopy;  ///< with laparoscopic tools
  std::string end_reason = "duration";  ///< "duration", "time-limit", "completed", "perforation",
                                        ///< "fluid-overload", "tissue-tear", "abort"
};

/// A period's score, or why it has none.
struct PeriodScore {
  std::optional<double> value;  ///< 0…100
  std::string reason;           ///< set when value is absent
};

/// Score of a period in [0, 100]: the mean of task completion (completed over assessable
/// tasks), economy of movement, view quality, time free of wall contact and force safety (1 −
/// max force over the warning level, clamped) — equal weights, each in [0, 1]. Terms without
/// data (no assessable task, no warning level, no look through the optics) are left out. The
/// trainee's work is assessable only once the instrument has moved: a period in which the tool
/// never moved has no score (its reason says so), so doing nothing never earns the safety terms.
/// `resection`, when the period holds "resect" tasks, is one more term: how much of what they
/// ask was taken off (each task's resected fraction over its required one, capped at 1, averaged),
/// so a half-done resection weighs as much as the way it was done.
PeriodScore period_score(const SessionMetrics& metrics, double force_warning,
                         std::optional<double> resection = std::nullopt);

/// The report as JSON (format "viscera-session-report", version 3): "score" is null with
/// "score_reason" when absent, in total and per procedure step.
nlohmann::json report_to_json(const SessionReport& report);

}  // namespace viscera::sim
