// The flow grid of a cavity (simulator/fluid/cavity_grid.h): in a hollow ball the fluid cells
// fill the inner sphere and nothing else, with the sphere's volume to a cell; in a hysteroscopy
// patient they fill the uterine cavity (every fluid cell lies nearest to the cavity wall, none
// outside the organ), and a jet from the internal os sets the whole cavity moving.

#include "simulator/fluid/cavity_grid.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/error.h"
#include "core/primitives/icosphere.h"
#include "simulator/camera/surface_bvh.h"
#include "simulator/fluid/stable_fluids.h"
#include "templates/template_catalog.h"

using namespace viscera;
using namespace viscera::sim::fluid;

namespace {

double fluid_volume(const FlowGrid& grid) {
  int cells = 0;
  for (int k = 0; k < grid.nz(); ++k)
    for (int j = 0; j < grid.ny(); ++j)
      for (int i = 0; i < grid.nx(); ++i)
        cells += grid.cell(i, j, k) == FlowCell::Fluid;
  return cells * std::pow(grid.cell_size(), 3);
}

core::Vec3 centre_of(const FlowGrid& grid, int i, int j, int k) {
  return grid.origin() + grid.cell_size() * core::Vec3(i + 0.5, j + 0.5, k + 0.5);
}

}  // namespace

TEST(CavityGrid, a_hollow_ball_fills_its_inner_sphere) {
  // Tissue between two spheres: the outer one outward, the inner one turned inside out.
  core::SurfaceMesh shell = core::make_icosphere(0.020, 4);
  const core::SurfaceMesh inner = core::make_icosphere(0.012, 4);
  const int offset = static_cast<int>(shell.vertices.size());
  std::vector<double> marks(shell.vertices.size(), 0.0);
  for (const auto& v : inner.vertices) {
    shell.vertices.push_back(v);
    marks.push_back(1.0);
  }
  for (const auto& t : inner.triangles)
    shell.triangles.push_back({t[0] + offset, t[2] + offset, t[1] + offset});
  const FlowGrid grid = label_cavity(shell.vertices, shell.triangles, marks, 0.001);
  const double sphere = 4.0 / 3.0 * std::numbers::pi * std::pow(0.012, 3);
  EXPECT_NEAR(fluid_volume(grid), sphere, 0.05 * sphere);
  for (int k = 0; k < grid.nz(); ++k)
    for (int j = 0; j < grid.ny(); ++j)
      for (int i = 0; i < grid.nx(); ++i) {
        if (grid.cell(i, j, k) == FlowCell::Fluid) {
          EXPECT_LT(centre_of(grid, i, j, k).norm(), 0.012);
        }
      }
  EXPECT_THROW(label_cavity(shell.vertices, shell.triangles,
                            std::vector<double>(shell.vertices.size(), 0.0), 0.001),
               core::InputError);
}

TEST(CavityGrid, pockets_cut_off_from_the_outflow_are_closed) {
  // Three pockets in a 12×5×5 box walled all round: x 1–3 with the outflow, x 5–6 and x 8–10.
  FlowGrid grid(12, 5, 5, 0.001);
  for (int k = 0; k < 5; ++k)
    for (int j = 0; j < 5; ++j)
      for (int i = 0; i < 12; ++i)
        if (i == 0 || i == 4 || i == 7 || i == 11 || j == 0 || j == 4 || k == 0 || k == 4)
          grid.set_cell(i, j, k, FlowCell::Solid);
  grid.set_cell(1, 2, 2, FlowCell::Open);
  grid.update_faces();
  EXPECT_EQ(close_stranded_pockets(grid), 2 * 9 + 3 * 9);
  EXPECT_EQ(grid.cell(2, 2, 2), FlowCell::Fluid);
  EXPECT_EQ(grid.cell(5, 2, 2), FlowCell::Solid);
  EXPECT_EQ(grid.cell(9, 2, 2), FlowCell::Solid);
  // Without an outflow the largest pocket stays.
  grid.set_cell(1, 2, 2, FlowCell::Solid);
  grid.set_cell(1, 1, 1, FlowCell::Solid);
  for (int k = 1; k < 4; ++k)
    for (int j = 1; j < 4; ++j)
      for (int i = 8; i < 11; ++i)
        grid.set_cell(i, j, k, FlowCell::Fluid);
  EXPECT_EQ(close_stranded_pockets(grid), 3 * 9 - 2);
  EXPECT_EQ(grid.cell(9, 2, 2), FlowCell::Fluid);
  EXPECT_EQ(grid.cell(2, 2, 2), FlowCell::Solid);
}

TEST(CavityGrid, a_hysteroscopy_patient_s_cavity_fills_and_flows) {
  const core::Scenario patient = templates::build_from_template("hysteroscopy", {}, 1);
  const core::SceneObject& uterus = *patient.find_object("uterus");
  const auto& marks = uterus.surface.vertex_attributes.at("cavity");
  FlowGrid grid = label_cavity(uterus.surface.vertices, uterus.surface.triangles, marks, 0.001);
  const double volume = fluid_volume(grid);
  EXPECT_GT(volume, 0.5e-6);  // ml
  EXPECT_LT(volume, 30e-6);
  // Every fluid cell lies in the cavity: its nearest wall is the cavity's (or the canal's).
  const sim::SurfaceBvh bvh(uterus.surface.triangles, uterus.surface.vertices);
  for (int k = 0; k < grid.nz(); ++k)
    for (int j = 0; j < grid.ny(); ++j)
      for (int i = 0; i < grid.nx(); ++i) {
        if (grid.cell(i, j, k) != FlowCell::Fluid) continue;
        const auto near = bvh.nearest(centre_of(grid, i, j, k));
        const auto& tri = uterus.surface.triangles[static_cast<std::size_t>(near.triangle)];
        EXPECT_GE(marks[static_cast<std::size_t>(tri[0])] +
                      marks[static_cast<std::size_t>(tri[1])] +
                      marks[static_cast<std::size_t>(tri[2])],
                  1.0);
      }
  // A jet into the cavity from the cell nearest the internal os, an outflow beside it: after
  // a second the flow stirs most of the cavity and leaves no divergence.
  core::Vec3 os = core::Vec3::Zero();
  for (const auto& mark : patient.landmarks)
    if (mark.id == "cervix-internal-os") os = mark.position;
  int best = -1;
  double best_distance = 1e9;
  for (int c = 0; c < grid.cell_count(); ++c) {
    const int i = c % grid.nx(), j = (c / grid.nx()) % grid.ny(), k = c / (grid.nx() * grid.ny());
    const double d = (centre_of(grid, i, j, k) - os).norm();
    if (grid.cell(i, j, k) == FlowCell::Fluid && d < best_distance) best = c, best_distance = d;
  }
  ASSERT_GE(best, 0);
  const int bi = best % grid.nx(), bj = (best / grid.nx()) % grid.ny(),
            bk = best / (grid.nx() * grid.ny());
  grid.set_cell(bi, bj, bk, FlowCell::Solid, core::Vec3(0.0, 0.0, 0.1));  // up into the cavity
  bool outflow = false;
  for (int di = -1; di <= 1 && !outflow; di += 2)
    if (grid.cell(bi + di, bj, bk) == FlowCell::Fluid)
      grid.set_cell(bi + di, bj, bk, FlowCell::Open), outflow = true;
  ASSERT_TRUE(outflow);
  grid.update_faces();
  FlowSettings settings;
  settings.threads = 1;
  settings.divergence_tolerance = 1e-3;
  for (int s = 0; s < 100; ++s)
    ASSERT_TRUE(step_flow(grid, settings).converged);
  EXPECT_LE(grid.max_divergence(), 1e-3);
  int moving = 0, fluid = 0;
  for (int k = 0; k < grid.nz(); ++k)
    for (int j = 0; j < grid.ny(); ++j)
      for (int i = 0; i < grid.nx(); ++i) {
        if (grid.cell(i, j, k) != FlowCell::Fluid) continue;
        ++fluid;
        moving += grid.velocity_at(centre_of(grid, i, j, k)).norm() > 1e-4;
      }
  EXPECT_GT(moving, fluid / 2);
}
