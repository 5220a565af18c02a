#include "simulator/session/loop_resection.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/error.h"
#include "simulator/cutting/fragments.h"
#include "simulator/session/cut_topology.h"
#include "simulator/session/cut_under_base.h"
#include "simulator/session/retired_tissue.h"
#include "simulator/session/severed_pieces.h"

namespace viscera::sim {

namespace {

/// A tenth of the radius, or 5°, between recorded poses of the sweep.
constexpr double kPoseSpacingOfRadius = 0.1;
const double kPoseTurnCosine = std::cos(5.0 * std::numbers::pi / 180.0);

struct Box {
  core::Vec3 lo = core::Vec3::Constant(std::numeric_limits<double>::infinity());
  core::Vec3 hi = -core::Vec3::Constant(std::numeric_limits<double>::infinity());
  void add(const core::Vec3& p) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  bool overlaps(const Box& o) const {
    return (lo.array() <= o.hi.array()).all() && (o.lo.array() <= hi.array()).all();
  }
};

}  // namespace

cutting::LoopElectrode standard_resection_loop() {
  cutting::LoopElectrode loop;
  loop.radius = 0.0025;
  loop.arc_radians = std::numbers::pi;
  loop.segments = 12;
  return loop;
}

cutting::LoopPose loop_pose(const InstrumentState& state) {
  cutting::LoopPose pose;
  pose.position = state.tip + state.loop_extension * state.axis.normalized();
  const core::Vec3 z = state.axis.normalized();
  const core::Vec3 y = -(state.up - state.up.dot(z) * z).normalized();  // hangs towards up
  pose.rotation.col(0) = y.cross(z);
  pose.rotation.col(1) = y;
  pose.rotation.col(2) = z;
  return pose;
}

LoopResection::LoopResection(const World& world, std::vector<int> bodies,
                             cutting::LoopElectrode loop)
    : bodies_(std::move(bodies)), loop_(loop) {
  for (const int b : bodies_) {
    initial_volume_.push_back(
        core::total_volume(world.models()[static_cast<std::size_t>(b)]->mesh));
    const auto held = world.held_nodes(b);
    held_at_start_.push_back(std::find(held.begin(), held.end(), std::uint8_t{1}) != held.end());
  }
  removed_volume_.assign(bodies_.size(), 0.0);
}

void LoopResection::record_pose(const InstrumentState& state) {
  const cutting::LoopPose pose = loop_pose(state);
  if (!sweep_.empty()) {
    const cutting::LoopPose& last = sweep_.back();
    const bool moved =
        (pose.position - last.position).norm() >= kPoseSpacingOfRadius * loop_.radius;
    const bool turned = pose.rotation.col(2).dot(last.rotation.col(2)) < kPoseTurnCosine ||
                        pose.rotation.col(1).dot(last.rotation.col(1)) < kPoseTurnCosine;
    if (!moved && !turned) return;
  }
  sweep_.push_back(pose);
}

void LoopResection::follow(const InstrumentState& state, World& world, double time,
                           CuttingSummary& summary, std::vector<SessionEvent>& events) {
  if (state.electrode) {
    if (!sweeping_) sweep_.clear();
    sweeping_ = true;
    record_pose(state);
    return;
  }
  if (!sweeping_) return;
  sweeping_ = false;
  // The pose at release ends the sweep, however little it moved since the last one kept.
  const cutting::LoopPose last = loop_pose(state);
  if (sweep_.empty() || (sweep_.back().position - last.position).norm() > 0.0)
    sweep_.push_back(last);
  cut(world, time, summary, events);
  sweep_.clear();
}

void LoopResection::cut(World& world, double time, CuttingSummary& summary,
                        std::vector<SessionEvent>& events) {
  cutting::CutSurface surface;
  try {
    surface = cutting::swept_loop_surface(loop_, sweep_);
  } catch (const core::InputError&) {
    return;  // the loop did not move while the pedal was down: nothing was swept
  }
  ++summary.sweeps;
  last_sweep_ = surface;
  Box swept;
  for (const auto& v : surface.vertices)
    swept.add(v);
  for (std::size_t k = 0; k < bodies_.size(); ++k) {
    const int b = bodies_[k];
    const BodyModel& model = *world.models()[static_cast<std::size_t>(b)];
    const auto positions = world.state().range(world.state().positions, b);
    const std::vector<core::Vec3> current(positions.begin(), positions.end());
    Box body;
    for (const auto& p : current)
      body.add(p);
    if (!swept.overlaps(body)) continue;
    try {
      cutting::require_sweep_leaves_tissue(model.mesh, current, loop_, sweep_);
    } catch (const core::InputError&) {
      ++summary.released_in_tissue;
      events.push_back({time, "cut-released-in-tissue",
                        "the pedal came up with the loop inside " + model.name +
                            ": no cut (a cut is made once the loop has left the tissue)"});
      continue;
    }
    const auto start = std::chrono::steady_clock::now();
    const cutting::TopologyChange change =
        visible_ != nullptr ? visible_->cut(b, model.mesh, current, surface, options_)
                            : cutting::hybrid_cut(model.mesh, current, surface, options_);
    const cutting::CutStatistics& s = change.statistics;
    if (change.changed) {
      world.topology_changed(b, topology_of_cut(change, world.held_nodes(b)));
      ++summary.cuts;
      summary.tets_created +=
          static_cast<long long>(s.tets_after) - static_cast<long long>(s.tets_before);
      summary.min_dihedral_before_degrees =
          std::min(summary.min_dihedral_before_degrees, s.min_dihedral_before_degrees);
      summary.min_dihedral_after_degrees =
          std::min(summary.min_dihedral_after_degrees, s.min_dihedral_after_degrees);
      summary.volume_after += s.rest_volume_after - s.rest_volume_before;
    }
    // The loop drawn under the base cuts the pathology's hold on the wall (cut_under_base.h).
    const int under = release_cut_under(world, b, surface);
    if (change.changed) {  // the cut's time includes the rebuild after cutting under the base
      summary.cut_seconds.push_back(
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }
    if (!change.changed && under == 0) continue;
    if (under > 0) {
      events.push_back({time, "cut-under-base",
                        "the loop passed under " + std::to_string(under) + " node(s) of " +
                            model.name + "'s base: their hold on the wall is cut"});
    }

    // Chips: the pieces cut off from every hold (severed_pieces.h).
    const core::TetMesh& cut_mesh = world.models()[static_cast<std::size_t>(b)]->mesh;
    BodyResection& resection = summary.bodies[k];
    resection.resected_volume = 0.0;
    resection.chips = 0;
    std::erase_if(chips_, [b](const Chip& chip) { return chip.body == b; });
    std::vector<cutting::Fragment> shreds;
    for (cutting::Fragment& chip :
         severed_fragments(cut_mesh, world.held_nodes(b), lost_every_hold(world, b))) {
      resection.resected_volume += chip.rest_volume;
      if (debris_sink_ && chip.rest_volume < debris_volume_) {
        shreds.push_back(std::move(chip));
        continue;
      }
      ++resection.chips;
      chips_.push_back({b, chip.nodes, chip.rest_volume});
    }
    resection.resected_volume += removed_volume_[k];              // the debris of earlier cuts
    if (observer_ && change.changed) observer_(b, change, time);  // the chips are known
    if (!shreds.empty()) shed(world, b, k, shreds, resection);
    events.push_back(
        {time, "cut",
         "the loop cut " + model.name + ": " +
             std::to_string(change.changed ? s.tets_traversed : 0) + " tets traversed, " +
             std::to_string(resection.chips) + " chip(s), " +
             (shreds.empty() ? std::string()
                             : std::to_string(shreds.size()) + " shred(s) of debris, ") +
             std::to_string(std::lround(100.0 * resection.resected_fraction())) + " % resected"});
  }
}

void LoopResection::shed(World& world, int body, std::size_t k,
                         const std::vector<cutting::Fragment>& shreds, BodyResection& resection) {
  const auto positions = world.state().range(world.state().positions, body);
  for (const cutting::Fragment& shred : shreds) {
    debris_sink_(fragment_centre(shred, positions), equivalent_radius(shred.rest_volume));
    removed_volume_[k] += shred.rest_volume;
    ++resection.debris;
  }
  remove(world, body, shreds);
}

void LoopResection::remove(World& world, int body,
                           const std::vector<cutting::Fragment>& fragments) {
  const BodyTopology topology = topology_without(world, body, fragments);
  if (visible_ != nullptr) visible_->retire(body, topology);
  world.topology_changed(body, topology);
}

void LoopResection::retrieve(std::size_t chip, World& world, double time, CuttingSummary& summary,
                             std::vector<SessionEvent>& events) {
  const Chip taken = chips_.at(chip);
  const auto k = static_cast<std::size_t>(std::find(bodies_.begin(), bodies_.end(), taken.body) -
                                          bodies_.begin());
  const core::TetMesh& mesh = world.models()[static_cast<std::size_t>(taken.body)]->mesh;
  std::vector<cutting::Fragment> pieces =
      severed_fragments(mesh, world.held_nodes(taken.body), lost_every_hold(world, taken.body));
  std::erase_if(pieces, [&](const cutting::Fragment& piece) {
    return !std::binary_search(piece.nodes.begin(), piece.nodes.end(), taken.nodes.front());
  });
  if (pieces.empty()) return;  // not a piece of its own any more
  removed_volume_[k] += pieces.front().rest_volume;
  BodyResection& resection = summary.bodies[k];
  resection.chips = std::max(0, resection.chips - 1);
  ++resection.chips_retrieved;
  resection.retrieved_volume += pieces.front().rest_volume;
  chips_.erase(chips_.begin() + static_cast<std::ptrdiff_t>(chip));
  remove(world, taken.body, pieces);
  events.push_back({time, "chip-retrieved",
                    "a chip of " + resection.body + " (" +
                        std::to_string(std::lround(pieces.front().rest_volume * 1e9)) +
                        " mm³) was taken out through the cervix; " +
                        std::to_string(resection.chips) + " left in the cavity"});
}

bool LoopResection::lost_every_hold(const World& world, int body) const {
  const auto k =
      static_cast<std::size_t>(std::find(bodies_.begin(), bodies_.end(), body) - bodies_.begin());
  if (k >= bodies_.size() || held_at_start_[k] == 0) return false;
  const auto held = world.held_nodes(body);
  return std::find(held.begin(), held.end(), std::uint8_t{1}) == held.end();
}

void LoopResection::begin(const World& world, CuttingSummary& summary) const {
  summary = CuttingSummary{};
  for (std::size_t k = 0; k < bodies_.size(); ++k) {
    BodyResection resection;
    resection.body = world.models()[static_cast<std::size_t>(bodies_[k])]->name;
    resection.initial_volume = initial_volume_[k];
    summary.bodies.push_back(resection);
    summary.volume_before += initial_volume_[k];
  }
  summary.volume_after = summary.volume_before;
}

}  // namespace viscera::sim
