#pragma once
/// Gravity g (m/s²) on every node: E = −Σ m_i g·(x_i − X_i), relative to the rest positions X.

#include "simulator/dynamics/force_term.h"

namespace viscera::sim {

class GravityTerm : public ForceTerm {
 public:
  GravityTerm(const Vec3& gravity, const SimulationState& state);
  std::string name() const override { return "gravity"; }
  double energy(std::span<const Vec3> x) const override;
  double add_forces(std::span<const Vec3> x, std::span<const Vec3> v,
                    std::span<Vec3> f) const override;
  void declare_blocks(BlockPattern&) const override {}
  void add_stiffness(std::span<const Vec3>, double, bool, BlockSparseMatrix&) const override {}
  void topology_changed(const SimulationState& state, int body) override;
  bool acts_per_node() const override { return true; }
  void add_node_forces(std::span<const int> nodes, std::span<const Vec3> x, std::span<const Vec3> v,
                       std::span<Vec3> f) const override;
  const Vec3& gravity() const { return gravity_; }

 private:
  Vec3 gravity_;
  std::vector<double> mass_;
  std::vector<Vec3> rest_;
};

}  // namespace viscera::sim
