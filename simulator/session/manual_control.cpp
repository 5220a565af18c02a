#include "simulator/session/manual_control.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <map>

#include "core/mesh/surface_mesh.h"

namespace viscera::sim {

namespace {
/// The slot of a held motion (advance … retract loop), −1 for pedals, toggles and abort.
int held_index(ManualCommand command) {
  const int index = static_cast<int>(command);
  return index < static_cast<int>(ManualCommand::CuttingPedal) ? index : -1;
}
}  // namespace

ManualControl::ManualControl(const InstrumentState& start, ManualRates rates)
    : state_(start), rates_(rates) {
  orthonormalise(state_);
}

std::optional<ManualCommand> ManualControl::command_for_key(const std::string& key) {
  static const std::map<std::string, ManualCommand> keys = {{"w", ManualCommand::Advance},
                                                            {"Up", ManualCommand::Advance},
                                                            {"s", ManualCommand::Withdraw},
                                                            {"Down", ManualCommand::Withdraw},
                                                            {"a", ManualCommand::SwingLeft},
                                                            {"Left", ManualCommand::SwingLeft},
                                                            {"d", ManualCommand::SwingRight},
                                                            {"Right", ManualCommand::SwingRight},
                                                            {"r", ManualCommand::SwingUp},
                                                            {"f", ManualCommand::SwingDown},
                                                            {"q", ManualCommand::RollLeft},
                                                            {"e", ManualCommand::RollRight},
                                                            {"i", ManualCommand::ToggleInflow},
                                                            {"o", ManualCommand::ToggleOutflow},
                                                            {"t", ManualCommand::ExtendLoop},
                                                            {"g", ManualCommand::RetractLoop},
                                                            {"space", ManualCommand::CuttingPedal},
                                                            {"c", ManualCommand::CoagulationPedal},
                                                            {"j", ManualCommand::CloseJaws},
                                                            {"l", ManualCommand::Irrigate},
                                                            {"0", ManualCommand::ToolNone},
                                                            {"1", ManualCommand::ToolGrasper},
                                                            {"2", ManualCommand::ToolClipApplier},
                                                            {"3", ManualCommand::ToolScissors},
                                                            {"4", ManualCommand::ToolBipolar},
                                                            {"5", ManualCommand::ToolSuction},
                                                            {"6", ManualCommand::ToolHook},
                                                            {"Escape", ManualCommand::Abort},
                                                            {"x", ManualCommand::Abort}};
  const auto it = keys.find(key);
  if (it == keys.end()) return std::nullopt;
  return it->second;
}

std::string ManualControl::bindings_text() {
  return "W/S or Up/Down: advance/withdraw   A/D or Left/Right: swing left/right\n"
         "R/F: swing up/down   Q/E: roll the optics   I/O: inflow/outflow valve\n"
         "T/G: extend/retract the loop   Space: cutting pedal   C: coagulation pedal\n"
         "1 grasper  2 clip applier  3 scissors  4 bipolar  5 suction  6 hook  0 none\n"
         "J: jaws/suction   Space with the hook: cutting current   C: coagulating current\n"
         "L: irrigation (lavage) valve of the suction–irrigation cannula\n"
         "Left-drag: swing the shaft   Wheel: advance/withdraw   Esc or X: abort";
}

void ManualControl::press(ManualCommand command) {
  if (const int index = held_index(command); index >= 0) {
    held_[index] = true;
  } else if (command == ManualCommand::CuttingPedal) {
    state_.electrode = true;
  } else if (command == ManualCommand::CoagulationPedal) {
    state_.coagulation = true;
  } else if (command == ManualCommand::CloseJaws) {
    state_.jaws_closed = true;
  } else if (command == ManualCommand::Irrigate) {
    state_.irrigating = true;
  } else if (command >= ManualCommand::ToolNone && command <= ManualCommand::ToolHook) {
    // Switching opens the jaws and shuts the irrigation valve: a tool comes in through the port
    // with them open and its valves shut.
    state_.tool = static_cast<LaparoscopicTool>(static_cast<int>(command) -
                                                static_cast<int>(ManualCommand::ToolNone));
    state_.jaws_closed = false;
    state_.irrigating = false;
  } else if (command == ManualCommand::NextTool || command == ManualCommand::PreviousTool) {
    const int count = static_cast<int>(kLastLaparoscopicTool) + 1;
    const int step = command == ManualCommand::NextTool ? 1 : count - 1;
    state_.tool = static_cast<LaparoscopicTool>((static_cast<int>(state_.tool) + step) % count);
    state_.jaws_closed = false;
    state_.irrigating = false;
  } else if (command == ManualCommand::ToggleInflow) {
    state_.inflow = state_.inflow > 0.0 ? 0.0 : 1.0;
  } else if (command == ManualCommand::ToggleOutflow) {
    state_.outflow = state_.outflow > 0.0 ? 0.0 : 1.0;
  } else if (command == ManualCommand::Abort) {
    state_.abort = true;
  }
}

void ManualControl::release(ManualCommand command) {
  if (const int index = held_index(command); index >= 0) held_[index] = false;
  if (command == ManualCommand::CuttingPedal) state_.electrode = false;
  if (command == ManualCommand::CoagulationPedal) state_.coagulation = false;
  if (command == ManualCommand::CloseJaws) state_.jaws_closed = false;
  if (command == ManualCommand::Irrigate) state_.irrigating = false;
}

void ManualControl::drag(double dx, double dy) {
  swing(-dx * rates_.mouse, dy * rates_.mouse);
}

void ManualControl::wheel(int notches) {
  state_.tip += notches * rates_.wheel * state_.axis;
}

void ManualControl::swing(double yaw, double pitch) {
  const core::Vec3 side = state_.axis.cross(state_.up).normalized();
  const Eigen::AngleAxisd turn_yaw(yaw, state_.up);
  const Eigen::AngleAxisd turn_pitch(pitch, side);
  const Eigen::Matrix3d rotation = (turn_pitch * turn_yaw).toRotationMatrix();
  state_.axis = rotation * state_.axis;
  state_.up = rotation * state_.up;
  orthonormalise(state_);
}

void ManualControl::roll(double angle) {
  state_.up = Eigen::AngleAxisd(angle, state_.axis) * state_.up;
  orthonormalise(state_);
}

const InstrumentState& ManualControl::advance(double dt) {
  const auto held = [&](ManualCommand c) { return held_[static_cast<int>(c)] ? 1.0 : 0.0; };
  const auto rate = [](double keys, double analog) { return std::clamp(keys + analog, -1.0, 1.0); };
  const double along =
      rate(held(ManualCommand::Advance) - held(ManualCommand::Withdraw), analog_.advance);
  if (along != 0.0) state_.tip += along * rates_.advance * dt * state_.axis;
  const double yaw =
      rate(held(ManualCommand::SwingLeft) - held(ManualCommand::SwingRight), analog_.yaw);
  const double pitch =
      rate(held(ManualCommand::SwingUp) - held(ManualCommand::SwingDown), analog_.pitch);
  if (yaw != 0.0 || pitch != 0.0) swing(yaw * rates_.swing * dt, pitch * rates_.swing * dt);
  const double spin =
      rate(held(ManualCommand::RollLeft) - held(ManualCommand::RollRight), analog_.roll);
  if (spin != 0.0) roll(spin * rates_.roll * dt);
  const double travel = held(ManualCommand::ExtendLoop) - held(ManualCommand::RetractLoop);
  if (travel != 0.0) {
    state_.loop_extension =
        std::clamp(state_.loop_extension + travel * rates_.loop * dt, 0.0, kMaxLoopExtension);
  }
  return state_;
}

InstrumentState starting_pose(const core::Scenario& scenario, double optics_angle) {
  const auto& marks = scenario.landmarks;
  if (!marks.empty()) {
    std::size_t entry = 0;
    for (std::size_t i = 0; i < marks.size(); ++i)
      if (marks[i].id == "cervix-internal-os") entry = i;
    core::Vec3 target = core::Vec3::Zero();
    int count = 0;
    for (std::size_t i = 0; i < marks.size(); ++i) {
      if (i == entry || marks[i].id.starts_with("cervix")) continue;
      target += marks[i].position;
      ++count;
    }
    const core::Vec3 tip = marks[entry].position + 0.003 * marks[entry].normal;
    if (count > 0) {
      target /= static_cast<double>(count);
    } else {
      target = tip + (marks[entry].normal.norm() > 0.0 ? marks[entry].normal
                                                       : core::Vec3(core::Vec3::UnitZ()));
    }
    if ((target - tip).norm() > 1e-6) return look_at(tip, target, target - tip, optics_angle);
  }
  InstrumentState state;
  for (const core::SceneObject& object : scenario.objects) {
    if (object.surface.vertices.empty()) continue;
    const core::BoundingBox box = core::bounds(object.surface);
    state.tip = 0.5 * (box.min + box.max);
    break;
  }
  return state;
}

}  // namespace viscera::sim
