#pragma once
/// A session run without a window at a fixed physics step (DESIGN.md §5, deterministic mode):
/// the world is stepped for a duration, sampled at a fixed interval, and summarised in a
/// report.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/progress.h"
#include "core/scenario/scenario.h"
#include "simulator/session/instrument_input.h"
#include "simulator/session/session_metrics.h"

namespace viscera::sim {

/// Options of a headless run.
struct HeadlessRunOptions {
  double duration = 2.0;           ///< simulated seconds
  double sample_interval = 0.01;   ///< s between energy samples
  std::string package;             ///< package path, recorded in the report
  /// When set, a haptic instrument whose tip follows this input presses on the body of object
  /// `instrument_body` with a proxy spring of `instrument_stiffness` N/m.
  const InstrumentInput* instrument = nullptr;
  std::string instrument_body;
  double instrument_stiffness = 200.0;
  long long checkpoint_interval = 100;  ///< physics steps between state hashes (for replay)
  bool record_inputs = false;           ///< keep the tip of every step in the report
  /// Complications (issue 8): the tool pushed further than this (m) into tissue perforates the
  /// wall and ends the session; 0 disables. Forces above `force_warning` (N) are logged as
  /// warnings, one per episode.
  double perforation_depth = 0.0;
  double force_warning = 0.0;
};

/// Something that happened during a session, at a time in s.
struct SessionEvent {
  double time = 0.0;
  std::string kind;     ///< "perforation" (ends the session) or "excessive-force"
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

/// What happened to one task of the scenario's session.
struct TaskResult {
  std::string id;
  std::string kind;
  std::string status;         ///< "completed", "not-completed" or "unavailable"
  double completed_at = -1.0; ///< s, or −1
  std::string note;
};

/// Per-body summary at the end of the run.
struct BodySummary {
  std::string name;
  std::size_t nodes = 0, edges = 0, tets = 0, surface_triangles = 0;
  double max_displacement = 0.0;   ///< m
  double centre_of_mass_drop = 0.0;  ///< m, along gravity
};

/// The result of a headless session.
struct SessionReport {
  std::string package;
  long long steps = 0;
  double simulated_time = 0.0;  ///< s
  double wall_time = 0.0;       ///< s
  double time_step = 0.0;       ///< s
  int substeps = 1;
  std::vector<EnergySample> samples;
  double max_displacement = 0.0;  ///< m, over the whole run
  double max_penetration = 0.0;   ///< m, deepest contact over every sub-step of the run
  double contact_stiffness = 0.0; ///< N/m, 0 when the scene has fewer than two bodies
  std::vector<BodySummary> bodies;
  std::vector<TaskResult> tasks;
  std::string final_state_hash;
  bool has_instrument = false;
  SessionMetrics metrics;                                   ///< of the instrument, when there is one
  std::vector<std::pair<long long, std::string>> checkpoints;  ///< (step, state hash)
  std::vector<core::Vec3> inputs;                           ///< tip of step 0 … steps, when recorded
  std::vector<SessionEvent> events;
  std::string end_reason = "duration";  ///< "duration" or "perforation"
};

/// Runs `scenario` headless for options.duration seconds. Tasks of kind "settle" complete when
/// the kinetic energy stays below parameters.kinetic_energy_below (J) for parameters.hold_time
/// (s); any other kind is reported "unavailable" with the reason. Throws core::Error subclasses.
SessionReport run_headless(const core::Scenario& scenario, const HeadlessRunOptions& options,
                           core::Progress& progress = core::Progress::none());

/// The report as JSON (format "viscera-session-report", version 1).
nlohmann::json report_to_json(const SessionReport& report);

}  // namespace viscera::sim
