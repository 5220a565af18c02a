// The second port's tool as the view draws it (issue 19 §3): a shaft up to the jaws' hinge and
// two jaws that open along the tool's up, measured on the mesh.

#include "simulator/view/port_instrument.h"

#include <gtest/gtest.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <algorithm>
#include <limits>

namespace viscera::view {
namespace {

sim::SecondPort grasper(bool closed) {
  sim::SecondPort port;
  port.inserted = true;
  port.tool = sim::LaparoscopicTool::Grasper;
  port.tip = core::Vec3(0.01, 0.02, 0.03);
  port.axis = core::Vec3(0, 0, -1);
  port.up = core::Vec3(0, 1, 0);
  port.jaws_closed = closed;
  return port;
}

/// Extent of the mesh's points along `direction` within `slab` m of the tip's plane across the
/// shaft (the jaws' tips).
double spread_at_tip(vtkPolyData* mesh, const sim::SecondPort& port, const core::Vec3& direction,
                     double slab) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i) {
    core::Vec3 p;
    mesh->GetPoint(i, p.data());
    if (std::abs((p - port.tip).dot(port.axis)) > slab) continue;
    lo = std::min(lo, (p - port.tip).dot(direction));
    hi = std::max(hi, (p - port.tip).dot(direction));
  }
  return hi - lo;
}

TEST(PortInstrument, an_empty_port_draws_nothing) {
  EXPECT_EQ(port_instrument_mesh(sim::SecondPort{})->GetNumberOfPoints(), 0);
}

TEST(PortInstrument, the_shaft_ends_at_the_hinge_and_open_jaws_spread_to_their_opening) {
  const PortInstrumentShape shape;
  const sim::SecondPort open = grasper(false);
  const auto mesh = port_instrument_mesh(open, shape);
  // Shaft: 2 rings of 12, then 8 corners per jaw.
  ASSERT_EQ(mesh->GetNumberOfPoints(), 24 + 16);
  double far = 0.0, near = std::numeric_limits<double>::infinity();
  for (vtkIdType i = 0; i < 24; ++i) {
    core::Vec3 p;
    mesh->GetPoint(i, p.data());
    const double behind = (open.tip - p).dot(open.axis);
    far = std::max(far, behind);
    near = std::min(near, behind);
    EXPECT_NEAR((p - open.tip - (p - open.tip).dot(open.axis) * open.axis).norm(),
                shape.shaft_radius, 1e-6);  // float points
  }
  EXPECT_NEAR(near, shape.jaw_length, 1e-6);
  EXPECT_NEAR(far, shape.jaw_length + shape.shaft_length, 1e-6);
  // The jaws' tips stand the opening apart along up (plus a jaw's thickness), closed they meet.
  const double open_spread = spread_at_tip(mesh, open, open.up, 1e-3);
  EXPECT_GT(open_spread, shape.jaw_opening);
  EXPECT_LT(open_spread, shape.jaw_opening + 2.0 * shape.jaw_thickness);
  const sim::SecondPort closed = grasper(true);
  EXPECT_LT(spread_at_tip(port_instrument_mesh(closed, shape), closed, closed.up, 1e-3),
            3.0 * shape.jaw_thickness);
}

TEST(PortInstrument, a_hook_or_cannula_has_no_jaws_and_its_shaft_runs_to_the_tip) {
  sim::SecondPort hook = grasper(false);
  hook.tool = sim::LaparoscopicTool::Suction;
  const auto mesh = port_instrument_mesh(hook);
  ASSERT_EQ(mesh->GetNumberOfPoints(), 24);
  double nearest = std::numeric_limits<double>::infinity();
  for (vtkIdType i = 0; i < 24; ++i) {
    core::Vec3 p;
    mesh->GetPoint(i, p.data());
    nearest = std::min(nearest, (hook.tip - p).dot(hook.axis));
  }
  EXPECT_NEAR(nearest, 0.0, 1e-6);
}

}  // namespace
}  // namespace viscera::view
