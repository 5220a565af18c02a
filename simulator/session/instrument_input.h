#pragma once
/// Where the instrument is and what the trainee does at each physics step of a deterministic
/// session: a scripted trajectory of timed waypoints, or the states recorded from an earlier
/// session (DESIGN.md §5: input sources of a session).

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/scenario/scenario_parts.h"
#include "simulator/session/instrument_state.h"

namespace viscera::sim {

/// Replaces the landmark places of a script by positions, so the same script drives every
/// patient a template generates (the trace keeps the resolved script, so it replays alone).
/// Wherever a waypoint's "tip" or "look_at" is an object instead of [x, y, z]:
///
///   {"landmark": "cervix-external-os", "towards": "fundus", "fraction": 0.4,
///    "along_normal": 0.008, "offset": [x, y, z], "frame": [a, b, c]}
///
/// the place is  L + fraction · (T − L) + along_normal · n_L + offset + a u + b v + c n_L,
/// with L and n_L the position and unit normal of "landmark" (the normal points away from the
/// tissue; a pathology's apex landmark's runs from its base to its apex, its base landmark's is
/// the wall's), T the position of "towards" (optional,
/// as are the others; lengths in m), and (u, v, n_L) the landmark's frame: u = n_L × ẑ made unit
/// (n_L × x̂ when n_L is vertical), v = n_L × u. A waypoint's "axis" or "up" may likewise be
/// {"landmark": id, "frame": [a, b, c]}, the direction a u + b v + c n_L. A tip place with
/// "follow": true also sets the waypoint's "tip_anchor" to L and its "tip_anchor_body" to the
/// landmark's object: the tip then moves with that tissue there (InstrumentState::follow). Throws
/// core::InputError naming `file` and the JSON pointer of a place whose landmark the scenario
/// lacks.
nlohmann::json resolve_script_landmarks(const nlohmann::json& script,
                                        const std::vector<core::Landmark>& landmarks,
                                        const std::string& file);

/// A source of instrument states, queried once per physics step.
class InstrumentInput {
 public:
  virtual ~InstrumentInput() = default;
  /// The instrument at physics step `step`, time `time` s.
  virtual InstrumentState state(long long step, double time) const = 0;
  /// Tip position in m at that step.
  core::Vec3 tip(long long step, double time) const { return state(step, time).tip; }
};

/// A scripted trajectory (issue 8: "JSON waypoints with tool and valve states"): the instrument
/// moves in straight lines between timed waypoints and rests at the last one.
///
///   {"format": "viscera-script", "version": 1 or 2, "body": "uterus", "stiffness": 200,
///    "optics_angle": 30,
///    "waypoints": [{"t": 0.0, "tip": [x, y, z], "axis": [x, y, z], "up": [x, y, z],
///                   "look_at": [x, y, z], "inflow": 1, "outflow": 0.5, "abort": false,
///                   "activate": 1, "loop_extension": 0.01}, …]}
///
/// t in s, positions in m, stiffness in N/m, optics angle in degrees. Version 1 scripts carry
/// only "tip"; "axis" (default: the previous waypoint's, or +z) and "up" set the shaft and the
/// roll of the optics, or "look_at" points the angled optics at a point (the shaft stays on the
/// side of the previous axis). "tip_anchor" [x, y, z] (m, a rest position on the body
/// "tip_anchor_body", default the tool's) makes the waypoint's tip follow the tissue there
/// (InstrumentState::follow). Valve openings are in [0, 1] and hold until changed; so does
/// "activate", the cutting pedal (0 or 1), which switches at its waypoint, and
/// "loop_extension", the resection loop's travel in front of the sheath (m, 0 … 0.02). "body"
/// names the object the tool touches (optional: the first simulated body). "tip" and "look_at"
/// may name landmarks once resolve_script_landmarks has replaced them. A laparoscopic script
/// also holds the working port's "tool" ("grasper", …), "close", "coagulate" and "irrigate"
/// (0 or 1), and the second port's tool (the left hand, SecondPort) as "left": {"tip", "axis",
/// "up", "tool", "close", "coagulate", "activate", "irrigate"} — held until a later waypoint's
/// "left" changes it, its pose blended between the waypoints that give it — or
/// {"withdraw": true}. "camera": {"tip", "look_at", "up"} (up: the picture's, default the
/// previous camera's, else +z) or {"tip", "axis", "up"} holds the
/// laparoscope apart from the working port (LaparoscopeCamera), blended the same way, or
/// {"release": true} gives the optics back to it; the first camera given holds from t = 0.
class ScriptedTrajectory final : public InstrumentInput {
 public:
  /// Parses a script; throws core::InputError naming `file` and the JSON pointer of a bad
  /// member (times must start at 0 and increase). `optics_angle` (°) serves "look_at" when the
  /// script does not state its own.
  static ScriptedTrajectory from_json(const nlohmann::json& json, const std::string& file,
                                      double optics_angle = 0.0);
  /// Reads a script file; throws core::InputError when it cannot be read or parsed.
  static ScriptedTrajectory read(const std::string& path, double optics_angle = 0.0);

  InstrumentState state(long long step, double time) const override;

  const std::string& body() const { return body_; }
  double stiffness() const { return stiffness_; }
  /// Wall thickness in m past which the tool perforates (0: no override) and force warning
  /// level in N (0: none), from the script's optional "perforation_depth" and "force_warning".
  double perforation_depth() const { return perforation_depth_; }
  double force_warning() const { return force_warning_; }
  /// Time of the last waypoint in s.
  double duration() const { return times_.back(); }

 private:
  std::string body_;
  double stiffness_ = 200.0;
  double perforation_depth_ = 0.0;
  double force_warning_ = 0.0;
  double abort_time_ = -1.0;  ///< s of the first waypoint that aborts, or −1
  std::vector<double> times_;
  std::vector<InstrumentState> states_;
};

/// The states of a recorded session as (step, state) changes: the state of step s is that of
/// the last change at or before s (the first change is at step 0, where the instrument is
/// attached); the last one holds after the end.
class RecordedInput final : public InstrumentInput {
 public:
  explicit RecordedInput(std::vector<std::pair<long long, InstrumentState>> changes);
  /// A version-1 recording: one tip per step from step 0, the shaft along +z.
  static RecordedInput from_tips(const std::vector<core::Vec3>& tips);
  InstrumentState state(long long step, double time) const override;

 private:
  std::vector<std::pair<long long, InstrumentState>> changes_;
};

}  // namespace viscera::sim
