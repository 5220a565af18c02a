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
  static const std::map<std::string, ManualCommand> keys = {
      {"w", ManualCommand::Advance},
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
      {"Tab", ManualCommand::SwitchHand},
      {"BackSpace", ManualCommand::WithdrawSecondTool},
      {"v", ManualCommand::TakeCamera},
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
         "Tab: switch hands (the left hand's tool in the second port)   Backspace: take it out\n"
         "V: move the laparoscope (the camera) apart from the tools; Tab: back to the tools\n"
         "Left-drag: swing the shaft   Wheel: advance/withdraw   Esc or X: abort";
}

void ManualControl::press(ManualCommand command) {
  InstrumentState& tool = held_tool();
  if (const int index = held_index(command); index >= 0) {
    held_[index] = true;
  } else if (command == ManualCommand::CuttingPedal) {
    tool.electrode = true;
  } else if (command == ManualCommand::CoagulationPedal) {
    tool.coagulation = true;
  } else if (command == ManualCommand::CloseJaws) {
    tool.jaws_closed = true;
  } else if (command == ManualCommand::Irrigate) {
    tool.irrigating = true;
  } else if (command >= ManualCommand::ToolNone && command <= ManualCommand::ToolHook) {
    // Switching opens the jaws and shuts the irrigation valve: a tool comes in through the port
    // with them open and its valves shut.
    tool.tool = static_cast<LaparoscopicTool>(static_cast<int>(command) -
                                              static_cast<int>(ManualCommand::ToolNone));
    tool.jaws_closed = false;
    tool.irrigating = false;
  } else if (command == ManualCommand::NextTool || command == ManualCommand::PreviousTool) {
    const int count = static_cast<int>(kLastLaparoscopicTool) + 1;
    const int step = command == ManualCommand::NextTool ? 1 : count - 1;
    tool.tool = static_cast<LaparoscopicTool>((static_cast<int>(tool.tool) + step) % count);
    tool.jaws_closed = false;
    tool.irrigating = false;
  } else if (command == ManualCommand::SwitchHand) {
    std::fill(std::begin(held_), std::end(held_), false);  // the other hand's keys start up
    const int from = hand_ == 2 ? 1 - tool_hand_ : hand_;  // from the camera: the tool last moved
    if (from == 0 && !state_.second.inserted) {
      state_.second = second_port_entry(camera_pose(state_));
      left_ = in_port(state_, 1);
    }
    hand_ = tool_hand_ = 1 - from;
  } else if (command == ManualCommand::WithdrawSecondTool) {
    state_.second = SecondPort{};
    hand_ = tool_hand_ = 0;
  } else if (command == ManualCommand::TakeCamera) {
    std::fill(std::begin(held_), std::end(held_), false);
    camera_ = camera_pose(state_);
    state_.camera.held = true;
    hand_ = 2;
  } else if (command == ManualCommand::ToggleInflow) {
    state_.inflow = state_.inflow > 0.0 ? 0.0 : 1.0;
  } else if (command == ManualCommand::ToggleOutflow) {
    state_.outflow = state_.outflow > 0.0 ? 0.0 : 1.0;
  } else if (command == ManualCommand::Abort) {
    state_.abort = true;
  }
  sync_second();
}

void ManualControl::release(ManualCommand command) {
  InstrumentState& tool = held_tool();
  if (const int index = held_index(command); index >= 0) held_[index] = false;
  if (command == ManualCommand::CuttingPedal) tool.electrode = false;
  if (command == ManualCommand::CoagulationPedal) tool.coagulation = false;
  if (command == ManualCommand::CloseJaws) tool.jaws_closed = false;
  if (command == ManualCommand::Irrigate) tool.irrigating = false;
  sync_second();
}

void ManualControl::sync_second() {
  if (hand_ == 2) {
    state_.camera.tip = camera_.tip;
    state_.camera.axis = camera_.axis;
    state_.camera.up = camera_.up;
  }
  if (tool_hand_ == 1) state_.second = port_tool(left_);
}

void ManualControl::drag(double dx, double dy) {
  swing(-dx * rates_.mouse, dy * rates_.mouse);
  sync_second();
}

void ManualControl::wheel(int notches) {
  InstrumentState& tool = moved();
  tool.tip += notches * rates_.wheel * tool.axis;
  sync_second();
}

void ManualControl::swing(double yaw, double pitch) {
  InstrumentState& tool = moved();
  const core::Vec3 side = tool.axis.cross(tool.up).normalized();
  const Eigen::AngleAxisd turn_yaw(yaw, tool.up);
  const Eigen::AngleAxisd turn_pitch(pitch, side);
  const Eigen::Matrix3d rotation = (turn_pitch * turn_yaw).toRotationMatrix();
  tool.axis = rotation * tool.axis;
  tool.up = rotation * tool.up;
  orthonormalise(tool);
}

void ManualControl::roll(double angle) {
  InstrumentState& tool = moved();
  tool.up = Eigen::AngleAxisd(angle, tool.axis) * tool.up;
  orthonormalise(tool);
}

const InstrumentState& ManualControl::advance(double dt) {
  const auto held = [&](ManualCommand c) { return held_[static_cast<int>(c)] ? 1.0 : 0.0; };
  const auto rate = [](double keys, double analog) { return std::clamp(keys + analog, -1.0, 1.0); };
  const double along =
      rate(held(ManualCommand::Advance) - held(ManualCommand::Withdraw), analog_.advance);
  if (along != 0.0) moved().tip += along * rates_.advance * dt * moved().axis;
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
  sync_second();
  return state_;
}

SecondPort second_port_entry(const InstrumentState& laparoscope) {
  InstrumentState pose = laparoscope;
  orthonormalise(pose);
  const core::Vec3 side = pose.axis.cross(pose.up).normalized();  // the image's right
  const core::Vec3 trocar = pose.tip - 0.03 * side;
  const core::Vec3 focus = pose.tip + 0.05 * pose.axis;
  SecondPort port;
  port.inserted = true;
  port.axis = (focus - trocar).normalized();
  port.tip = trocar + 0.5 * (focus - trocar);
  port.up = pose.up - pose.up.dot(port.axis) * port.axis;
  port.up = port.up.norm() > 1e-9 ? port.up.normalized() : port.axis.unitOrthogonal();
  port.tool = LaparoscopicTool::Grasper;
  return port;
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
