#include "simulator/fluid/cavity_grid.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>

#include "core/error.h"
#include "simulator/camera/surface_bvh.h"

namespace viscera::sim::fluid {
namespace {

/// Distances along +x from `origin` at which the ray crosses the surface, in order.
std::vector<double> crossings(const SurfaceBvh& bvh, core::Vec3 origin, double length) {
  std::vector<double> at;
  const core::Vec3 along = core::Vec3::UnitX();
  double travelled = 0.0;
  while (travelled < length) {
    const RayHit hit = bvh.cast(origin, along, length - travelled);
    if (hit.triangle < 0) break;
    travelled += hit.distance;
    at.push_back(travelled);
    // Step past the triangle just met; a nanometre is far below any cell.
    origin += (hit.distance + 1e-9) * along;
    travelled += 1e-9;
  }
  return at;
}

/// 1 for each cell of `grid` whose centre lies inside the closed surface: a cell centre is
/// inside after an odd number of crossings of a ray along x that starts outside the whole
/// surface. Rows are nudged off the cell centres' exact lattice so they do not run along mesh
/// edges.
std::vector<std::uint8_t> inside_cells(const FlowGrid& grid, std::span<const core::Vec3> positions,
                                       const std::vector<core::Triangle>& triangles) {
  std::vector<std::uint8_t> inside(static_cast<std::size_t>(grid.cell_count()), 0);
  if (triangles.empty()) return inside;
  const double h = grid.cell_size();
  const core::Vec3& origin = grid.origin();
  core::Vec3 lo = core::Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const auto& p : positions) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const double surface_lo = std::min(origin.x(), lo.x());
  const double surface_hi = std::max(origin.x() + grid.nx() * h, hi.x());
  const double before = origin.x() - surface_lo + h;  // ray start to the grid, m
  const double length = before + surface_hi - origin.x() + h;
  const SurfaceBvh bvh(triangles, positions);
  for (int k = 0; k < grid.nz(); ++k) {
    const double z = origin.z() + h * (k + 0.5 + 2.91e-6);
    if (z < lo.z() || z > hi.z()) continue;
    for (int j = 0; j < grid.ny(); ++j) {
      const double y = origin.y() + h * (j + 0.5 + 1.37e-6);
      if (y < lo.y() || y > hi.y()) continue;
      const std::vector<double> at = crossings(bvh, core::Vec3(origin.x() - before, y, z), length);
      std::size_t passed = 0;
      for (int i = 0; i < grid.nx(); ++i) {
        const double x = before + (i + 0.5) * h;
        while (passed < at.size() && at[passed] < x)
          ++passed;
        inside[static_cast<std::size_t>(grid.cell_index(i, j, k))] = passed % 2 == 1;
      }
    }
  }
  return inside;
}

/// The face-connected pockets of the cells marked 1 in `open`: each cell's pocket (−1 where
/// not open) and the pockets' sizes.
std::vector<int> pockets_of(const FlowGrid& grid, const std::vector<std::uint8_t>& open,
                            std::vector<int>& sizes) {
  const int nx = grid.nx(), ny = grid.ny(), nz = grid.nz();
  std::vector<int> pocket(open.size(), -1);
  sizes.clear();
  for (std::size_t seed = 0; seed < open.size(); ++seed) {
    if (!open[seed] || pocket[seed] >= 0) continue;
    const int id = static_cast<int>(sizes.size());
    int size = 0;
    std::deque<int> queue{static_cast<int>(seed)};
    pocket[seed] = id;
    while (!queue.empty()) {
      const int c = queue.front();
      queue.pop_front();
      ++size;
      const int i = c % nx, j = (c / nx) % ny, k = c / (nx * ny);
      const int next[6][3] = {{i - 1, j, k}, {i + 1, j, k}, {i, j - 1, k},
                              {i, j + 1, k}, {i, j, k - 1}, {i, j, k + 1}};
      for (const auto& q : next) {
        if (q[0] < 0 || q[1] < 0 || q[2] < 0 || q[0] >= nx || q[1] >= ny || q[2] >= nz) continue;
        const auto m = static_cast<std::size_t>(grid.cell_index(q[0], q[1], q[2]));
        if (!open[m] || pocket[m] >= 0) continue;
        pocket[m] = id;
        queue.push_back(static_cast<int>(m));
      }
    }
    sizes.push_back(size);
  }
  return pocket;
}

/// Labels every cell of `grid` outside pocket `keep` solid at rest and every cell in it fluid
/// (open cells stay open); returns how many labels changed.
int keep_pocket(FlowGrid& grid, const std::vector<int>& pocket, int keep) {
  int changed = 0;
  for (int k = 0; k < grid.nz(); ++k)
    for (int j = 0; j < grid.ny(); ++j)
      for (int i = 0; i < grid.nx(); ++i) {
        const FlowCell before = grid.cell(i, j, k);
        const bool in = pocket[static_cast<std::size_t>(grid.cell_index(i, j, k))] == keep;
        const FlowCell after = !in                        ? FlowCell::Solid
                               : before == FlowCell::Open ? FlowCell::Open
                                                          : FlowCell::Fluid;
        changed += after != before;
        grid.set_cell(i, j, k, after);
      }
  return changed;
}

}  // namespace

FlowGrid label_cavity(std::span<const core::Vec3> positions,
                      const std::vector<core::Triangle>& triangles,
                      const std::vector<double>& cavity_marks, double cell_size, int margin) {
  if (!(cell_size > 0.0)) throw core::UsageError("the cavity's cell size must be positive, m");
  core::Vec3 lo = core::Vec3::Constant(std::numeric_limits<double>::infinity());
  core::Vec3 hi = -lo;
  for (std::size_t v = 0; v < positions.size() && v < cavity_marks.size(); ++v) {
    if (cavity_marks[v] != 1.0) continue;
    lo = lo.cwiseMin(positions[v]);
    hi = hi.cwiseMax(positions[v]);
  }
  if (!(lo.x() <= hi.x()))
    throw core::InputError("the surface marks no cavity wall (no \"cavity\" vertex of 1)");
  const core::Vec3 origin = lo - margin * cell_size * core::Vec3::Ones();
  std::array<int, 3> n{};
  for (int a = 0; a < 3; ++a)
    n[a] = static_cast<int>(std::ceil((hi[a] - lo[a]) / cell_size)) + 2 * margin + 1;
  if (static_cast<double>(n[0]) * n[1] * n[2] > 256.0 * 256.0 * 256.0)
    throw core::UsageError("a cavity grid of that cell size would exceed 256³ cells");
  FlowGrid grid(n[0], n[1], n[2], cell_size, origin);
  std::vector<std::uint8_t> open = inside_cells(grid, positions, triangles);
  for (auto& o : open)
    o = !o;
  // The cavity is the pocket the marked wall faces: each marked vertex votes for the pockets of
  // its cell and the six beside it. The others lie outside the organ, in the box's corners —
  // larger than a slit-like cavity once the margin grows. Without a vote, the largest pocket.
  std::vector<int> sizes;
  const std::vector<int> pocket = pockets_of(grid, open, sizes);
  if (sizes.empty()) throw core::InputError("the cavity leaves no fluid cell at this cell size");
  std::vector<long long> votes(sizes.size(), 0);
  for (std::size_t v = 0; v < positions.size() && v < cavity_marks.size(); ++v) {
    if (cavity_marks[v] != 1.0) continue;
    const auto [i, j, k] = grid.cell_of(positions[v]);
    const CellCoord near[7] = {{i, j, k},     {i - 1, j, k}, {i + 1, j, k}, {i, j - 1, k},
                               {i, j + 1, k}, {i, j, k - 1}, {i, j, k + 1}};
    for (const CellCoord& q : near) {
      if (!grid.contains(q)) continue;
      const int p = pocket[static_cast<std::size_t>(grid.cell_index(q))];
      if (p >= 0) ++votes[static_cast<std::size_t>(p)];
    }
  }
  const bool voted = *std::max_element(votes.begin(), votes.end()) > 0;
  keep_pocket(grid, pocket,
              voted
                  ? static_cast<int>(std::max_element(votes.begin(), votes.end()) - votes.begin())
                  : static_cast<int>(std::max_element(sizes.begin(), sizes.end()) - sizes.begin()));
  grid.update_faces();
  return grid;
}

int relabel_cavity(FlowGrid& grid, std::span<const core::Vec3> positions,
                   const std::vector<core::Triangle>& triangles) {
  std::vector<std::uint8_t> open = inside_cells(grid, positions, triangles);
  for (auto& o : open)
    o = !o;
  std::vector<int> sizes;
  const std::vector<int> pocket = pockets_of(grid, open, sizes);
  std::vector<int> shared(sizes.size(), 0);
  for (int k = 0; k < grid.nz(); ++k)
    for (int j = 0; j < grid.ny(); ++j)
      for (int i = 0; i < grid.nx(); ++i) {
        const int p = pocket[static_cast<std::size_t>(grid.cell_index(i, j, k))];
        if (p >= 0 && grid.cell(i, j, k) != FlowCell::Solid) ++shared[static_cast<std::size_t>(p)];
      }
  const auto best = std::max_element(shared.begin(), shared.end());
  if (best == shared.end() || *best == 0)
    throw core::InputError("the cavity's wall has closed over every fluid cell of its grid");
  const int changed = keep_pocket(grid, pocket, static_cast<int>(best - shared.begin()));
  grid.update_faces();
  return changed;
}

int close_stranded_pockets(FlowGrid& grid) {
  std::vector<std::uint8_t> open(static_cast<std::size_t>(grid.cell_count()), 0);
  for (int k = 0; k < grid.nz(); ++k)
    for (int j = 0; j < grid.ny(); ++j)
      for (int i = 0; i < grid.nx(); ++i)
        open[static_cast<std::size_t>(grid.cell_index(i, j, k))] =
            grid.cell(i, j, k) != FlowCell::Solid;
  std::vector<int> sizes;
  const std::vector<int> pocket = pockets_of(grid, open, sizes);
  if (sizes.size() < 2) return 0;
  std::vector<std::uint8_t> keep(sizes.size(), 0);
  bool any_outflow = false;
  for (int k = 0; k < grid.nz(); ++k)
    for (int j = 0; j < grid.ny(); ++j)
      for (int i = 0; i < grid.nx(); ++i)
        if (grid.cell(i, j, k) == FlowCell::Open) {
          keep[static_cast<std::size_t>(
              pocket[static_cast<std::size_t>(grid.cell_index(i, j, k))])] = 1;
          any_outflow = true;
        }
  if (!any_outflow)
    keep[static_cast<std::size_t>(std::max_element(sizes.begin(), sizes.end()) - sizes.begin())] =
        1;
  int closed = 0;
  for (int k = 0; k < grid.nz(); ++k)
    for (int j = 0; j < grid.ny(); ++j)
      for (int i = 0; i < grid.nx(); ++i) {
        const int p = pocket[static_cast<std::size_t>(grid.cell_index(i, j, k))];
        if (p < 0 || keep[static_cast<std::size_t>(p)]) continue;
        grid.set_cell(i, j, k, FlowCell::Solid);
        ++closed;
      }
  return closed;
}

int mark_inside_solid(FlowGrid& grid, std::span<const core::Vec3> positions,
                      const std::vector<core::Triangle>& triangles, const core::Vec3& velocity) {
  const std::vector<std::uint8_t> inside = inside_cells(grid, positions, triangles);
  int marked = 0;
  for (int k = 0; k < grid.nz(); ++k)
    for (int j = 0; j < grid.ny(); ++j)
      for (int i = 0; i < grid.nx(); ++i) {
        if (!inside[static_cast<std::size_t>(grid.cell_index(i, j, k))] ||
            grid.cell(i, j, k) == FlowCell::Solid)
          continue;
        grid.set_cell(i, j, k, FlowCell::Solid, velocity);
        ++marked;
      }
  return marked;
}

}  // namespace viscera::sim::fluid
