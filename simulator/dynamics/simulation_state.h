#pragma once
/// The one state of a simulation (the design of PositionBasedDynamics' ParticleData): every node
/// of every body in global arrays, each body a contiguous node range. SI units throughout.

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "core/math_types.h"

namespace viscera::sim {

using core::Vec3;

/// Where a body's nodes lie in the global arrays.
struct BodyNodes {
  std::string name;
  int first = 0;  ///< global index of the body's node 0
  int count = 0;
};

/// The node arrays of one body, in its own numbering (all of the same length).
struct BodyNodeData {
  std::vector<Vec3> rest;           ///< m
  std::vector<Vec3> positions;      ///< m
  std::vector<Vec3> velocities;     ///< m/s, or empty for zero
  std::vector<double> masses;       ///< kg
  std::vector<std::uint8_t> fixed;  ///< 1 for a node held still (inverse mass 0), or empty
};

/// Positions, velocities, rest positions and masses of every node of every body.
class SimulationState {
 public:
  /// Appends a body at rest (positions = rest, zero velocity) and returns its index. A free
  /// node needs a positive mass (checked by the world, which knows the object's name).
  int add_body(std::string name, std::span<const Vec3> rest, std::span<const double> mass,
               std::span<const std::uint8_t> fixed);
  /// Topology change of one body: its node range is replaced by `data` (new count), the nodes
  /// of later bodies move up or down. Throws core::UsageError for mismatched array lengths.
  void replace_body_nodes(int body, const BodyNodeData& data);

  std::size_t node_count() const { return positions.size(); }
  const std::vector<BodyNodes>& bodies() const { return bodies_; }
  const BodyNodes& body(int b) const { return bodies_[static_cast<std::size_t>(b)]; }
  /// The body owning global node `node` (binary search over the ranges).
  int body_of(int node) const;

  /// Views of one body's part of a global array.
  template <class T>
  std::span<T> range(std::vector<T>& array, int b) const {
    return {array.data() + body(b).first, static_cast<std::size_t>(body(b).count)};
  }
  template <class T>
  std::span<const T> range(const std::vector<T>& array, int b) const {
    return {array.data() + body(b).first, static_cast<std::size_t>(body(b).count)};
  }

  std::vector<Vec3> positions, velocities, rest_positions;  ///< global, size node_count()
  std::vector<double> masses, inverse_masses;               ///< kg, 1/kg (0 = fixed node)
  double time = 0.0;                                        ///< s

 private:
  std::vector<BodyNodes> bodies_;
};

}  // namespace viscera::sim
