#pragma once
/// Where the instrument tip is at each physics step of a deterministic session: a scripted
/// trajectory of timed waypoints, or the tips recorded from an earlier session (DESIGN.md §5:
/// input sources of a session).

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/math_types.h"

namespace viscera::sim {

/// A source of instrument tip positions, queried once per physics step.
class InstrumentInput {
 public:
  virtual ~InstrumentInput() = default;
  /// Tip position in m for physics step `step` at time `time` s.
  virtual core::Vec3 tip(long long step, double time) const = 0;
};

/// A scripted trajectory (issue 8: "JSON waypoints with tool and valve states"): the tip moves
/// in straight lines between timed waypoints and rests at the last one.
///
///   {"format": "viscera-script", "version": 1, "body": "ball", "stiffness": 200,
///    "waypoints": [{"t": 0.0, "tip": [x, y, z]}, …]}     (t in s, tip in m, stiffness N/m)
class ScriptedTrajectory final : public InstrumentInput {
 public:
  /// Parses a script; throws core::InputError naming `file` and the JSON pointer of a bad
  /// member (times must start at 0 and increase).
  static ScriptedTrajectory from_json(const nlohmann::json& json, const std::string& file);
  /// Reads a script file; throws core::InputError when it cannot be read or parsed.
  static ScriptedTrajectory read(const std::string& path);

  core::Vec3 tip(long long step, double time) const override;

  const std::string& body() const { return body_; }
  double stiffness() const { return stiffness_; }
  /// Wall thickness in m past which the tool perforates (0: no check) and force warning level
  /// in N (0: none), from the script's optional "perforation_depth" and "force_warning".
  double perforation_depth() const { return perforation_depth_; }
  double force_warning() const { return force_warning_; }
  /// Time of the last waypoint in s.
  double duration() const { return times_.back(); }

 private:
  std::string body_;
  double stiffness_ = 200.0;
  double perforation_depth_ = 0.0;
  double force_warning_ = 0.0;
  std::vector<double> times_;
  std::vector<core::Vec3> tips_;
};

/// The tips of a recorded session: tips[s] for step s, from step 0 (where the instrument is
/// attached); the last one holds after the end.
class RecordedInput final : public InstrumentInput {
 public:
  explicit RecordedInput(std::vector<core::Vec3> tips) : tips_(std::move(tips)) {}
  core::Vec3 tip(long long step, double time) const override;

 private:
  std::vector<core::Vec3> tips_;
};

}  // namespace viscera::sim
