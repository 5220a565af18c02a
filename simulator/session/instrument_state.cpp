#include "simulator/session/instrument_state.h"

#include <array>
#include <cmath>
#include <numbers>

namespace viscera::sim {
namespace {

constexpr std::array<std::string_view, 7> kToolNames = {
    "none", "grasper", "clip-applier", "scissors", "bipolar", "suction", "hook"};

double radians(double degrees) {
  return degrees * std::numbers::pi / 180.0;
}

core::Vec3 any_perpendicular(const core::Vec3& v) {
  const core::Vec3 other = std::abs(v.x()) < 0.9 ? core::Vec3::UnitX() : core::Vec3::UnitY();
  return v.cross(other).normalized();
}

}  // namespace

core::Vec3 view_direction(const InstrumentState& s, double optics_angle) {
  const double a = radians(optics_angle);
  return (std::cos(a) * s.axis + std::sin(a) * s.up).normalized();
}

void orthonormalise(InstrumentState& s) {
  s.axis = s.axis.norm() > 0.0 ? core::Vec3(s.axis.normalized()) : core::Vec3::UnitZ();
  core::Vec3 up = s.up - s.up.dot(s.axis) * s.axis;
  s.up = up.norm() > 1e-9 ? core::Vec3(up.normalized()) : any_perpendicular(s.axis);
}

InstrumentState look_at(const core::Vec3& tip, const core::Vec3& target,
                        const core::Vec3& axis_hint, double optics_angle) {
  InstrumentState s;
  s.tip = tip;
  const core::Vec3 view = (target - tip).normalized();
  core::Vec3 side = axis_hint - axis_hint.dot(view) * view;  // towards the hint, across the view
  side = side.norm() > 1e-9 ? core::Vec3(side.normalized()) : any_perpendicular(view);
  const double a = radians(optics_angle);
  s.axis = std::cos(a) * view + std::sin(a) * side;
  // The optics tilt from the axis towards the view: up is the view's component across the axis.
  s.up = (view - view.dot(s.axis) * s.axis);
  if (s.up.norm() < 1e-9) s.up = -side;
  orthonormalise(s);
  return s;
}

std::string_view tool_name(LaparoscopicTool tool) {
  return kToolNames[static_cast<std::size_t>(tool)];
}

std::optional<LaparoscopicTool> tool_from_name(std::string_view name) {
  for (std::size_t i = 0; i < kToolNames.size(); ++i)
    if (kToolNames[i] == name) return static_cast<LaparoscopicTool>(i);
  return std::nullopt;
}

InstrumentState blend(const InstrumentState& a, const InstrumentState& b, double f) {
  InstrumentState s;
  s.tip = (1.0 - f) * a.tip + f * b.tip;
  s.axis = (1.0 - f) * a.axis + f * b.axis;
  s.up = (1.0 - f) * a.up + f * b.up;
  s.inflow = (1.0 - f) * a.inflow + f * b.inflow;
  s.outflow = (1.0 - f) * a.outflow + f * b.outflow;
  s.abort = f >= 1.0 && b.abort;
  s.electrode = f >= 1.0 ? b.electrode : a.electrode;
  s.coagulation = f >= 1.0 ? b.coagulation : a.coagulation;
  s.tool = f >= 1.0 ? b.tool : a.tool;
  s.jaws_closed = f >= 1.0 ? b.jaws_closed : a.jaws_closed;
  s.irrigating = f >= 1.0 ? b.irrigating : a.irrigating;
  s.loop_extension = (1.0 - f) * a.loop_extension + f * b.loop_extension;
  // The displacement field is smooth, so blending the anchors blends the offsets; a state that
  // does not follow lends the other its anchor.
  s.follow = (1.0 - f) * a.follow + f * b.follow;
  // Between two bodies the tip follows the nearer waypoint's.
  if (a.follow > 0.0 && b.follow > 0.0 && a.anchor_body == b.anchor_body) {
    s.anchor = (1.0 - f) * a.anchor + f * b.anchor;
    s.anchor_body = a.anchor_body;
  } else {
    const bool from_a = b.follow > 0.0 ? a.follow > 0.0 && f < 0.5 : true;
    s.anchor = from_a ? a.anchor : b.anchor;
    s.anchor_body = from_a ? a.anchor_body : b.anchor_body;
  }
  s.second = blend(a.second, b.second, f);
  s.camera = blend(a.camera, b.camera, f);
  orthonormalise(s);
  return s;
}

namespace {

/// A pose that is taken up or put down: switches from `a` until f reaches 1; a pose absent in
/// `a` (`present` false) takes `b`'s and stays absent until then.
template <typename Pose>
Pose blend_pose(const Pose& a, const Pose& b, double f, bool Pose::*present) {
  if (!(a.*present)) {
    Pose s = b;
    s.*present = f >= 1.0 && b.*present;
    return s;
  }
  Pose s = f >= 1.0 ? b : a;  // the switches
  if (!(b.*present)) return s;
  s.tip = (1.0 - f) * a.tip + f * b.tip;
  s.axis = ((1.0 - f) * a.axis + f * b.axis).normalized();
  s.up = (1.0 - f) * a.up + f * b.up;
  s.up = (s.up - s.up.dot(s.axis) * s.axis).normalized();
  return s;
}

}  // namespace

SecondPort blend(const SecondPort& a, const SecondPort& b, double f) {
  return blend_pose(a, b, f, &SecondPort::inserted);
}

LaparoscopeCamera blend(const LaparoscopeCamera& a, const LaparoscopeCamera& b, double f) {
  return blend_pose(a, b, f, &LaparoscopeCamera::held);
}

SecondPort port_tool(const InstrumentState& tool, bool inserted) {
  SecondPort port;
  port.inserted = inserted;
  port.tip = tool.tip;
  port.axis = tool.axis;
  port.up = tool.up;
  port.tool = tool.tool;
  port.jaws_closed = tool.jaws_closed;
  port.coagulation = tool.coagulation;
  port.electrode = tool.electrode;
  port.irrigating = tool.irrigating;
  return port;
}

InstrumentState camera_pose(const InstrumentState& state) {
  InstrumentState s;
  s.tip = state.camera.held ? state.camera.tip : state.tip;
  s.axis = state.camera.held ? state.camera.axis : state.axis;
  s.up = state.camera.held ? state.camera.up : state.up;
  return s;
}

InstrumentState in_port(const InstrumentState& state, int port) {
  if (port == 0) return state;
  InstrumentState s;
  s.tip = state.second.tip;
  s.axis = state.second.axis;
  s.up = state.second.up;
  s.tool = state.second.tool;
  s.jaws_closed = state.second.jaws_closed;
  s.coagulation = state.second.coagulation;
  s.electrode = state.second.electrode;
  s.irrigating = state.second.irrigating;
  return s;
}

}  // namespace viscera::sim
