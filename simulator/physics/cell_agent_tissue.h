#pragma once
/// Agent-based tissue (Kuzub; seed 003 §V, eq. 3–9): every cell carries its own dynamics — a
/// spring to its home position, springs with damping to the neighbours found around it at
/// start-up, and elastic collisions — and forces from neighbours arrive through a pending-force
/// buffer, so all cells move in step whatever order they are processed in. Cutting removes the
/// connections a blade crosses; connections stretched past a limit tear, and past a yield
/// strain they lengthen for good (plasticity); tearing counts the stretch from the original
/// length, so plastic flow does not postpone it forever. Works in 3D, and in 2D with `planar`.
///
/// Per step of dt seconds, for each cell (eq. 3–7):
///   F_pending = Σ_connections k_conn (|d| − l0) d̂          (eq. 3, from the previous positions)
///   F = F_pending + k_home (p_home − p)                      (eq. 4)
///   a = F / m                                                (eq. 5, read as the acceleration of
///                                                             this step: accumulating it would
///                                                             integrate the force twice)
///   v = v + dt·a − b·v                                       (eq. 6, b the per-step damping)
///   p = p + dt·v                                             (eq. 7)

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "core/math_types.h"
#include "core/scenario/scenario_parts.h"

namespace viscera::sim {

/// Mechanical character of one kind of cell (heterogeneous tissue mixes several).
struct CellType {
  double mass = 1e-4;                  ///< kg
  double radius = 0.001;               ///< m, for collisions
  double home_stiffness = 0.5;         ///< k_home, N/m
  double connection_stiffness = 20.0;  ///< k_conn, N/m
  double damping = 0.05;               ///< b, fraction of velocity removed per step (0–1)
  double collision_efficiency = 0.5;   ///< k_collision (eq. 8)
  double tear_strain = 1.0;            ///< a connection stretched beyond this breaks
  double yield_strain = 0.5;           ///< beyond this the rest length grows (plasticity)
};

/// A spring between two cells.
struct CellConnection {
  int a = 0, b = 0;
  double rest_length = 0.0;      ///< m, grows with plastic flow
  double original_length = 0.0;  ///< m, at discovery: tearing is measured against it
  double stiffness = 0.0;        ///< N/m (mean of the two cells' k_conn)
  double yield_strain = 0.0;
  double tear_strain = 0.0;
};

/// The cell types of a scenario's cell tissue, in its order.
std::vector<CellType> cell_types_of(const core::CellTissueSpec& spec);

/// Neighbour discovery (seed 003 §V, "a fast configuration stage … establishes neighbour
/// connections"): each cell picks its up to `max_neighbours` nearest cells within
/// `neighbour_radius` m (ties by index); a connection exists when either side picked the other,
/// with the cells' distance as rest and original length, the mean of their k_conn and the
/// smaller of their yield and tear strains. Sorted by (a, b), a < b. Cells are binned in a grid
/// of the radius, so discovery is linear in the cell count. Throws core::UsageError when
/// `type_of` does not give every cell a type of `types`.
std::vector<CellConnection> discover_cell_connections(std::span<const core::Vec3> positions,
                                                      std::span<const CellType> types,
                                                      std::span<const int> type_of,
                                                      double neighbour_radius, int max_neighbours);

/// Tearing, then plasticity, of `connections` at `positions` (seed 003 §V, "Future
/// Development", implemented): every connection longer than (1 + tear_strain) × its original
/// length breaks and is moved out of `connections` into the result (in order); every remaining
/// one longer than (1 + yield_strain) × its rest length gets the rest length
/// length / (1 + yield_strain), the stretch beyond the yield becoming permanent.
std::vector<CellConnection> tear_and_yield(std::span<const core::Vec3> positions,
                                           std::vector<CellConnection>& connections);

/// Spring force in N on cell b of connection `c` at `positions` (−it on a): eq. 3,
/// k_conn (|d| − l0) d̂ pulling b towards a when stretched.
core::Vec3 connection_force(const CellConnection& c, std::span<const core::Vec3> positions);

/// A sheet or volume of cell agents.
class CellAgentTissue {
 public:
  /// Cells at `positions` (also their homes) with `types[type_of[i]]`. Connections join each
  /// cell to its up to `max_neighbours` nearest cells within `neighbour_radius` m (seed 003:
  /// four in a sheet), made symmetric. `planar` keeps every cell in its z plane.
  CellAgentTissue(std::vector<core::Vec3> positions, std::vector<CellType> types,
                  std::vector<int> type_of, double neighbour_radius, int max_neighbours,
                  bool planar);

  /// One step of eq. 3–9 of `dt` s; then tearing and plasticity.
  void step(double dt);

  /// Holds cell `cell` at `position` (a grasping tool); it pulls its neighbours but does not
  /// integrate itself until released.
  void drag(int cell, const core::Vec3& position);
  void release(int cell);

  /// Removes every connection whose segment crosses triangle (a, b, c) (a blade sweeping
  /// through the tissue); returns how many were cut. In 2D, pass a triangle that stands
  /// across the sheet.
  int cut(const core::Vec3& a, const core::Vec3& b, const core::Vec3& c);

  /// Adds an external force in N to a cell for the next step.
  void push(int cell, const core::Vec3& force) {
    pending_[static_cast<std::size_t>(cell)] += force;
  }

  const std::vector<core::Vec3>& positions() const { return position_; }
  const std::vector<core::Vec3>& velocities() const { return velocity_; }
  const std::vector<core::Vec3>& homes() const { return home_; }
  const std::vector<CellConnection>& connections() const { return connections_; }
  /// Number of connections torn since construction.
  int torn() const { return torn_; }
  /// Per cell, the sum of the spring forces of its connections at the current positions (N):
  /// what eq. 3 puts into the pending buffer.
  std::vector<core::Vec3> connection_forces() const;

 private:
  std::vector<CellType> types_;
  std::vector<int> type_of_;
  std::vector<core::Vec3> home_, position_, velocity_, pending_;
  std::vector<std::uint8_t> dragged_;
  std::vector<CellConnection> connections_;
  bool planar_;
  int torn_ = 0;
};

}  // namespace viscera::sim
