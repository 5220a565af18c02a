#include "simulator/session/chip_retrieval.h"

#include <algorithm>
#include <memory>
#include <string>

#include "simulator/dynamics/node_reference.h"

namespace viscera::sim {

ChipRetrieval::ChipRetrieval(World& world, const InstrumentState& entry,
                             ChipRetrievalSettings settings)
    : settings_(settings), entry_tip_(entry.tip), entry_axis_(entry.axis.normalized()) {
  auto hold = std::make_unique<GraspTerm>(settings_.hold_stiffness);
  hold_ = hold.get();
  world.add_term(std::move(hold));
}

int ChipRetrieval::held_chip(const LoopResection& resection) const {
  if (!hold_->holding()) return -1;
  const NodeReference& held = hold_->held().front();
  const auto& chips = resection.chips();
  for (std::size_t c = 0; c < chips.size(); ++c) {
    if (chips[c].body != held.body) continue;
    if (std::binary_search(chips[c].nodes.begin(), chips[c].nodes.end(), held.node))
      return static_cast<int>(c);
  }
  return -1;
}

bool ChipRetrieval::try_catch(const InstrumentState& state, World& world,
                              const LoopResection& resection, double time,
                              std::vector<SessionEvent>& events) {
  const cutting::LoopPose pose = loop_pose(state);
  const double reach = resection.loop().radius + settings_.catch_reach;
  const SimulationState& s = world.state();
  for (const Chip& chip : resection.chips()) {
    const int first = s.body(chip.body).first;
    const bool within_reach = std::any_of(chip.nodes.begin(), chip.nodes.end(), [&](int n) {
      return (s.positions[static_cast<std::size_t>(first + n)] - pose.position).norm() <= reach;
    });
    if (!within_reach) continue;
    std::vector<NodeReference> held;
    for (const int n : chip.nodes)
      held.push_back(reference_node(s, chip.body, n));
    const std::size_t count = held.size();
    hold_->hold(s, std::move(held), pose.position, pose.rotation);
    world.stiffness_changed();
    events.push_back({time, "chip-caught",
                      "the loop holds a chip of " +
                          world.models()[static_cast<std::size_t>(chip.body)]->name +
                          " against the sheath (" + std::to_string(count) + " node(s))"});
    return true;
  }
  return false;
}

void ChipRetrieval::follow(const InstrumentState& state, World& world, LoopResection& resection,
                           double time, CuttingSummary& summary,
                           std::vector<SessionEvent>& events) {
  const bool drawn_back = state.loop_extension <= settings_.catch_extension;
  const bool pedal = state.electrode || state.coagulation;
  if (pedal) armed_ = false;
  if (!drawn_back && !pedal) armed_ = true;
  if (hold_->holding() && (!drawn_back || pedal || held_chip(resection) < 0)) {
    hold_->release();
    world.stiffness_changed();
    events.push_back({time, "chip-released", "the loop let go of the chip"});
  }
  if (!hold_->holding()) {
    if (armed_ && drawn_back && !resection.chips().empty() &&
        try_catch(state, world, resection, time, events))
      armed_ = false;
    return;
  }
  const cutting::LoopPose pose = loop_pose(state);
  hold_->move_jaws(pose.position, pose.rotation);
  if ((state.tip - entry_tip_).dot(entry_axis_) > 0.0) return;  // still in the cavity
  const int chip = held_chip(resection);
  hold_->release();
  world.stiffness_changed();
  resection.retrieve(static_cast<std::size_t>(chip), world, time, summary, events);
}

}  // namespace viscera::sim
