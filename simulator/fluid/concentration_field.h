#pragma once
/// The blood carried by the distension flow (issue 18 §3; seed 000 §6 clouds the view "with
/// blood"): a volume fraction per grid cell (ml of blood per ml, 0…1) moved by the flow's face
/// velocities. The seeds define no concentration; this one is advected in flux form with
/// first-order upwind fluxes (what leaves one cell enters its neighbour, so a closed cavity keeps
/// every drop to rounding, and no cell goes below zero or above its neighbours), in as many
/// sub-steps as keep the Courant number ≤ 0.9. Clear medium enters through inflow faces and
/// blood leaves with the flow through open cells; bleeding adds volume at a cell.

#include <vector>

#include "simulator/fluid/flow_grid.h"

namespace viscera::sim::fluid {

class ConcentrationField {
 public:
  /// A clear field over `grid`'s cells.
  explicit ConcentrationField(const FlowGrid& grid);

  /// Adds `volume` m³ of blood to the fluid or open cell holding `point` (m); nothing for a
  /// point outside the grid or in a solid cell. Returns the volume added.
  double add_blood(const FlowGrid& grid, const core::Vec3& point, double volume);

  /// Moves the field through `time_step` s with `grid`'s current face velocities (which should
  /// be divergence-free: the flow solver's output). Returns the sub-steps taken.
  int advect(const FlowGrid& grid, double time_step);

  /// After `grid` was relabelled: hands the blood of every cell that became solid to its
  /// non-solid face neighbours in equal shares (a wall closing over a cell pushes its contents
  /// aside). A solid cell with no such neighbour keeps its blood until the cavity reopens there,
  /// so the total never changes. Returns the volume moved, m³.
  double settle(const FlowGrid& grid);

  /// Spills what a cell holds above a fraction of 1 (more blood than the cell's volume: particles
  /// stopped at a wall where the flow stands still) into its non-solid face neighbours, in equal
  /// shares, over at most `passes` sweeps. The total does not change. Returns the volume moved,
  /// m³.
  double spill(const FlowGrid& grid, int passes = 8);

  /// Blood volume fraction of cell (i,j,k).
  double at(const FlowGrid& grid, int i, int j, int k) const {
    return fraction_[static_cast<std::size_t>(grid.cell_index(i, j, k))];
  }
  /// Total blood in the grid's cells, m³.
  double total_volume(const FlowGrid& grid) const;
  /// Blood carried out through open cells and inflow faces so far, m³.
  double drained_volume() const { return drained_; }

 private:
  /// Adds `amount` (a volume fraction) to cell (i,j,k)'s non-solid face neighbours in equal
  /// shares; false, and nothing added, when all six are solid.
  bool share_with_neighbours(const FlowGrid& grid, int i, int j, int k, double amount);

  std::vector<double> fraction_;
  double drained_ = 0.0;
};

}  // namespace viscera::sim::fluid
