#pragma once
/// Plasticity of tet and mass-spring bodies (seed 003 §V: "permanently changing default …
/// connection length if a certain stretch threshold is exceeded"; the material's plastic_yield):
/// after every accepted step, the rest length l0 of each distance term or KisMo spring whose
/// strain ε = (l − l0) / l0 exceeds the yield ε_y follows it, l0 ← l / (1 + ε_y), so at most
/// the yield strain stays elastic and the rest becomes permanent set. Only stretch flows, as the
/// seed has it ("stretch threshold"): compressed edges keep their rest length — shortening them
/// under a pressing tool, while the volume terms keep the rest volume, would flatten the tets
/// at rest and turn them inside out.
/// The flow stops where the tissue tears: a rest length never grows past L (1 + ε_t), L its
/// original length (ε_t the tearing_threshold; TissueTearing reports the tear, the
/// cutting module splits it), so a sustained load past the yield — ideal plasticity, no
/// hardening — cannot stretch a body without bound. Volume terms keep their rest volume
/// (plastic flow of tissue is taken as isochoric) and area terms their rest area. A material
/// with plastic_yield ≤ 0 does not flow. The term adds no energy or force; rest data rebuilt by
/// a topology change start again from the new rest mesh.

#include <string>

#include "simulator/dynamics/body_edges.h"

namespace viscera::sim {

/// Applies the rule above to every edge (global node pairs) with its own yield strain, a rest
/// length never growing past `longest` (m); returns how many rest lengths moved.
int apply_plastic_flow(std::span<const Vec3> x, std::span<const std::array<int, 2>> edges,
                       std::span<double> rest_length, std::span<const double> yield_strain,
                       std::span<const double> longest);

class PlasticFlow : public ForceTerm {
 public:
  /// Flow of the rest lengths `edges` hold, with each edge's plastic_yield from its tets'
  /// materials. The term holding them must outlive this one and come before it in the world's
  /// term list (its topology_changed rebuilds the edges this one then re-reads).
  PlasticFlow(BodyEdges edges, const SimulationState& state);

  std::string name() const override { return "plastic-flow " + edges_.model().name; }
  double energy(std::span<const Vec3>) const override { return 0.0; }
  double add_forces(std::span<const Vec3>, std::span<const Vec3>, std::span<Vec3>) const override {
    return 0.0;
  }
  void declare_blocks(BlockPattern&) const override {}
  void add_stiffness(std::span<const Vec3>, double, bool, BlockSparseMatrix&) const override {}
  /// Moves the rest lengths strained past the yield at the accepted positions.
  void after_step(const SimulationState& state) override;
  /// Once per step: the strain of the whole step, under either integrator.
  bool after_each_substep() const override { return false; }
  void topology_changed(const SimulationState& state, int body) override;

  /// Rest-length moves so far (one per edge and step).
  long long flow_events() const { return flow_events_; }
  /// Per edge, the yield strain in use.
  const std::vector<double>& yield_strain() const { return yield_; }

 private:
  void capture(const SimulationState& state);

  BodyEdges edges_;
  std::vector<double> yield_, longest_;  ///< longest: L (1 + ε_t), m
  long long flow_events_ = 0;
};

}  // namespace viscera::sim
