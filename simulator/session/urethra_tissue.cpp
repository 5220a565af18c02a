#include "simulator/session/urethra_tissue.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "core/sha256.h"

namespace viscera::sim {

namespace {

/// Pitch θx (towards +y) and yaw θy (towards +x) of a unit shaft axis (seed 002 §5.1).
void angles_of(const core::Vec3& axis, double& pitch, double& yaw) {
  const core::Vec3 a = axis.normalized();
  pitch = std::asin(std::clamp(a.y(), -1.0, 1.0));
  yaw = std::atan2(a.x(), a.z());
}

/// Signed roll (rad) that turns `from` into `to` about `axis`, both projected normal to it.
double roll_between(const core::Vec3& from, const core::Vec3& to, const core::Vec3& axis) {
  const core::Vec3 n = axis.normalized();
  const core::Vec3 a = from - from.dot(n) * n, b = to - to.dot(n) * n;
  if (a.norm() < 1e-12 || b.norm() < 1e-12) return 0.0;
  return std::atan2(a.cross(b).dot(n), a.dot(b));
}

void append(std::string& bytes, double v) {
  char raw[sizeof(double)];
  std::memcpy(raw, &v, sizeof v);
  bytes.append(raw, sizeof raw);
}

}  // namespace

UrethraParameters urethra_parameters(const core::UrethraLatticeSpec& spec) {
  UrethraParameters p;
  p.curvature = spec.curvature;
  p.length = spec.length;
  p.radius = spec.radius;
  p.points_per_section = spec.points_per_section;
  p.basic_sections = spec.sections;
  p.endoscope_radius = spec.endoscope_radius;
  p.spring_stiffness = spec.spring_stiffness;
  p.friction = spec.friction;
  p.viscous_friction = spec.viscous_friction;
  p.break_force = spec.break_force;
  p.break_torque = spec.break_torque;
  return p;
}

UrethraTissue::UrethraTissue(const core::UrethraLatticeSpec& spec, const InstrumentState& start)
    : name_(spec.object), model_(urethra_parameters(spec)), last_(start) {
  endoscope_.tip = start.tip;
  angles_of(start.axis, endoscope_.pitch, endoscope_.yaw);
  feedback_ = model_.feedback(endoscope_);
}

void UrethraTissue::move(const InstrumentState& state, double dt) {
  endoscope_.tip = state.tip;
  angles_of(state.axis, endoscope_.pitch, endoscope_.yaw);
  endoscope_.velocity = (state.tip - last_.tip) / dt;
  endoscope_.spin_rate = roll_between(last_.up, state.up, state.axis) / dt;
  last_ = state;
  feedback_ = model_.feedback(endoscope_);
}

std::optional<TissueEvent> UrethraTissue::complication() {
  const double limit = model_.parameters().break_force;
  const double torque = model_.parameters().break_torque;
  if (feedback_.bar_force >= 1.0) {
    return TissueEvent{"perforation", "the axial force of " +
                                          std::to_string(limit * feedback_.bar_force) +
                                          " N exceeded the urethra's break force of " +
                                          std::to_string(limit) + " N"};
  }
  const double bar = std::max({feedback_.bar_tx, feedback_.bar_ty, feedback_.bar_tz});
  if (bar >= 1.0) {
    return TissueEvent{"tissue-tear", "a torque of " + std::to_string(torque * bar) +
                                          " N·m exceeded the urethra's break torque of " +
                                          std::to_string(torque) + " N·m"};
  }
  return std::nullopt;
}

std::vector<TissueEvent> UrethraTissue::warnings() {
  std::vector<TissueEvent> out;
  std::set<std::string> now(feedback_.warnings.begin(), feedback_.warnings.end());
  for (const auto& w : now) {
    if (!active_warnings_.contains(w)) out.push_back({"force-warning", w});
  }
  active_warnings_ = std::move(now);
  return out;
}

std::string UrethraTissue::state_hash() const {
  std::string bytes;
  for (int i = 0; i < 3; ++i)
    append(bytes, endoscope_.tip[i]);
  for (int i = 0; i < 3; ++i)
    append(bytes, endoscope_.velocity[i]);
  append(bytes, endoscope_.pitch);
  append(bytes, endoscope_.yaw);
  append(bytes, endoscope_.spin_rate);
  for (int i = 0; i < 3; ++i)
    append(bytes, feedback_.force[i]);
  append(bytes, feedback_.normal_force);
  append(bytes, feedback_.torque_x);
  append(bytes, feedback_.torque_y);
  append(bytes, feedback_.torque_z);
  return core::sha256_hex(bytes);
}

}  // namespace viscera::sim
