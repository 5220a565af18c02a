#include "simulator/session/electrosurgical_hook.h"

#include <algorithm>

namespace viscera::sim {
namespace {

double distance_to_segment(const core::Vec3& p, const core::Vec3& a, const core::Vec3& b) {
  const core::Vec3 ab = b - a;
  const double t = std::clamp((p - a).dot(ab) / std::max(ab.squaredNorm(), 1e-300), 0.0, 1.0);
  return (p - (a + t * ab)).norm();
}

}  // namespace

std::array<core::Vec3, 3> hook_wire(const InstrumentState& state, const HookOptions& options) {
  return {state.tip - options.shank * state.axis, state.tip, state.tip + options.length * state.up};
}

core::Vec3 hook_touch_point(const InstrumentState& state, const HookOptions& options) {
  return state.electrode ? hook_wire(state, options)[0] : state.tip;
}

double distance_to_hook(const core::Vec3& point, const InstrumentState& state,
                        const HookOptions& options) {
  const auto wire = hook_wire(state, options);
  return std::min(distance_to_segment(point, wire[0], wire[1]),
                  distance_to_segment(point, wire[1], wire[2]));
}

std::optional<cutting::CutSurface> HookSweep::follow(const InstrumentState& state) {
  if (state.tool != LaparoscopicTool::Hook || !state.electrode) return finish();
  const auto wire = hook_wire(state, options_);
  last_.assign(wire.begin(), wire.end());
  const bool moved =
      samples_.empty() || (wire[1] - samples_.back()[1]).norm() >= options_.sample_spacing;
  if (moved) samples_.push_back(last_);
  if (samples_.size() >= options_.max_samples) return finish();
  return std::nullopt;
}

std::optional<cutting::CutSurface> HookSweep::finish() {
  // The wire where the current last flowed closes the sweep.
  if (!samples_.empty() && last_ != samples_.back()) samples_.push_back(last_);
  std::vector<std::vector<core::Vec3>> samples;
  samples.swap(samples_);
  if (samples.size() < 2) return std::nullopt;  // the current flowed but the wire stood still
  return cutting::swept_wire_surface(samples);
}

}  // namespace viscera::sim
