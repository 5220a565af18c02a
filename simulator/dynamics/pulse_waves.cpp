#include "simulator/dynamics/pulse_waves.h"

#include <cmath>
#include <string>

#include "core/error.h"
#include "core/scenario/vessel_paths.h"

namespace viscera::sim {

double mean_edge_length(const core::TetMesh& mesh) {
  double sum = 0.0;
  std::size_t count = 0;
  const auto add = [&](int a, int b) {
    sum +=
        (mesh.nodes[static_cast<std::size_t>(a)] - mesh.nodes[static_cast<std::size_t>(b)]).norm();
    ++count;
  };
  for (const auto& t : mesh.tets)
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j)
        add(t[i], t[j]);
  if (count == 0)
    for (const auto& f : mesh.surface_faces)
      for (int i = 0; i < 3; ++i)
        add(f[i], f[(i + 1) % 3]);
  return count > 0 ? sum / static_cast<double>(count) : 0.0;
}

PulseWaves::PulseWaves(std::shared_ptr<const BodyModel> model, const SimulationState& state,
                       const core::PulseSpec& spec, core::VesselTree tree, std::string id)
    : BodyTerm(std::move(model)), spec_(spec), tree_(std::move(tree)), id_(std::move(id)) {
  const core::ErrorLocation where{"", "", id_};
  if (!(spec_.heart_rate > 0.0))
    throw core::InputError("pulse \"" + id_ + "\": the heart rate must be positive", where);
  if (!(spec_.pulse_velocity > 0.0))
    throw core::InputError("pulse \"" + id_ + "\": the pulse velocity must be positive", where);
  if (!(spec_.wall_force >= 0.0))
    throw core::InputError("pulse \"" + id_ + "\": the wall force must not be negative", where);
  period_ = 60.0 / spec_.heart_rate;
  initialise(state);
}

void PulseWaves::build(const SimulationState& state, int first) {
  first_ = first;
  double spacing = mean_edge_length(model().mesh);
  if (!(spacing > 0.0)) spacing = 1e-3;  // a body of isolated nodes: sample every millimetre
  knots_ = pulse_wall_knots(tree_, state.range(state.rest_positions, model().body), spacing);
  block_downstream();
  pushed_.clear();
  pushed_force_.clear();
  pushed_rest_.clear();
}

const core::VesselSegment& PulseWaves::segment(int index) const {
  if (index < 0 || index >= static_cast<int>(tree_.segments.size()))
    throw core::UsageError("pulse \"" + id_ + "\": no segment " + std::to_string(index) +
                           " in vessel tree \"" + tree_.id + "\" to occlude");
  return tree_.segments[static_cast<std::size_t>(index)];
}

void PulseWaves::occlude(int segment, double along) {
  const auto& seg = this->segment(segment);
  const double length = (seg.distal - seg.proximal).norm();
  if (!(along >= 0.0 && along <= length))
    throw core::UsageError("pulse \"" + id_ + "\": an occlusion must lie on its segment (0 to " +
                           std::to_string(length) + " m along)");
  occlusions_.emplace_back(segment,
                           proximal_arc_lengths(tree_)[static_cast<std::size_t>(segment)] + along);
  block_downstream();
}

void PulseWaves::occlude_at(int segment, const Vec3& rest_point) {
  const auto& seg = this->segment(segment);
  const double along = core::nearest_point_on_segment(tree_, segment, rest_point).along;
  occlude(segment, along * (seg.distal - seg.proximal).norm());
}

bool PulseWaves::occlude_nearest(const Vec3& rest_point, double reach) {
  const core::VesselSegmentPoint nearest = core::nearest_point_on_vessel(tree_, rest_point);
  if (nearest.segment < 0 || nearest.wall_distance > reach) return false;
  occlude_at(nearest.segment, rest_point);
  return true;
}

void PulseWaves::block_downstream() {
  blocked_.assign(knots_.size(), false);
  for (std::size_t k = 0; k < knots_.size(); ++k)
    for (const auto& [segment, arc] : occlusions_) {
      // Downstream: on the clipped segment past the clip, or on any segment below it.
      int s = knots_[k].segment;
      bool below = s == segment && knots_[k].arc > arc;
      for (s = tree_.segments[static_cast<std::size_t>(s)].parent; !below && s >= 0;
           s = tree_.segments[static_cast<std::size_t>(s)].parent)
        below = s == segment;
      if (below) blocked_[k] = true;
    }
}

void PulseWaves::shift(int delta) {
  first_ += delta;
  for (int& n : pushed_)
    n += delta;
}

void PulseWaves::prepare(const SimulationState& state, const StepContext& context) {
  pushed_.clear();
  pushed_force_.clear();
  pushed_rest_.clear();
  // Knot k is pushed in the step [time, end) holding an arrival n·T + arc/v of beat n ≥ 0, and
  // only while beat n's wave still runs (arc/v < T: the next beat deletes it). Both ends move
  // back by a nanosecond-scale margin, so an arrival on a step boundary counts once, for the
  // step it opens, however the boundary times were rounded.
  const double margin = 1e-6 * context.h;
  const double start = context.time - margin;
  const double end = context.time + context.h - margin;
  for (std::size_t k = 0; k < knots_.size(); ++k) {
    const PulseWallKnot& knot = knots_[k];
    const double travel = knot.arc / spec_.pulse_velocity;
    if (travel >= period_) break;  // sorted by arc: no wave reaches this far
    if (blocked_[k]) continue;
    const double beat = (std::ceil((end - travel) / period_) - 1.0) * period_;
    if (beat < -margin || beat + travel < start) continue;
    pushed_.push_back(first_ + knot.node);
    pushed_force_.push_back(spec_.wall_force * knot.direction);
    pushed_rest_.push_back(state.rest_positions[static_cast<std::size_t>(first_ + knot.node)]);
  }
}

double PulseWaves::energy(std::span<const Vec3> x) const {
  double e = 0.0;
  for (std::size_t k = 0; k < pushed_.size(); ++k)
    e -= pushed_force_[k].dot(x[static_cast<std::size_t>(pushed_[k])] - pushed_rest_[k]);
  return e;
}

double PulseWaves::add_forces(std::span<const Vec3> x, std::span<const Vec3> /*v*/,
                              std::span<Vec3> f) const {
  for (std::size_t k = 0; k < pushed_.size(); ++k)
    f[static_cast<std::size_t>(pushed_[k])] += pushed_force_[k];
  return energy(x);
}

}  // namespace viscera::sim
