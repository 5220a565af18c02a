#pragma once
/// The monopolar L-hook of laparoscopic surgery (issue 17 §4): a bare wire that runs the last
/// `shank` m of the shaft to its tip and bends there through a right angle, standing `length` m
/// out along InstrumentState::up. The surgeon hooks tissue, lifts it off what lies behind, and
/// presses a pedal:
///
/// - the cutting pedal (InstrumentState::electrode; a script's `"activate": 1`, the Space key,
///   the pad's and device's cutting buttons) vaporises the tissue ahead of the wire. As with the
///   resectoscope's loop (seed 000 §5.1: the cut is "non-progressive", applied once the
///   electrode has traversed the tissue) the wire's sweep is recorded while the current flows
///   and cut into the tissue when it stops: the ruled surface between the wire's positions
///   (cutting::swept_wire_surface), through the hybrid cut of every body it crosses;
/// - the coagulation pedal (InstrumentState::coagulation) heats the knots within
///   `coagulation_reach` m of the wire, as the bipolar forceps heat those between their jaws.
///
/// Decisions where the seeds are silent: cutting current vaporises rather than pushes, so while
/// it flows the hook's contact with the tissue moves to the insulated shaft behind the bare
/// wire (touch_point()), and the wire passes through what it cuts; without current the bend of
/// the hook touches, hooks and lifts tissue. The wire is recorded every `sample_spacing` m of
/// travel of its bend (and where the current stops), so a slow stroke does not grow the cut
/// surface without bound.

#include <array>
#include <optional>
#include <vector>

#include "core/math_types.h"
#include "simulator/cutting/cut_surface.h"
#include "simulator/session/instrument_state.h"

namespace viscera::sim {

struct HookOptions {
  double shank = 0.003;          ///< m of bare wire along the shaft behind the bend (5 mm L-hooks)
  double length = 0.004;         ///< m the hook stands out across the shaft
  double sample_spacing = 2e-4;  ///< m of the bend's travel between recorded wire positions
  /// m from the wire within which knots heat: the thermal spread of monopolar coagulation
  /// (2–5 mm), and no less than the laparoscopy nets' knot rings lie apart
  double coagulation_reach = 3e-3;
  std::size_t max_samples = 2000;  ///< a stroke longer than this is cut where it stands
};

/// The hook's wire at `state`: the start of the bare shank, the bend (the instrument's tip) and
/// the end of the hook, in m.
std::array<core::Vec3, 3> hook_wire(const InstrumentState& state, const HookOptions& options);

/// Where the hook touches tissue at `state`: its bend, or with cutting current the end of the
/// insulated shaft behind the bare wire.
core::Vec3 hook_touch_point(const InstrumentState& state, const HookOptions& options);

/// m, the distance from `point` to the hook's wire at `state`.
double distance_to_hook(const core::Vec3& point, const InstrumentState& state,
                        const HookOptions& options);

/// The sweep of the hook's wire under cutting current.
class HookSweep {
 public:
  explicit HookSweep(HookOptions options = {}) : options_(options) {}
  /// After a step with the instrument in `state`: records the wire while the hook is in the
  /// port with cutting current; returns the swept surface when the current stops (the pedal
  /// released, or the hook taken out of the port) after the wire moved, or when the stroke
  /// reached `max_samples`; nullopt otherwise.
  std::optional<cutting::CutSurface> follow(const InstrumentState& state);
  /// True while the current flows and the sweep records.
  bool recording() const { return !samples_.empty(); }
  const HookOptions& options() const { return options_; }

 private:
  std::optional<cutting::CutSurface> finish();

  HookOptions options_;
  std::vector<std::vector<core::Vec3>> samples_;
  std::vector<core::Vec3> last_;  ///< the wire at the last step with current
};

}  // namespace viscera::sim
