#pragma once
/// What the trainee does with the instrument at one physics step: where the tip is, where the
/// shaft points, how the angled optics are rolled, the valve states, and whether the trainee
/// aborts (seed 000 §8.1: the resectoscope's sensors report valve positions and camera angle).

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "core/math_types.h"

namespace viscera::sim {

/// The instrument in the working port of a laparoscopic session (seed 001 §4.1; issue 19 §3),
/// at the same tip and shaft as the pose. `None` is the bare shaft of the optics: a probe.
enum class LaparoscopicTool : std::uint8_t {
  None,
  Grasper,
  ClipApplier,
  Scissors,
  Bipolar,
  /// a suction–irrigation cannula: "closing" opens its suction valve, `irrigating` its
  /// irrigation valve (two trumpet valves, as real ones)
  Suction,
  /// a monopolar L-hook: the cutting pedal (`electrode`) cuts what its wire sweeps through, the
  /// coagulation pedal coagulates what the wire touches (electrosurgical_hook.h)
  Hook
};
/// The last tool, for cycling through them.
inline constexpr LaparoscopicTool kLastLaparoscopicTool = LaparoscopicTool::Hook;

/// "none", "grasper", "clip-applier", "scissors", "bipolar", "suction", "hook": the names scripts,
/// traces and the procedures' task parameters use.
std::string_view tool_name(LaparoscopicTool tool);
/// The tool of that name, or nullopt.
std::optional<LaparoscopicTool> tool_from_name(std::string_view name);

/// Longest travel of a resection loop in front of the sheath, m.
inline constexpr double kMaxLoopExtension = 0.02;

/// The tool in the second instrument port of a laparoscopic session (issue 19 §3; seed 001
/// §3.1: the trainer's two instrument ports beside the laparoscope): the other hand's
/// instrument through its own trocar, with its own pose and controls. The laparoscope's working
/// port (InstrumentState's own tool) is the right hand and carries the camera; this is the
/// left hand. Empty (`inserted` false) until a script, the keyboard or a device puts a tool in.
struct SecondPort {
  bool inserted = false;                  ///< a tool is in the port, in the abdomen
  core::Vec3 tip = core::Vec3::Zero();    ///< m
  core::Vec3 axis = core::Vec3::UnitZ();  ///< shaft direction, from the handle towards the tip
  core::Vec3 up = core::Vec3::UnitY();    ///< the jaws' closing direction
  LaparoscopicTool tool = LaparoscopicTool::None;  ///< None: a blunt probe
  bool jaws_closed = false;
  bool coagulation = false;  ///< coagulation pedal (bipolar forceps, hook)
  bool electrode = false;    ///< cutting pedal (hook)
  bool irrigating = false;   ///< irrigation valve (suction–irrigation cannula)

  bool operator==(const SecondPort&) const = default;
};

/// The laparoscope held as a camera of its own (issue 19 §3; seed 001 §3.1: the trainer has two
/// instrument ports beside the laparoscope): an assistant's — or the trainee's other — hand holds
/// the optics through the umbilical trocar, apart from both tools. Not held (the default), the
/// optics are the working port's: an operating laparoscope whose tool runs through its own
/// channel, and every hysteroscope and cystoscope. Held, the view, its head light, the
/// "centre-target" tasks, the camera's coverage and the lens's steaming are the laparoscope's.
struct LaparoscopeCamera {
  bool held = false;
  core::Vec3 tip = core::Vec3::Zero();    ///< m, the objective
  core::Vec3 axis = core::Vec3::UnitZ();  ///< shaft direction, from the handle towards the tip
  core::Vec3 up = core::Vec3::UnitY();    ///< the side the angled optics look towards

  bool operator==(const LaparoscopeCamera&) const = default;
};

/// Instrument pose and controls. Positions in m; `axis` and `up` unit and orthogonal.
struct InstrumentState {
  core::Vec3 tip = core::Vec3::Zero();
  core::Vec3 axis = core::Vec3::UnitZ();  ///< shaft direction, from the handle towards the tip
  core::Vec3 up = core::Vec3::UnitY();    ///< the side the angled optics look towards
  double inflow = 0.0;                    ///< inflow valve opening, 0 (closed) … 1 (open)
  double outflow = 0.0;                   ///< outflow valve opening, 0 … 1
  bool abort = false;                     ///< the trainee ends the session
  /// The resectoscope's loop electrode is energised (the cutting pedal is down, seed 000 §5):
  /// while it is, the loop's sweep through tissue is recorded, and the cut is made once the
  /// loop has left the tissue again (LoopResection).
  bool electrode = false;
  /// m the loop stands out in front of the sheath tip along the shaft: the working element's
  /// travel. The surgeon extends the loop behind the tissue and draws it back towards the
  /// sheath to cut (seed 000 §5), so the sheath itself need not move through the tissue.
  double loop_extension = 0.0;
  /// The coagulation pedal is down: the loop, energised with a coagulating current, seals the
  /// bleeding sources it touches (seed 000 §1.1.4: a bleeding source is "stopped via unipolar
  /// coagulation").
  bool coagulation = false;
  /// The laparoscopic tool in the working port (switched during a session).
  LaparoscopicTool tool = LaparoscopicTool::None;
  /// The tool's jaws are closed (the handle squeezed): a grasper holds, a clip applier fires
  /// its clip, scissors cut, bipolar forceps press the tissue between their electrodes.
  bool jaws_closed = false;
  /// The irrigation valve of the suction–irrigation cannula is open (its second trumpet
  /// valve): the jet leaves the tip while the cannula is in the port (irrigation_jet.h).
  bool irrigating = false;
  /// How much the tip follows the tissue, 0 … 1 (a script place with "follow": a trainee who
  /// keeps the tool on what he sees, where the tissue is now): the tip is offset by
  /// `follow` × the displacement (current − rest, m) of the nodes of body `anchor_body` (empty:
  /// the instrument's) nearest `anchor`, a rest position in m. Distension moves the wall a
  /// millimetre in a few seconds, as much as a polyp's stalk is high.
  double follow = 0.0;
  core::Vec3 anchor = core::Vec3::Zero();
  std::string anchor_body = {};
  /// The second instrument port (the left hand) of a laparoscopic session.
  SecondPort second = {};
  /// The laparoscope as a camera apart from the working port (when held).
  LaparoscopeCamera camera = {};

  bool operator==(const InstrumentState&) const = default;
};

/// The instruments of a laparoscopic session: the working port (0, the right hand) and the
/// second port (1, the left hand).
inline constexpr int kInstrumentPorts = 2;

/// The tool in port `port` (0 or 1) as an instrument state of its own: port 0 is `state`; port 1
/// is `state.second`'s pose and controls with everything else at its default.
InstrumentState in_port(const InstrumentState& state, int port);
/// The inverse: `tool`'s pose and controls (tip, axis, up, tool, jaws, both pedals, irrigation)
/// as a port's tool, in the port when `inserted`.
SecondPort port_tool(const InstrumentState& tool, bool inserted = true);

/// The optics' pose as an instrument state: the held laparoscope's tip, axis and up, else
/// `state`'s own (the optics at the working port's tip); everything else at its default.
InstrumentState camera_pose(const InstrumentState& state);

/// The optics' viewing direction: the shaft axis tilted by `optics_angle` degrees towards `up`
/// (a 30° hysteroscope looks 30° off its shaft, on the side its light post marks).
core::Vec3 view_direction(const InstrumentState& state, double optics_angle);

/// Makes `axis` unit and `up` unit and orthogonal to it (Gram–Schmidt; any perpendicular when
/// they are parallel).
void orthonormalise(InstrumentState& state);

/// The pose whose angled optics look from `tip` at `target`: the view direction points at the
/// target and the shaft axis lies in the plane of that direction and `axis_hint`, tilted by the
/// optics angle away from the view. Lengths in m, angle in degrees.
InstrumentState look_at(const core::Vec3& tip, const core::Vec3& target,
                        const core::Vec3& axis_hint, double optics_angle);

/// Blends two states: positions linearly, directions by normalised linear blend, valves
/// linearly; `f` in [0, 1]. Abort is taken from `b` once f reaches 1; the electrode, the
/// coagulation, the tool, its jaws and the irrigation valve (switches, not blends) stay as in `a`
/// until then. The second port blends the same way; a port empty in `a` takes `b`'s pose (a tool
/// is put in where it is first placed) and stays empty until f reaches 1. The camera blends as
/// the second port: taken up where `b` holds it, at f = 1.
InstrumentState blend(const InstrumentState& a, const InstrumentState& b, double f);
SecondPort blend(const SecondPort& a, const SecondPort& b, double f);
LaparoscopeCamera blend(const LaparoscopeCamera& a, const LaparoscopeCamera& b, double f);

}  // namespace viscera::sim
