#pragma once
/// Springs that hold connected objects together at their knots (seed 001 §3.3: KisMo joins
/// organs at their nearest knots, e.g. a tube to the uterus, a ligament to the pelvic wall).
/// Each node pair of a scenario connection becomes a linear spring of the connection's stiffness
/// (N/m) with the pair's rest distance as its rest length; the two ends get equal and opposite
/// forces, so connections conserve momentum.

#include <vector>

#include "core/scenario/scenario.h"
#include "simulator/physics/deformable_body.h"
#include "simulator/physics/stable_step.h"

namespace viscera::sim {

/// One spring between node `node_a` of body `body_a` and node `node_b` of body `body_b`.
struct ConnectionSpring {
  int body_a = 0;
  int node_a = 0;
  int body_b = 0;
  int node_b = 0;
  double stiffness = 0.0;    ///< N/m
  double rest_length = 0.0;  ///< m, the pair's distance in the rest configuration
};

/// The connection springs of a world; built once, applied every sub-step.
class ConnectionSprings {
 public:
  /// No connections.
  ConnectionSprings() = default;

  /// Resolves each connection's object ids among the bodies (by body name) and its node pairs
  /// against those bodies' rest positions. Throws
  /// core::InputError naming the connection (JSON pointer /scenario/connections/i) when an
  /// object has no simulated body, a node index is out of range or a stiffness is not positive.
  ConnectionSprings(const core::Scenario& scenario, const std::vector<DeformableBody>& bodies);

  /// Adds the spring forces at the bodies' current positions (after compute_forces(), before
  /// integrate()).
  void apply(std::vector<DeformableBody>& bodies) const;

  /// Elastic energy in J stored in the springs at the current positions: Σ k/2 (|d| − l0)².
  double energy(const std::vector<DeformableBody>& bodies) const;

  /// Largest sum of connection stiffness meeting at one node, N/m: the extra stiffness the
  /// explicit integrator's stable step must allow for.
  double max_node_stiffness() const { return max_node_stiffness_; }

  /// Adds each spring's stiffness bound k·I (3×3) between its two nodes to `stiffness`, body b's
  /// nodes numbered from offsets[b]. k·I bounds the spring's Hessian at any length at or beyond
  /// its rest length (k along the spring, k (1 − l0/|d|) across it).
  void add_linearised_terms(RankOneSystem& stiffness, std::span<const int> offsets) const;

  /// Adds 2k for every spring ending at a node of body `body` to node_stiffness[node]: the
  /// spring's share of that node's Gershgorin row (k on the diagonal, k off it).
  void add_node_stiffness(int body, std::span<double> node_stiffness) const;

  const std::vector<ConnectionSpring>& springs() const { return springs_; }
  bool empty() const { return springs_.empty(); }

 private:
  std::vector<ConnectionSpring> springs_;
  double max_node_stiffness_ = 0.0;
};

}  // namespace viscera::sim
