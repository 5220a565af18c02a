#pragma once
/// Linear springs between nodes of different bodies (seed 001 §3.3: KisMo joins organs at their
/// nearest knots), from the scenario's connections of non-pathology objects: stiffness k (N/m),
/// rest length the pair's rest distance. E = ½ k (|d| − l0)², equal and opposite forces.

#include <memory>
#include <vector>

#include "core/scenario/scenario.h"
#include "simulator/dynamics/force_term.h"

namespace viscera::sim {

/// One spring between node `node_a` of body `body_a` and node `node_b` of body `body_b`
/// (body-local node numbers).
struct ConnectionSpring {
  int body_a = 0;
  int node_a = 0;
  int body_b = 0;
  int node_b = 0;
  double stiffness = 0.0;    ///< N/m
  double rest_length = 0.0;  ///< m
};

class ConnectionSpringTerm : public ForceTerm {
 public:
  ConnectionSpringTerm(std::vector<ConnectionSpring> springs, const SimulationState& state);
  std::string name() const override { return "connection-springs"; }
  double energy(std::span<const Vec3> x) const override;
  double add_forces(std::span<const Vec3> x, std::span<const Vec3> v,
                    std::span<Vec3> f) const override;
  void declare_blocks(BlockPattern&) const override;
  void add_stiffness(std::span<const Vec3> x, double scale, bool project,
                     BlockSparseMatrix&) const override;
  /// Re-reads node offsets; springs at nodes of a re-meshed body keep their node when it still
  /// exists (new nodes are appended by cutting), else they are dropped.
  void topology_changed(const SimulationState& state, int body) override;
  /// Drops the springs at the nodes of `body` flagged in `released` (BodyTopology).
  void release(int body, std::span<const std::uint8_t> released);
  const std::vector<ConnectionSpring>& springs() const { return springs_; }

 private:
  void resolve(const SimulationState& state);
  std::vector<ConnectionSpring> springs_;
  std::vector<std::array<int, 2>> global_;
};

}  // namespace viscera::sim
