#include "simulator/fluid/cavity_flow.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.h"
#include "simulator/fluid/cavity_grid.h"

namespace viscera::sim::fluid {
namespace {

/// The cell edge that puts `resolution` cells along the longest side of the marked wall's box.
double cell_size_for(std::span<const core::Vec3> wall, const std::vector<double>& marks,
                     int resolution) {
  core::Vec3 lo = core::Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (std::size_t v = 0; v < wall.size() && v < marks.size(); ++v) {
    if (marks[v] != 1.0) continue;
    lo = lo.cwiseMin(wall[v]);
    hi = hi.cwiseMax(wall[v]);
  }
  if (!(lo.x() <= hi.x()))
    throw core::InputError("the surface marks no cavity wall (no \"cavity\" vertex of 1)");
  return (hi - lo).maxCoeff() / resolution;
}

/// Largest distance between matching points of `a` and `b` (infinite when their sizes differ).
double largest_motion(std::span<const core::Vec3> a, const std::vector<core::Vec3>& b) {
  if (a.size() != b.size()) return std::numeric_limits<double>::infinity();
  double largest = 0.0;
  for (std::size_t v = 0; v < a.size(); ++v)
    largest = std::max(largest, (a[v] - b[v]).squaredNorm());
  return std::sqrt(largest);
}

core::Vec3 cell_centre(const FlowGrid& grid, int i, int j, int k) {
  return grid.origin() + grid.cell_size() * core::Vec3(i + 0.5, j + 0.5, k + 0.5);
}

/// Face neighbours and their outward normals.
constexpr int kNext[6][3] = {{-1, 0, 0}, {1, 0, 0}, {0, -1, 0}, {0, 1, 0}, {0, 0, -1}, {0, 0, 1}};

}  // namespace

CavityFlow::CavityFlow(std::span<const core::Vec3> wall,
                       const std::vector<core::Triangle>& triangles,
                       const std::vector<double>& cavity_marks, const CavityFlowSettings& settings,
                       std::uint64_t seed)
    : settings_(settings),
      wall_triangles_(triangles),
      grid_(label_cavity(wall, triangles, cavity_marks,
                         cell_size_for(wall, cavity_marks, std::max(settings.resolution, 1)),
                         std::max(settings.margin, 1))),
      blood_(grid_),
      particles_(settings.particles, seed),
      bubbles_(settings.bubbles, seed ^ 0xb0bb1e5ull),
      debris_(settings.debris),
      vortices_(settings.vortices, seed ^ 0x9e3779b97f4a7c15ull),
      wall_labelled_(wall.begin(), wall.end()) {
  if (settings.resolution < 4 || !(settings.interval > 0.0) || !(settings.relabel_motion > 0.0) ||
      !(settings.sheath_radius >= 0.0) || !(settings.view_depth >= 0.0) ||
      !(settings.extinction >= 0.0))
    throw core::UsageError(
        "the cavity flow needs at least 4 cells across, a positive interval and relabelling "
        "motion, and no negative radius, depth or extinction");
  tissue_labels_.resize(static_cast<std::size_t>(grid_.cell_count()));
  for (int k = 0; k < grid_.nz(); ++k)
    for (int j = 0; j < grid_.ny(); ++j)
      for (int i = 0; i < grid_.nx(); ++i)
        tissue_labels_[static_cast<std::size_t>(grid_.cell_index(i, j, k))] = grid_.cell(i, j, k);
}

void CavityFlow::relabel(const CavityInputs& inputs) {
  const double reach = settings_.relabel_motion * grid_.cell_size();
  // Without the wall's positions (a step that was not due) nothing is labelled again.
  if (inputs.wall.size() != wall_labelled_.size())
    throw core::UsageError("the cavity flow needs the wall's current positions, one per vertex");
  bool tissue = inputs.obstacles_cut || largest_motion(inputs.wall, wall_labelled_) > reach ||
                inputs.obstacles.size() != obstacles_labelled_.size();
  for (std::size_t o = 0; o < inputs.obstacles.size() && !tissue; ++o)
    tissue = largest_motion(inputs.obstacles[o].positions, obstacles_labelled_[o]) > reach;
  if (tissue) {
    relabel_cavity(grid_, inputs.wall, wall_triangles_);
    wall_labelled_.assign(inputs.wall.begin(), inputs.wall.end());
    obstacles_labelled_.clear();
    for (const CavityObstacle& obstacle : inputs.obstacles) {
      if (obstacle.triangles != nullptr)
        mark_inside_solid(grid_, obstacle.positions, *obstacle.triangles);
      obstacles_labelled_.emplace_back(obstacle.positions.begin(), obstacle.positions.end());
    }
    for (int k = 0; k < grid_.nz(); ++k)
      for (int j = 0; j < grid_.ny(); ++j)
        for (int i = 0; i < grid_.nx(); ++i) {
          const FlowCell cell = grid_.cell(i, j, k);
          tissue_labels_[static_cast<std::size_t>(grid_.cell_index(i, j, k))] =
              cell == FlowCell::Open ? FlowCell::Fluid : cell;
        }
    ++relabellings_;
  }
  const bool in_cavity = inputs.sheath && in_tissue_fluid(inputs.tip);
  const bool sheath_moved =
      in_cavity != sheath_labelled_ ||
      (in_cavity && ((inputs.tip - sheath_tip_).norm() +
                         settings_.view_depth * (inputs.axis - sheath_axis_).norm() >
                     reach));
  if (!tissue && !sheath_moved) return;
  label_sheath(inputs, in_cavity);
  close_stranded();
  grid_.update_faces();
  blood_.settle(grid_);
}

bool CavityFlow::in_tissue_fluid(const core::Vec3& point) const {
  const CellCoord cell = grid_.cell_of(point);
  if (!grid_.contains(cell)) return false;
  return tissue_labels_[static_cast<std::size_t>(grid_.cell_index(cell))] == FlowCell::Fluid;
}

void CavityFlow::label_sheath(const CavityInputs& inputs, bool in_cavity) {
  for (int k = 0; k < grid_.nz(); ++k)
    for (int j = 0; j < grid_.ny(); ++j)
      for (int i = 0; i < grid_.nx(); ++i)
        grid_.set_cell(i, j, k,
                       tissue_labels_[static_cast<std::size_t>(grid_.cell_index(i, j, k))]);
  inflow_cells_.clear();
  sheath_cells_.clear();
  sheath_labelled_ = in_cavity;
  sheath_tip_ = inputs.tip;
  sheath_axis_ = inputs.axis;
  if (!in_cavity) return;
  const double h = grid_.cell_size();
  // A shaft thinner than the grid still blocks one line of cells.
  const double radius = std::max(settings_.sheath_radius, 0.75 * h);
  const core::Vec3 axis = inputs.axis.normalized();
  // The outflow holes: the ring of cells around the shaft 5–15 mm behind the tip, or, with only
  // the tip in the cavity (the rest in the canal), the ring around its last 5 mm.
  std::vector<int> holes, near_holes;
  for (int k = 0; k < grid_.nz(); ++k)
    for (int j = 0; j < grid_.ny(); ++j)
      for (int i = 0; i < grid_.nx(); ++i) {
        if (grid_.cell(i, j, k) != FlowCell::Fluid) continue;
        const core::Vec3 d = cell_centre(grid_, i, j, k) - inputs.tip;
        const double along = d.dot(axis);
        const double across = (d - along * axis).norm();
        const int c = grid_.cell_index(i, j, k);
        if (along > 0.0) continue;
        if (across <= radius) {
          (along > -h ? inflow_cells_ : sheath_cells_).push_back(c);
        } else if (across <= radius + h && along >= -0.015) {
          (along <= -0.005 ? holes : near_holes).push_back(c);
        }
      }
  if (holes.empty()) holes = std::move(near_holes);
  const auto at = [&](int c) {
    return std::array<int, 3>{c % grid_.nx(), (c / grid_.nx()) % grid_.ny(),
                              c / (grid_.nx() * grid_.ny())};
  };
  for (const int c : sheath_cells_) {
    const auto [i, j, k] = at(c);
    grid_.set_cell(i, j, k, FlowCell::Solid);
  }
  for (const int c : inflow_cells_) {
    const auto [i, j, k] = at(c);
    grid_.set_cell(i, j, k, FlowCell::Solid);
  }
  for (const int c : holes) {
    const auto [i, j, k] = at(c);
    grid_.set_cell(i, j, k, FlowCell::Open);
  }
  // Without an outflow the closed cavity cannot take a jet: no inflow cells then.
  if (holes.empty()) inflow_cells_.clear();
}

void CavityFlow::close_stranded() {
  if (close_stranded_pockets(grid_) == 0) return;
  // A closed cell may have been an inflow cell: keep only those still beside the flow.
  std::erase_if(inflow_cells_, [&](int c) {
    const int i = c % grid_.nx(), j = (c / grid_.nx()) % grid_.ny(),
              k = c / (grid_.nx() * grid_.ny());
    for (const auto& e : kNext)
      if (grid_.cell_or_solid(i + e[0], j + e[1], k + e[2]) != FlowCell::Solid) return false;
    return true;
  });
}

void CavityFlow::drive_inflow(const core::Vec3& axis, double inflow) {
  const double h = grid_.cell_size();
  const core::Vec3 a = axis.normalized();
  // Net outward area of the inflow cells' faces to the cavity, weighted by the axis: the flux
  // of a unit velocity along the axis.
  double flux = 0.0;
  for (const int c : inflow_cells_) {
    const int i = c % grid_.nx(), j = (c / grid_.nx()) % grid_.ny(),
              k = c / (grid_.nx() * grid_.ny());
    for (int n = 0; n < 6; ++n) {
      const auto& e = kNext[n];
      if (grid_.cell_or_solid(i + e[0], j + e[1], k + e[2]) == FlowCell::Solid) continue;
      flux += (a.x() * e[0] + a.y() * e[1] + a.z() * e[2]) * h * h;
    }
  }
  const double speed = flux > 1e-3 * h * h && inflow > 0.0 ? inflow / flux : 0.0;
  for (const int c : inflow_cells_) {
    const int i = c % grid_.nx(), j = (c / grid_.nx()) % grid_.ny(),
              k = c / (grid_.nx() * grid_.ny());
    grid_.set_solid_velocity(i, j, k, speed * a);
  }
}

void CavityFlow::advance(double dt, const CavityInputs& inputs) {
  const double h = grid_.cell_size();
  for (const BloodRelease& release : inputs.blood) {
    if (!(release.volume > 0.0)) continue;
    // Born in the cavity, not in the tissue's cell: the first non-solid cell out along the
    // normal, a cell to four cells out (a cell out when all of them are solid).
    core::Vec3 birth = release.site + h * release.normal;
    for (double out = h; out <= 4.0 * h; out += 0.5 * h) {
      const core::Vec3 at = release.site + out * release.normal;
      if (grid_.cell_or_solid(grid_.cell_of(at)) != FlowCell::Solid) {
        birth = at;
        break;
      }
    }
    particles_.emit(birth, release.normal, release.speed, release.volume, grid_, blood_);
    released_ += release.volume;
  }
  // Debris enters where it was cut off (in the open cell beside it when that lies in tissue).
  for (const DebrisRelease& shred : inputs.debris) {
    core::Vec3 at = shred.position;
    const CellCoord c = grid_.cell_of(at);
    if (grid_.cell_or_solid(c) == FlowCell::Solid) {
      for (const auto& e : kNext) {
        const CellCoord n{c.i + e[0], c.j + e[1], c.k + e[2]};
        if (grid_.cell_or_solid(n) == FlowCell::Solid) continue;
        at = grid_.origin() + h * core::Vec3(n.i + 0.5, n.j + 0.5, n.k + 0.5);
        break;
      }
    }
    debris_.add(at, shred.radius);
  }
  // Air comes in with the pump's fluid once the sheath's inflow cells are in the cavity.
  if (inflow_cells_.empty()) {
    bubbles_.admit(0.0, dt, core::Vec3::Zero(), grid_);
  } else {
    core::Vec3 inlet = core::Vec3::Zero();
    for (const int c : inflow_cells_) {
      const int i = c % grid_.nx(), j = (c / grid_.nx()) % grid_.ny(),
                k = c / (grid_.nx() * grid_.ny());
      inlet += grid_.origin() + h * core::Vec3(i + 0.5, j + 0.5, k + 0.5);
    }
    inlet /= static_cast<double>(inflow_cells_.size());
    // Born a cell ahead of the shaft's end, in the fluid the jet enters.
    bubbles_.admit(inputs.inflow_rate, dt, inlet + h * inputs.axis.normalized(), grid_);
  }
  gathered_ += dt;
  inflow_volume_ += std::max(0.0, inputs.inflow_rate) * dt;
  if (gathered_ < settings_.interval * (1.0 - 1e-9)) return;
  const double step = gathered_;
  const double inflow = inflow_volume_ / step;
  gathered_ = inflow_volume_ = 0.0;
  relabel(inputs);
  drive_inflow(inputs.axis, inflow);
  vortices_.advance(grid_, inflow_cells_.empty() ? 0.0 : inflow, step);
  FlowSettings flow = settings_.flow;
  flow.time_step = step;
  last_step_ = solver_.step(grid_, flow);
  if (!std::isfinite(last_step_.max_divergence))
    throw core::SimulationError("the distension flow's velocity is no longer finite", "cavity", -1,
                                flow_steps_, "the pressure projection diverged on this labelling");
  blood_.advect(grid_, step);
  particles_.advance(grid_, &vortices_, blood_, step);
  bubbles_.advance(grid_, inputs.up, step);
  debris_.advance(grid_, inputs.up, step);
  blood_.spill(grid_);
  ++flow_steps_;
}

double CavityFlow::view_transmission(const core::Vec3& eye, const core::Vec3& direction) const {
  const double h = grid_.cell_size();
  const double ds = 0.5 * h;
  const core::Vec3 d = direction.normalized();
  double depth = 0.0;  // ∫ c ds, m
  for (double s = 0.5 * ds; s < settings_.view_depth; s += ds) {
    const CellCoord at = grid_.cell_of(eye + s * d);
    if (!grid_.contains(at)) break;
    if (grid_.cell(at.i, at.j, at.k) == FlowCell::Solid) {
      if (s > h) break;  // the wall, or the sheath's own cells at the eye
      continue;
    }
    depth += blood_.at(grid_, at.i, at.j, at.k) * ds;
  }
  return std::exp(-settings_.extinction * depth);
}

}  // namespace viscera::sim::fluid
