#pragma once
/// Penalty contact between bodies (seed 000 §4) as a force term. prepare() finds the active set:
/// spatial hashing of every body's vertices against the other bodies' tets (§4.1), consistent
/// penetration depth d0 and direction n per colliding vertex (§4.2), the vertex's barycentric
/// weights w in the tet that holds it. Within the step each contact is the linearised gap
///   d(x) = d0 − n·((x_v − x_v⁰) − Σ w_k (x_k − x_k⁰)),  E = ½ k max(d, 0)²,
/// so the force k d n on the vertex and −w_k k d n on the tet's nodes (momentum conserved) are
/// exactly −∇E, and the Hessian k c cᵀ ⊗ n nᵀ (c = (1, −w)) is positive semi-definite.
/// Vertex–body pairs that already overlap in the rest configuration (a pathology's base sunk
/// into its wall) are authored geometry, not collisions, and are left out.

#include <memory>
#include <vector>

#include "simulator/collision/penetration_depth.h"
#include "simulator/collision/spatial_hash.h"
#include "simulator/dynamics/body_model.h"
#include "simulator/dynamics/force_term.h"

namespace viscera::sim {

/// What the contacts of the last prepare() were.
struct ContactStatistics {
  int colliding_points = 0;      ///< vertices inside another body
  double max_penetration = 0.0;  ///< m
  double total_force = 0.0;      ///< N, sum of the penalty force magnitudes at detection
};

class BodyContactTerm : public ForceTerm {
 public:
  /// `models` indexed by body; `stiffness` in N/m per colliding point.
  BodyContactTerm(std::vector<std::shared_ptr<const BodyModel>> models, double stiffness,
                  const SimulationState& state);
  std::string name() const override { return "body-contact"; }
  void prepare(const SimulationState& state, const StepContext& context) override;
  double energy(std::span<const Vec3> x) const override;
  double add_forces(std::span<const Vec3> x, std::span<const Vec3> v,
                    std::span<Vec3> f) const override;
  void declare_blocks(BlockPattern&) const override;
  void add_stiffness(std::span<const Vec3> x, double scale, bool project,
                     BlockSparseMatrix&) const override;
  bool structure_changed() const override { return structure_changed_; }
  void topology_changed(const SimulationState& state, int body) override;
  double worst_case_node_stiffness() const override { return stiffness_; }
  std::span<const int> worst_case_nodes() const override { return surface_nodes_; }

  const ContactStatistics& statistics() const { return statistics_; }
  double stiffness() const { return stiffness_; }

 private:
  struct Contact {
    std::array<int, 5> node;  ///< global: vertex, then the tet's four nodes
    std::array<double, 4> weight;
    Vec3 direction;
    double depth;            ///< d0, m
    std::array<Vec3, 5> at;  ///< positions at detection
  };
  double gap(const Contact& c, std::span<const Vec3> x) const;
  /// Caches for every body, or only `changed_body`'s adjacency when it is ≥ 0.
  void rebuild(const SimulationState& state, int changed_body);
  /// rest_overlap_ for every body, or only its pairs with `changed` (an index in models_) when
  /// that is less than the body count.
  void find_rest_overlaps(const std::vector<CollisionBodyView>& rest_views, std::size_t changed);

  std::vector<std::shared_ptr<const BodyModel>> models_;
  double stiffness_;
  std::unique_ptr<SpatialHash> hash_;
  std::vector<VertexAdjacency> adjacency_;
  std::vector<std::vector<std::uint8_t>> rest_overlap_;  ///< per body, node × body flags
  std::vector<int> surface_nodes_;
  std::vector<Contact> contacts_;
  /// (vertex, tet node) pairs declared since the last topology change, sorted.
  mutable std::vector<std::array<int, 2>> declared_;
  bool structure_changed_ = false;
  ContactStatistics statistics_;
};

}  // namespace viscera::sim
