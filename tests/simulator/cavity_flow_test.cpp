// The session's cavity flow (simulator/fluid/cavity_flow.h) in a hollow ball whose inner sphere
// (12 mm) is the cavity: the sheath's jet leaves through its outflow holes exactly what it
// brings; blood released at a site is conserved to rounding and clouds the optics; the grid
// follows a wall that moves and an obstacle put into the cavity.

#include "simulator/fluid/cavity_flow.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/error.h"
#include "core/primitives/icosphere.h"

using namespace viscera;
using namespace viscera::sim::fluid;

namespace {

struct HollowBall {
  core::SurfaceMesh surface;
  std::vector<double> marks;
};

/// Tissue between an outer sphere of 20 mm and an inner one of 12 mm (turned inside out), the
/// inner one marked as the cavity wall.
HollowBall hollow_ball() {
  HollowBall ball{core::make_icosphere(0.020, 4), {}};
  const core::SurfaceMesh inner = core::make_icosphere(0.012, 4);
  const int offset = static_cast<int>(ball.surface.vertices.size());
  ball.marks.assign(ball.surface.vertices.size(), 0.0);
  for (const auto& v : inner.vertices) {
    ball.surface.vertices.push_back(v);
    ball.marks.push_back(1.0);
  }
  for (const auto& t : inner.triangles)
    ball.surface.triangles.push_back({t[0] + offset, t[2] + offset, t[1] + offset});
  return ball;
}

CavityFlowSettings settings_24() {
  CavityFlowSettings settings;
  settings.resolution = 24;  // 1 mm cells across the 24 mm cavity
  settings.interval = 0.02;
  settings.sheath_radius = 1.5e-3;
  settings.flow.threads = 1;
  return settings;
}

/// The jet's inputs: the sheath along +z with its tip 4 mm below the centre.
CavityInputs jet(const HollowBall& ball, double inflow) {
  CavityInputs inputs;
  inputs.wall = ball.surface.vertices;
  inputs.sheath = true;
  inputs.tip = core::Vec3(0.0, 0.0, -0.004);
  inputs.axis = core::Vec3::UnitZ();
  inputs.inflow_rate = inflow;
  return inputs;
}

int count_cells(const FlowGrid& grid, FlowCell kind) {
  int n = 0;
  for (int k = 0; k < grid.nz(); ++k)
    for (int j = 0; j < grid.ny(); ++j)
      for (int i = 0; i < grid.nx(); ++i)
        n += grid.cell(i, j, k) == kind;
  return n;
}

/// m³/s flowing from non-open cells into the open cells.
double flux_into_open_cells(const FlowGrid& grid) {
  const double h = grid.cell_size();
  double flux = 0.0;
  for (int k = 0; k < grid.nz(); ++k)
    for (int j = 0; j < grid.ny(); ++j)
      for (int i = 0; i < grid.nx(); ++i) {
        if (grid.cell(i, j, k) != FlowCell::Open) continue;
        for (int axis = 0; axis < 3; ++axis) {
          const FaceDims d = grid.face_dims(axis);
          const int di = axis == 0, dj = axis == 1, dk = axis == 2;
          const auto& u = grid.velocity(axis);
          // The low face: inflow is +u; the high face: inflow is −u (from non-open cells).
          if (grid.cell_or_solid(i - di, j - dj, k - dk) != FlowCell::Open)
            flux += u[static_cast<std::size_t>(d.index(i, j, k))] * h * h;
          if (grid.cell_or_solid(i + di, j + dj, k + dk) != FlowCell::Open)
            flux -= u[static_cast<std::size_t>(d.index(i + di, j + dj, k + dk))] * h * h;
        }
      }
  return flux;
}

double blood_accounted(const CavityFlow& flow) {
  return flow.particles().carried_volume() + flow.particles().pending_volume() +
         flow.blood().total_volume(flow.grid()) + flow.blood().drained_volume() +
         flow.particles().lost_volume();
}

}  // namespace

TEST(CavityFlow, the_jet_leaves_through_the_outflow_holes_what_it_brings) {
  const HollowBall ball = hollow_ball();
  CavityFlow flow(ball.surface.vertices, ball.surface.triangles, ball.marks, settings_24(), 7);
  EXPECT_EQ(count_cells(flow.grid(), FlowCell::Open), 0);  // no sheath yet: a closed cavity
  const double inflow = 2e-6;                              // m³/s, 120 ml/min
  const CavityInputs inputs = jet(ball, inflow);
  for (int s = 0; s < 500; ++s)
    flow.advance(1e-3, inputs);
  EXPECT_EQ(flow.flow_steps(), 25);
  EXPECT_TRUE(flow.last_step().converged);
  EXPECT_LE(flow.grid().max_divergence(), flow.settings().flow.divergence_tolerance);
  EXPECT_GT(count_cells(flow.grid(), FlowCell::Open), 0);
  // Incompressible and closed but for the holes: what enters at the tip leaves there.
  const double h = flow.grid().cell_size();
  const double slack = flow.settings().flow.divergence_tolerance *
                       count_cells(flow.grid(), FlowCell::Fluid) * h * h * h;
  EXPECT_NEAR(flux_into_open_cells(flow.grid()), inflow, slack);
  // The jet runs along the axis ahead of the tip, faster than the cavity around.
  const core::Vec3 ahead = flow.grid().velocity_at(inputs.tip + core::Vec3(0.0, 0.0, 0.003));
  const core::Vec3 aside = flow.grid().velocity_at(core::Vec3(0.008, 0.0, -0.004));
  EXPECT_GT(ahead.z(), 0.0);
  EXPECT_GT(ahead.norm(), 2.0 * aside.norm());
}

TEST(CavityFlow, released_blood_is_conserved_and_clouds_the_view) {
  const HollowBall ball = hollow_ball();
  CavityFlow flow(ball.surface.vertices, ball.surface.triangles, ball.marks, settings_24(), 7);
  CavityInputs inputs = jet(ball, 1e-6);
  const core::Vec3 eye = inputs.tip;
  EXPECT_DOUBLE_EQ(flow.view_transmission(eye, core::Vec3::UnitZ()), 1.0);
  double lowest = 1.0, total = 0.0;
  for (int s = 0; s < 1500; ++s) {
    // 0.2 ml over the first 0.2 s from a site on the wall ahead of the optics, out of the wall.
    inputs.blood.clear();
    if (s < 200) {
      inputs.blood.push_back({core::Vec3(0.0, 0.0, 0.0115), -core::Vec3::UnitZ(), 0.02, 1e-9});
      total += 1e-9;
    }
    flow.advance(1e-3, inputs);
    lowest = std::min(lowest, flow.view_transmission(eye, core::Vec3::UnitZ()));
    ASSERT_NEAR(blood_accounted(flow), flow.released_blood(), 1e-12 * total + 1e-18) << s;
  }
  EXPECT_DOUBLE_EQ(flow.released_blood(), total);
  EXPECT_LT(lowest, flow.settings().obscured_transmission);
  EXPECT_TRUE(flow.obscured(eye, core::Vec3::UnitZ()) ||
              flow.view_transmission(eye, core::Vec3::UnitZ()) > lowest);
  // Looking sideways at the clear part of the cavity the view is better than through the blood.
  EXPECT_GT(flow.view_transmission(eye, -core::Vec3::UnitX()), lowest);
}

TEST(CavityFlow, the_grid_follows_a_moving_wall_and_keeps_the_blood) {
  HollowBall ball = hollow_ball();
  CavityFlow flow(ball.surface.vertices, ball.surface.triangles, ball.marks, settings_24(), 7);
  CavityInputs inputs = jet(ball, 0.0);
  inputs.sheath = false;
  inputs.blood.push_back({core::Vec3(0.0, 0.0, 0.0), core::Vec3::UnitX(), 0.0, 5e-9});
  flow.advance(0.02, inputs);
  inputs.blood.clear();
  const long long before = flow.relabellings();
  const auto centroid = [&] {
    core::Vec3 sum = core::Vec3::Zero();
    int n = 0;
    const FlowGrid& g = flow.grid();
    for (int k = 0; k < g.nz(); ++k)
      for (int j = 0; j < g.ny(); ++j)
        for (int i = 0; i < g.nx(); ++i)
          if (g.cell(i, j, k) == FlowCell::Fluid) {
            sum += g.origin() + g.cell_size() * core::Vec3(i + 0.5, j + 0.5, k + 0.5);
            ++n;
          }
    return core::Vec3(sum / n);
  };
  const core::Vec3 start = centroid();
  // The wall moves 2 mm along x (within the grid's margin of 3 cells).
  std::vector<core::Vec3> moved = ball.surface.vertices;
  for (auto& v : moved)
    v.x() += 0.002;
  inputs.wall = moved;
  flow.advance(0.02, inputs);
  EXPECT_EQ(flow.relabellings(), before + 1);
  EXPECT_NEAR((centroid() - start).x(), 0.002, 0.5 * flow.grid().cell_size());
  EXPECT_NEAR(blood_accounted(flow), 5e-9, 1e-20);
  // A wall that stays where it was labelled is not labelled again.
  flow.advance(0.02, inputs);
  EXPECT_EQ(flow.relabellings(), before + 1);
}

TEST(CavityFlow, an_obstacle_in_the_cavity_is_solid_until_it_leaves) {
  const HollowBall ball = hollow_ball();
  CavityFlow flow(ball.surface.vertices, ball.surface.triangles, ball.marks, settings_24(), 7);
  core::SurfaceMesh polyp = core::make_icosphere(0.003, 2);
  for (auto& v : polyp.vertices)
    v += core::Vec3(0.005, 0.0, 0.0);
  CavityInputs inputs = jet(ball, 0.0);
  inputs.sheath = false;
  const FlowGrid& g = flow.grid();
  const core::Vec3 local = (core::Vec3(0.005, 0.0, 0.0) - g.origin()) / g.cell_size();
  const int i = static_cast<int>(local.x()), j = static_cast<int>(local.y()),
            k = static_cast<int>(local.z());
  const int fluid_before = count_cells(g, FlowCell::Fluid);
  inputs.obstacles.push_back({polyp.vertices, &polyp.triangles});
  flow.advance(0.02, inputs);
  EXPECT_EQ(g.cell(i, j, k), FlowCell::Solid);
  // About the sphere's volume in cells: 113 mm³ at 1 mm cells.
  const int taken = fluid_before - count_cells(g, FlowCell::Fluid);
  EXPECT_NEAR(taken, 4.0 / 3.0 * std::numbers::pi * 27.0, 30.0);
  inputs.obstacles.clear();
  flow.advance(0.02, inputs);
  EXPECT_EQ(g.cell(i, j, k), FlowCell::Fluid);
  EXPECT_EQ(count_cells(g, FlowCell::Fluid), fluid_before);
  // A due step without the wall's positions is refused, not labelled from nothing.
  inputs.wall = {};
  EXPECT_THROW(flow.advance(0.02, inputs), core::UsageError);
}

TEST(CavityFlow, air_comes_in_with_the_jet_and_rises_or_leaves_through_the_holes) {
  const HollowBall ball = hollow_ball();
  CavityFlow flow(ball.surface.vertices, ball.surface.triangles, ball.marks, settings_24(), 7);
  CavityInputs inputs = jet(ball, 2e-6);
  inputs.up = core::Vec3::UnitZ();
  for (int s = 0; s < 1000; ++s)
    flow.advance(1e-3, inputs);
  const AirBubbles& bubbles = flow.bubbles();
  // The pump started from rest: the tubing's burst (2 ml is less than one bubble's 5 ml).
  EXPECT_EQ(bubbles.admitted(), flow.settings().bubbles.burst_count);
  EXPECT_EQ(bubbles.admitted(),
            bubbles.flushed() + bubbles.lost() + static_cast<long long>(bubbles.size()));
  // Born ahead of the tip (4 mm below the centre); in 1 s those still in the cavity rose.
  double mean_height = 0.0;
  for (const core::Vec3& p : bubbles.positions())
    mean_height += p.z() / static_cast<double>(bubbles.size());
  if (!bubbles.positions().empty()) {
    EXPECT_GT(mean_height, 0.0);
  }
  for (const core::Vec3& p : bubbles.positions())
    EXPECT_LT(p.norm(), 0.012 + flow.grid().cell_size());  // inside the cavity
}

TEST(CavityFlow, debris_enters_where_it_was_cut_off_and_settles_or_leaves_through_the_holes) {
  const HollowBall ball = hollow_ball();
  CavityFlow flow(ball.surface.vertices, ball.surface.triangles, ball.marks, settings_24(), 7);
  CavityInputs inputs = jet(ball, 2e-6);
  inputs.up = core::Vec3::UnitZ();
  // Four shreds of 0.5 mm cut off 6 mm above the centre; one inside the wall (13 mm out) is
  // admitted in the open cell beside it.
  for (int i = 0; i < 4; ++i)
    inputs.debris.push_back({core::Vec3(0.002 * (i - 1.5), 0.0, 0.006), 0.5e-3});
  inputs.debris.push_back({core::Vec3(0.0, 0.013, 0.0), 0.5e-3});
  flow.advance(1e-3, inputs);
  inputs.debris.clear();
  const SuspendedParticles& debris = flow.debris();
  ASSERT_EQ(debris.admitted(), 5);
  EXPECT_NE(flow.grid().cell_or_solid(flow.grid().cell_of(debris.positions()[4])), FlowCell::Solid);
  for (int s = 0; s < 1000; ++s)
    flow.advance(1e-3, inputs);
  // Every shred is still in the cavity, drawn out through the holes or lost: none vanished.
  EXPECT_EQ(debris.admitted(),
            debris.flushed() + debris.lost() + static_cast<long long>(debris.size()));
  // Tissue settles: in 1 s the shreds that stayed sank from where they came in (6 mm up).
  for (std::size_t i = 0; i < debris.size(); ++i) {
    EXPECT_LT(debris.positions()[i].norm(), 0.012 + flow.grid().cell_size());
    if (i < 4 && debris.positions()[i].head<2>().norm() < 0.004) {
      EXPECT_LT(debris.positions()[i].z(), 0.006);
    }
  }
}
