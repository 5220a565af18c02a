#pragma once
/// Pulse waves on a vessel tree as forces on its host body (Kühnapfel et al., KISMET; seed 001
/// §5.1.1). Every beat, 60 / heart_rate s apart from t = 0, a wave starts at the top of the
/// hierarchy and runs along every branch at pulse_velocity m/s (duplicated at bifurcations:
/// its front is at the same arc length on every path, vessel_wave_paths.h). "The first force
/// wave applies forces onto the vessel walls, the second wave removes the forces in the next
/// simulation step at the same spot": a wall knot gets wall_force N along its direction (from
/// the vessel axis out to the knot) during the one step in which the front passes its arc, and
/// every knot the front sweeps in a step is pushed together ("forces to groups of knot rings"
/// when the step is coarse). A new beat deletes the wave still running (the seed's rule when the
/// heart rate is too high for the tree), so a front never travels further than one beat.
///
/// Energy of the step's load, relative to rest: E = −Σ F_k · (x_k − X_k) over the knots pushed
/// (a load constant in x, zero Hessian).

#include <utility>
#include <vector>

#include "core/scenario/scenario_parts.h"
#include "simulator/dynamics/body_term.h"
#include "simulator/dynamics/vessel_wave_paths.h"

namespace viscera::sim {

class PulseWaves : public BodyTerm {
 public:
  /// The pulse `spec` on `tree`, hosted by the body of `model`; `id` names the active
  /// deformation in errors. Throws core::InputError for a non-positive heart rate or pulse
  /// velocity, a negative wall force or a malformed tree (proximal_arc_lengths).
  PulseWaves(std::shared_ptr<const BodyModel> model, const SimulationState& state,
             const core::PulseSpec& spec, core::VesselTree tree, std::string id);

  std::string name() const override { return "pulse " + id_ + " " + model().name; }
  /// Chooses the knots the front passes in [time, time + h).
  void prepare(const SimulationState& state, const StepContext& context) override;
  double energy(std::span<const Vec3> x) const override;
  double add_forces(std::span<const Vec3> x, std::span<const Vec3> v,
                    std::span<Vec3> f) const override;
  void declare_blocks(BlockPattern&) const override {}
  void add_stiffness(std::span<const Vec3>, double, bool, BlockSparseMatrix&) const override {}
  /// The heart drives the vessels: a pulsing vessel never falls asleep between beats (its
  /// next beat comes from the clock, not from the state).
  bool drives() const override { return true; }

  /// A clip or a coagulated spot on segment `segment` (index into the tree's segments), `along`
  /// m from its proximal end: the wave no longer passes it, so no knot downstream of it (further
  /// along that segment, or on any of its descendants) is pushed from the next prepare() on
  /// (seed 001 §5.1.2: "the pulse stops behind the clip"). Occlusions add up and survive
  /// topology changes. Throws core::UsageError for a segment not in the tree or `along` outside
  /// [0, its length].
  void occlude(int segment, double along);
  /// occlude() at the point of segment `segment`'s axis nearest `rest_point` (m, in the frame
  /// the tree was authored in: the host's rest frame).
  void occlude_at(int segment, const Vec3& rest_point);
  /// A clip or coagulation at `rest_point` (m, host rest frame): occludes the segment whose
  /// wall (axis distance minus radius) lies nearest, when that is within `reach` m. Returns
  /// whether a segment was occluded.
  bool occlude_nearest(const Vec3& rest_point, double reach);
  /// The id of the vessel tree the wave runs on.
  const std::string& vessel_tree() const { return tree_.id; }
  /// Whether the wave still reaches wall knot `k` (an index into knots()).
  bool reaches(std::size_t k) const { return !blocked_[k]; }

  /// s between beats.
  double period() const { return period_; }
  /// The wall knots, with body-local node indices.
  const std::vector<PulseWallKnot>& knots() const { return knots_; }
  /// Global nodes pushed in the prepared step.
  const std::vector<int>& pushed() const { return pushed_; }

 protected:
  void build(const SimulationState& state, int first) override;
  void shift(int delta) override;

 private:
  core::PulseSpec spec_;
  core::VesselTree tree_;
  std::string id_;
  double period_ = 1.0;
  int first_ = 0;
  std::vector<PulseWallKnot> knots_;
  std::vector<std::pair<int, double>> occlusions_;  ///< (segment, hierarchy arc m) of each clip
  std::vector<bool> blocked_;                       ///< per knot: downstream of an occlusion
  void block_downstream();
  /// Segment `index` of the tree; throws core::UsageError naming the pulse when out of range.
  const core::VesselSegment& segment(int index) const;
  std::vector<int> pushed_;         ///< global nodes
  std::vector<Vec3> pushed_force_;  ///< N, per pushed node
  std::vector<Vec3> pushed_rest_;   ///< m, their rest positions
};

/// Mean length in m of the edges of `mesh`'s tets (each tet's six edges counted), or of its
/// surface triangles' edges when it has no tets: the sampling spacing of the wall knots.
double mean_edge_length(const core::TetMesh& mesh);

}  // namespace viscera::sim
