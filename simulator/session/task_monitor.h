#pragma once
/// Detects the completion of one procedure task from tool and camera state (seed 000 §11: low-
/// level activities "are only used to evaluate the completion of a task"). Task kinds and their
/// parameters are listed in core/scenario/procedure.h.

#include <optional>
#include <string>

#include "core/scenario/scenario_parts.h"
#include "simulator/session/instrument_state.h"
#include "simulator/session/laparoscopy_summary.h"

namespace viscera::sim {

class SurfaceCoverage;

/// A point a task refers to: a landmark or an explicit position. m, unit normal or zero.
struct TaskTarget {
  core::Vec3 position = core::Vec3::Zero();
  core::Vec3 normal = core::Vec3::Zero();
  std::string object;  ///< the object a landmark lies on, or ""
};

/// The session as a task sees it at one moment.
struct CuttingSummary;  // session_report.h

struct TaskContext {
  double time = 0.0;  ///< s
  InstrumentState state;
  core::Vec3 eye = core::Vec3::Zero();    ///< m, the optics' objective (camera_pose(state).tip)
  core::Vec3 view = core::Vec3::UnitZ();  ///< unit viewing direction of the optics
  bool in_contact = false;
  std::string contact_object;               ///< object the tool touches, when in contact
  double force = 0.0;                       ///< N on the instrument
  double kinetic_energy = 0.0;              ///< J, all bodies
  const SurfaceCoverage* camera = nullptr;  ///< for lines of sight, or null
  /// Fraction of the surface region seen, for inspect-surface tasks (set per task by the session).
  double fraction_seen = 0.0;
  /// The trainee has moved the instrument since the session began. Tasks of the instrument
  /// (reach, centre-target, inspect-surface, withdraw, touch) complete only then: a condition
  /// that holds at the starting pose alone is not the trainee's work.
  bool instrument_moved = true;
  /// The resection loop's cuts so far, or null when the instrument cannot cut ("resect" tasks).
  const CuttingSummary* cutting = nullptr;
  /// What the laparoscopic tools did so far, or null without them (grasp, clip, coagulate and
  /// cut tasks).
  const LaparoscopySummary* laparoscopy = nullptr;
  /// The object the grasper holds now and the rest positions (m) of the knots it holds.
  std::string grasped_object;
  std::vector<core::Vec3> grasped_rest;
  /// The largest strain of the links at the held knots (LaparoscopicTools::grasp_stretch).
  double grasp_stretch = 0.0;
};

/// What became of a task. Status "completed", "not-completed" or "unavailable".
struct TaskResult {
  std::string id;
  std::string name;
  std::string kind;
  std::string step;  ///< id of the step it belongs to, or "" for loose tasks
  std::string substep;
  std::string status = "not-completed";
  double completed_at = -1.0;  ///< s, or −1
  std::string note;            ///< why unavailable, or how it was judged
  double best = -1.0;  ///< closest approach: m (reach), ° (centre-target), fraction (inspect)
  core::Vec3 completed_tip = core::Vec3::Zero();  ///< where the tool was when it completed
};

/// Watches one task.
class TaskMonitor {
 public:
  /// `target` is the resolved landmark or position (nullopt when the task has none or it
  /// could not be resolved: `missing` says why, and the task is unavailable). `simulated_tool`
  /// is the kind of instrument the session simulates; with `laparoscopic_tools` its working
  /// port also carries the grasper, clip applier, scissors and bipolar forceps.
  TaskMonitor(const core::TaskSpec& task, std::string step, std::string substep,
              std::optional<TaskTarget> target, const std::string& missing,
              const std::string& simulated_tool, bool laparoscopic_tools = false);

  /// Looks at the session; completes the task when its condition has held long enough.
  void update(const TaskContext& context);

  const TaskResult& result() const { return result_; }
  bool done() const { return result_.status != "not-completed"; }
  const core::TaskSpec& spec() const { return spec_; }

 private:
  bool holds(const TaskContext& context);
  /// Grasp, clip, coagulate and cut tasks, from what the laparoscopic tools did.
  bool tool_task_holds(const TaskContext& context);
  /// Keeps the closest approach in result_.best.
  void track_best(double value, bool lower_is_better);
  void complete(const TaskContext& context, const std::string& note);

  core::TaskSpec spec_;
  TaskResult result_;
  std::optional<TaskTarget> target_;
  double hold_time_ = 0.0;
  double holding_since_ = -1.0;
  bool was_inside_ = false;  ///< withdraw: the tool has been past the plane inwards
};

}  // namespace viscera::sim
