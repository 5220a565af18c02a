#pragma once
/// Tearing of tet and mass-spring bodies past the material's tearing_threshold (seed 003 §V:
/// "deformation of intercellular connection beyond a certain maximum length breaks that
/// connection"; seed 001 §4.1 tears by duplicating knots). After every accepted step, each edge
/// (distance term or KisMo spring) stretched beyond (1 + threshold) × its ORIGINAL rest length —
/// measured from the rest mesh, so plastic flow does not postpone tearing forever — is recorded
/// once as a TearEvent. Splitting the mesh is the cutting module's topology change
/// (World::topology_changed); this term only reports where and when the tissue tore.

#include <string>
#include <vector>

#include "simulator/dynamics/body_edges.h"

namespace viscera::sim {

/// One tear: an edge or a cell connection stretched past its limit.
struct TearEvent {
  double time = 0.0;           ///< s, end of the step that tore it
  std::string body;            ///< the object's id
  int node_a = 0, node_b = 0;  ///< body-local nodes (cells) it joined
  double strain = 0.0;         ///< stretch from the original length when it tore
  double threshold = 0.0;      ///< the tearing strain it passed
};

class TissueTearing : public ForceTerm {
 public:
  /// Watches the edges `edges` holds, each with the tearing_threshold of its tets' materials
  /// (the smallest where layers meet). Same ordering rule as PlasticFlow.
  TissueTearing(BodyEdges edges, const SimulationState& state);

  std::string name() const override { return "tearing " + edges_.model().name; }
  double energy(std::span<const Vec3>) const override { return 0.0; }
  double add_forces(std::span<const Vec3>, std::span<const Vec3>, std::span<Vec3>) const override {
    return 0.0;
  }
  void declare_blocks(BlockPattern&) const override {}
  void add_stiffness(std::span<const Vec3>, double, bool, BlockSparseMatrix&) const override {}
  void after_step(const SimulationState& state) override;
  /// Once per step: the strain of the whole step, under either integrator.
  bool after_each_substep() const override { return false; }
  void topology_changed(const SimulationState& state, int body) override;

  /// Every tear so far, in the order they happened.
  const std::vector<TearEvent>& tears() const { return tears_; }

 private:
  void capture(const SimulationState& state);

  BodyEdges edges_;
  int first_ = 0;
  std::vector<double> original_, threshold_;
  std::vector<std::uint8_t> torn_;
  std::vector<TearEvent> tears_;
};

}  // namespace viscera::sim
