#include "simulator/fluid/cavity_grid.h"

#include <algorithm>
#include <cmath>
#include <deque>

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

  // Outside the tissue, row by row: a cell centre is in the tissue after an odd number of
  // crossings of a ray that starts outside the whole surface. Rows are nudged off the cell
  // centres' exact lattice so they do not run along mesh edges.
  double surface_lo = origin.x(), surface_hi = origin.x() + n[0] * cell_size;
  for (const auto& p : positions) {
    surface_lo = std::min(surface_lo, p.x());
    surface_hi = std::max(surface_hi, p.x());
  }
  const double before = origin.x() - surface_lo + cell_size;  // ray start to the grid, m
  const double length = before + surface_hi - origin.x() + cell_size;
  const SurfaceBvh bvh(triangles, positions);
  std::vector<std::uint8_t> open(static_cast<std::size_t>(grid.cell_count()), 0);
  for (int k = 0; k < n[2]; ++k) {
    for (int j = 0; j < n[1]; ++j) {
      const core::Vec3 start = origin + core::Vec3(-before, cell_size * (j + 0.5 + 1.37e-6),
                                                   cell_size * (k + 0.5 + 2.91e-6));
      const std::vector<double> at = crossings(bvh, start, length);
      std::size_t passed = 0;
      for (int i = 0; i < n[0]; ++i) {
        const double x = before + (i + 0.5) * cell_size;
        while (passed < at.size() && at[passed] < x)
          ++passed;
        open[static_cast<std::size_t>(grid.cell_index(i, j, k))] = passed % 2 == 0;
      }
    }
  }

  // The largest face-connected pocket is the cavity (others: outside the organ in the box).
  std::vector<int> pocket(open.size(), -1);
  int best = -1, best_size = 0, pockets = 0;
  for (std::size_t seed = 0; seed < open.size(); ++seed) {
    if (!open[seed] || pocket[seed] >= 0) continue;
    int size = 0;
    std::deque<int> queue{static_cast<int>(seed)};
    pocket[seed] = pockets;
    while (!queue.empty()) {
      const int c = queue.front();
      queue.pop_front();
      ++size;
      const int i = c % n[0], j = (c / n[0]) % n[1], k = c / (n[0] * n[1]);
      const int next[6][3] = {{i - 1, j, k}, {i + 1, j, k}, {i, j - 1, k},
                              {i, j + 1, k}, {i, j, k - 1}, {i, j, k + 1}};
      for (const auto& q : next) {
        if (q[0] < 0 || q[1] < 0 || q[2] < 0 || q[0] >= n[0] || q[1] >= n[1] || q[2] >= n[2])
          continue;
        const auto m = static_cast<std::size_t>(grid.cell_index(q[0], q[1], q[2]));
        if (!open[m] || pocket[m] >= 0) continue;
        pocket[m] = pockets;
        queue.push_back(static_cast<int>(m));
      }
    }
    if (size > best_size) best = pockets, best_size = size;
    ++pockets;
  }
  if (best < 0) throw core::InputError("the cavity leaves no fluid cell at this cell size");
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i)
        if (pocket[static_cast<std::size_t>(grid.cell_index(i, j, k))] != best)
          grid.set_cell(i, j, k, FlowCell::Solid);
  grid.update_faces();
  return grid;
}

}  // namespace viscera::sim::fluid
