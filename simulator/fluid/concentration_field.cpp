#include "simulator/fluid/concentration_field.h"

#include <algorithm>
#include <cmath>

namespace viscera::sim::fluid {

ConcentrationField::ConcentrationField(const FlowGrid& grid)
    : fraction_(static_cast<std::size_t>(grid.cell_count()), 0.0) {}

double ConcentrationField::add_blood(const FlowGrid& grid, const core::Vec3& point, double volume) {
  const CellCoord cell = grid.cell_of(point);
  if (grid.cell_or_solid(cell) == FlowCell::Solid || !(volume > 0.0)) return 0.0;
  const double h = grid.cell_size();
  fraction_[static_cast<std::size_t>(grid.cell_index(cell))] += volume / (h * h * h);
  return volume;
}

double ConcentrationField::total_volume(const FlowGrid& grid) const {
  double sum = 0.0;
  for (const double c : fraction_)
    sum += c;
  const double h = grid.cell_size();
  return sum * h * h * h;
}

bool ConcentrationField::share_with_neighbours(const FlowGrid& grid, int i, int j, int k,
                                               double amount) {
  const CellCoord next[6] = {{i - 1, j, k}, {i + 1, j, k}, {i, j - 1, k},
                             {i, j + 1, k}, {i, j, k - 1}, {i, j, k + 1}};
  int open = 0;
  for (const CellCoord& q : next)
    open += grid.cell_or_solid(q) != FlowCell::Solid;
  if (open == 0) return false;
  for (const CellCoord& q : next)
    if (grid.cell_or_solid(q) != FlowCell::Solid)
      fraction_[static_cast<std::size_t>(grid.cell_index(q))] += amount / open;
  return true;
}

double ConcentrationField::spill(const FlowGrid& grid, int passes) {
  double moved = 0.0;
  const double h3 = grid.cell_size() * grid.cell_size() * grid.cell_size();
  for (int pass = 0; pass < passes; ++pass) {
    bool spilled = false;
    for (int k = 0; k < grid.nz(); ++k)
      for (int j = 0; j < grid.ny(); ++j)
        for (int i = 0; i < grid.nx(); ++i) {
          auto& c = fraction_[static_cast<std::size_t>(grid.cell_index(i, j, k))];
          if (c <= 1.0 || grid.cell(i, j, k) == FlowCell::Solid) continue;
          const double excess = c - 1.0;
          if (!share_with_neighbours(grid, i, j, k, excess)) continue;
          c = 1.0;
          moved += excess * h3;
          spilled = true;
        }
    if (!spilled) break;
  }
  return moved;
}

double ConcentrationField::settle(const FlowGrid& grid) {
  double moved = 0.0;
  const double h3 = grid.cell_size() * grid.cell_size() * grid.cell_size();
  for (int k = 0; k < grid.nz(); ++k)
    for (int j = 0; j < grid.ny(); ++j)
      for (int i = 0; i < grid.nx(); ++i) {
        auto& c = fraction_[static_cast<std::size_t>(grid.cell_index(i, j, k))];
        if (c == 0.0 || grid.cell(i, j, k) != FlowCell::Solid) continue;
        if (!share_with_neighbours(grid, i, j, k, c)) continue;
        moved += c * h3;
        c = 0.0;
      }
  return moved;
}

int ConcentrationField::advect(const FlowGrid& grid, double time_step) {
  const double h = grid.cell_size();
  double fastest = 0.0;
  for (int axis = 0; axis < 3; ++axis)
    for (const double u : grid.velocity(axis))
      fastest = std::max(fastest, std::abs(u));
  const int substeps = std::max(1, static_cast<int>(std::ceil(fastest * time_step / (0.9 * h))));
  const double dt = time_step / substeps;
  const int nx = grid.nx(), ny = grid.ny(), nz = grid.nz();
  for (int s = 0; s < substeps; ++s) {
    // Face fluxes first (fraction · velocity · dt/h, upwind), then each cell takes in and gives
    // out exactly the fluxes of its faces.
    std::vector<double> change(fraction_.size(), 0.0);
    for (int axis = 0; axis < (grid.planar() ? 2 : 3); ++axis) {
      const FaceDims d = grid.face_dims(axis);
      const auto& u = grid.velocity(axis);
      for (int k = 0; k < d.z; ++k) {
        for (int j = 0; j < d.y; ++j) {
          for (int i = 0; i < d.x; ++i) {
            const double velocity = u[static_cast<std::size_t>(d.index(i, j, k))];
            if (velocity == 0.0) continue;
            const int ai = i - (axis == 0), aj = j - (axis == 1), ak = k - (axis == 2);
            const FlowCell a = grid.cell_or_solid(ai, aj, ak), b = grid.cell_or_solid(i, j, k);
            if (a == FlowCell::Solid && b == FlowCell::Solid) continue;
            // Upwind: the cell the flow comes from; clear medium from a solid (an inflow).
            const bool from_a = velocity > 0.0;
            const FlowCell source = from_a ? a : b;
            const double carried =
                source == FlowCell::Solid
                    ? 0.0
                    : fraction_[static_cast<std::size_t>(from_a ? grid.cell_index(ai, aj, ak)
                                                                : grid.cell_index(i, j, k))];
            const double flux = carried * velocity * dt / h;  // fraction moved from a to b
            if (a != FlowCell::Solid)
              change[static_cast<std::size_t>(grid.cell_index(ai, aj, ak))] -= flux;
            else
              drained_ -= flux * h * h * h;  // into a solid: never, unless it sucks (outflow)
            if (b != FlowCell::Solid)
              change[static_cast<std::size_t>(grid.cell_index(i, j, k))] += flux;
            else
              drained_ += flux * h * h * h;
          }
        }
      }
    }
    for (std::size_t c = 0; c < fraction_.size(); ++c)
      fraction_[c] += change[c];
    // Open cells are the outside world: what reaches them is gone.
    for (int k = 0; k < nz; ++k)
      for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
          if (grid.cell(i, j, k) != FlowCell::Open) continue;
          auto& c = fraction_[static_cast<std::size_t>(grid.cell_index(i, j, k))];
          drained_ += c * h * h * h;
          c = 0.0;
        }
  }
  return substeps;
}

}  // namespace viscera::sim::fluid
