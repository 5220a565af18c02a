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
/// Kinds detected when the working port carries the laparoscopic tools (LaparoscopicTools).
const std::set<std::string> kToolKinds = {"grasp", "pull", "clip", "coagulate", "cut"};
const std::set<std::string> kLaparoscopicTools = {"grasper", "clip-applier", "scissors", "bipolar",
                                                  "hook"};
const std::set<std::string> kSimulatedTools = {"hysteroscope",        "cystoscope",   "laparoscope",
                                               "resectoscope-optics", "resectoscope", "probe"};

/// The tool a task kind needs when it names none.
std::string tool_needed(const std::string& kind) {
  if (kind == "grasp" || kind == "pull") return "grasper";
  if (kind == "clip") return "clip-applier";
  if (kind == "cut") return "scissors";
  if (kind == "resect") return "resectoscope";
  if (kind == "coagulate") return "bipolar";
  return "";
}

double parameter(const core::TaskSpec& task, const char* key, double fallback) {
  const auto it = task.parameters.find(key);
  return it != task.parameters.end() && it->is_number() ? it->get<double>() : fallback;
}

}  // namespace

TaskMonitor::TaskMonitor(const core::TaskSpec& task, std::string step, std::string substep,
                         std::optional<TaskTarget> target, const std::string& missing,
                         const std::string& simulated_tool, bool laparoscopic_tools)
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
  const bool simulated =
      kSimulatedTools.contains(tool) || (laparoscopic_tools && kLaparoscopicTools.contains(tool));
  if (!tool.empty() && !simulated) {
    result_.status = "unavailable";
    // "a grasper", "a clip-applier", but "scissors".
    result_.note = "needs " + std::string(tool.ends_with('s') ? "" : "a ") + tool +
                   ", which this runtime cannot simulate yet (it simulates a rigid " +
                   simulated_tool + " with a camera and a haptic tip)";
  } else if (!kDetectedKinds.contains(task.kind) &&
             !(laparoscopic_tools && kToolKinds.contains(task.kind))) {
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

void TaskMonitor::track_best(double value, bool lower_is_better) {
  if (result_.best < 0.0 || (lower_is_better ? value < result_.best : value > result_.best))
    result_.best = value;
}

bool TaskMonitor::holds(const TaskContext& c) {
  const core::Vec3& tip = c.state.tip;
  if (spec_.kind == "reach") {
    const double d = (tip - target_->position).norm();
    track_best(d, true);
    return d <= parameter(spec_, "radius", 0.005);
  }
  if (spec_.kind == "centre-target") {
    const core::Vec3 to = target_->position - c.eye;
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
    return c.camera == nullptr || c.camera->visible(c.eye, target_->position, 0.002);
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
  if (kToolKinds.contains(spec_.kind)) return tool_task_holds(c);
  return false;
}

bool TaskMonitor::tool_task_holds(const TaskContext& c) {
  if (c.laparoscopy == nullptr) return false;
  const LaparoscopySummary& tools = *c.laparoscopy;
  // The object and site: the task's "object", else its landmark's; within "radius" m of the
  // landmark (at rest: sites are judged where the tissue belongs, not where it was pulled).
  const std::string object =
      spec_.parameters.value("object", target_ ? target_->object : std::string());
  const double radius = parameter(spec_, "radius", 0.015);
  const auto near = [&](const core::Vec3& rest) {
    return !target_ || (rest - target_->position).norm() <= radius;
  };
  if (spec_.kind == "pull") {
    // Grasped and pulled until the links at the held knots stretch by "stretch".
    if (c.grasped_rest.empty() || c.grasped_object != object) return false;
    track_best(c.grasp_stretch, false);
    return c.grasp_stretch >= parameter(spec_, "stretch", 0.2);
  }
  if (spec_.kind == "grasp") {
    if (c.grasped_object != object || c.grasped_rest.empty()) return false;
    for (const auto& p : c.grasped_rest)
      if (near(p)) return true;
    return false;
  }
  if (spec_.kind == "clip") {
    // The "count"-th secure clip on the object near the site (1 for the first clip task).
    int secure = 0;
    for (const ClipPlacement& clip : tools.clips)
      if (clip.body == object && clip.secure() && near(clip.rest_position)) ++secure;
    track_best(secure, false);
    return secure >= parameter(spec_, "count", 1.0);
  }
  if (spec_.kind == "coagulate") {
    const CoagulatedTissue* coagulated = tools.coagulated_of(object);
    if (coagulated == nullptr) return false;
    bool at_site = false;
    for (const auto& p : coagulated->rest_positions)
      at_site = at_site || near(p);
    track_best(coagulated->length, false);
    return at_site && coagulated->length >= parameter(spec_, "length", 0.004);
  }
  // cut: divided the object near the site, between two secure clips when the task says so, by
  // the tool it names (any cutting tool when it names none).
  const bool between = spec_.parameters.value("between_clips", false);
  const std::string tool = spec_.parameters.value("tool", std::string());
  for (const TissueCut& cut : tools.cuts)
    if (cut.body == object && cut.separated() && (!between || cut.between_clips) &&
        (tool.empty() || cut.tool == tool))
      return true;
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
