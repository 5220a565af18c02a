#include "simulator/session/task_monitor.h"

#include <cmath>
#include <numbers>
#include <set>

#include "simulator/camera/surface_coverage.h"
#include "simulator/session/session_report.h"

namespace viscera::sim {
namespace {

/// Task kinds this runtime detects, and the tools it simulates (a rigid endoscope or probe:
/// one shaft whose tip carries the haptic proxy and the camera).
const std::set<std::string> kDetectedKinds = {
    "reach", "centre-target", "inspect-surface", "withdraw", "touch", "settle", "resect"};
const std::set<std::string> kSimulatedTools = {"hysteroscope",        "cystoscope",   "laparoscope",
                                               "resectoscope-optics", "resectoscope", "probe"};

/// The tool a task kind needs when it names none.
std::string tool_needed(const std::string& kind) {
  if (kind == "grasp" || kind == "pull") return "grasper";
  if (kind == "clip") return "clip-applier";
  if (kind == "cut") return "scissors";
  if (kind == "resect") return "resectoscope";
  return "";
}

double parameter(const core::TaskSpec& task, const char* key, double fallback) {
  const auto it = task.parameters.find(key);
  return it != task.parameters.end() && it->is_number() ? it->get<double>() : fallback;
}

}  // namespace

TaskMonitor::TaskMonitor(const core::TaskSpec& task, std::string step, std::string substep,
                         std::optional<TaskTarget> target, const std::string& missing,
                         const std::string& simulated_tool)
    : spec_(task), target_(std::move(target)) {
  if (!spec_.parameters.is_object())
    spec_.parameters = nlohmann::json::object();  // `{}` in C++ is null
  result_.id = task.id;
  result_.name = task.name;
  result_.kind = task.kind;
  result_.step = std::move(step);
  result_.substep = std::move(substep);
  hold_time_ = parameter(task, "hold_time", 0.0);
  const std::string tool = spec_.parameters.value("tool", tool_needed(task.kind));
  if (!tool.empty() && !kSimulatedTools.contains(tool)) {
    result_.status = "unavailable";
    // "a grasper", "a clip-applier", but "scissors".
    result_.note = "needs " + std::string(tool.ends_with('s') ? "" : "a ") + tool +
                   ", which this runtime cannot simulate yet (it simulates a rigid " +
                   simulated_tool + " with a camera and a haptic tip)";
  } else if (!kDetectedKinds.contains(task.kind)) {
    result_.status = "unavailable";
    result_.note = "tasks of kind \"" + task.kind + "\" cannot be detected by this runtime";
  } else if (!missing.empty()) {
    result_.status = "unavailable";
    result_.note = missing;
  }
}

void TaskMonitor::complete(const TaskContext& c, const std::string& note) {
  result_.status = "completed";
  result_.completed_at = c.time;
  result_.completed_tip = c.state.tip;
  result_.note = note;
}

bool TaskMonitor::holds(const TaskContext& c) {
  const core::Vec3& tip = c.state.tip;
  const auto track_best = [this](double value, bool lower_is_better) {
    if (result_.best < 0.0 || (lower_is_better ? value < result_.best : value > result_.best))
      result_.best = value;
  };
  if (spec_.kind == "reach") {
    const double d = (tip - target_->position).norm();
    track_best(d, true);
    return d <= parameter(spec_, "radius", 0.005);
  }
  if (spec_.kind == "centre-target") {
    const core::Vec3 to = target_->position - tip;
    const double distance = to.norm();
    if (distance < 1e-9) return false;
    const double angle =
        std::acos(std::clamp(c.view.dot(to / distance), -1.0, 1.0)) * 180.0 / std::numbers::pi;
    track_best(angle, true);
    if (angle > parameter(spec_, "max_angle", 10.0)) return false;
    if (distance < parameter(spec_, "min_distance", 0.0) ||
        distance > parameter(spec_, "max_distance", 0.05))
      return false;
    // A centred orifice behind a fold of the wall is not seen.
    return c.camera == nullptr || c.camera->visible(tip, target_->position, 0.002);
  }
  if (spec_.kind == "inspect-surface") {
    track_best(c.fraction_seen, false);
    return c.fraction_seen >= parameter(spec_, "fraction", 0.8);
  }
  if (spec_.kind == "withdraw") {
    // The landmark's normal points out of the body: out past the plane by the margin, after
    // having been inside it.
    const core::Vec3 out =
        target_->normal.norm() > 0.0 ? target_->normal : core::Vec3(-c.state.axis);
    const double height = (tip - target_->position).dot(out);
    if (height < 0.0) was_inside_ = true;
    return was_inside_ && height >= parameter(spec_, "margin", 0.005);
  }
  if (spec_.kind == "touch") {
    const std::string object = spec_.parameters.value("object", std::string());
    const bool touching = c.in_contact && (object.empty() || object == c.contact_object);
    if (touching) track_best(c.force, false);
    return touching && c.force >= parameter(spec_, "min_force", 0.0) &&
           c.force <= parameter(spec_, "max_force", std::numeric_limits<double>::infinity());
  }
  if (spec_.kind == "settle")
    return c.kinetic_energy < parameter(spec_, "kinetic_energy_below", 1e-6);
  if (spec_.kind == "resect") {
    // The named pathology's resected fraction (chips: fragments that lost every anchor).
    if (c.cutting == nullptr) return false;
    const auto named = spec_.parameters.find("object");
    const std::string object =
        named != spec_.parameters.end() && named->is_string() ? named->get<std::string>() : "";
    const BodyResection* b = c.cutting->find(object);
    if (b == nullptr) return false;
    track_best(b->resected_fraction(), false);
    return b->resected_fraction() >= parameter(spec_, "fraction", 0.9);
  }
  return false;
}

void TaskMonitor::update(const TaskContext& c) {
  if (done()) return;
  if (!c.instrument_moved && spec_.kind != "settle") {
    holding_since_ = -1.0;
    return;
  }
  if (!holds(c)) {
    holding_since_ = -1.0;
    return;
  }
  if (holding_since_ < 0.0) holding_since_ = c.time;
  if (c.time - holding_since_ >= hold_time_ - 1e-12) complete(c, "");
}

}  // namespace viscera::sim
