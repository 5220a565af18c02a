#include "simulator/haptics/rigid_instrument.h"

#include <gtest/gtest.h>

#include <numbers>

#include "core/error.h"
#include "simulator/haptics/device_limits.h"
#include "tests/simulator/sim_fixtures.h"

namespace viscera::sim {
namespace {

/// A flat sheet at z = 0 facing +z, 20 cm wide, in 20 × 20 squares.
viscera::testing::Sheet sheet() {
  return viscera::testing::make_sheet(20, 0.1);
}

/// The shaft lying along +x at height z (the frame's +z turned onto +x).
InstrumentPose lying(double x0, double z) {
  InstrumentPose pose;
  pose.position = {x0, 0.0013, z};
  pose.orientation =
      Eigen::Quaterniond(Eigen::AngleAxisd(std::numbers::pi / 2, core::Vec3::UnitY()));
  return pose;
}

TEST(RigidInstrument,
     a_shaft_pressed_flat_feels_the_sum_of_its_points_and_no_torque_about_its_middle) {
  const viscera::testing::Sheet s = sheet();
  const ProxySurface surface(s.faces);
  RigidInstrument tool = RigidInstrument::shaft(0.1, 11, 100.0);
  tool.reset(lying(-0.05, 0.01));
  tool.update(lying(-0.05, -0.002), surface, s.positions);
  EXPECT_TRUE(tool.axis().isApprox(core::Vec3::UnitX(), 1e-12));
  EXPECT_TRUE(tool.force().isApprox(core::Vec3(0, 0, 11 * 100.0 * 0.002), 1e-9));
  EXPECT_LT(tool.torque_about({0.0, 0.0013, -0.002}).norm(), 1e-12);
  EXPECT_EQ(tool.tissue_loads().size(), 11u);
  core::Vec3 on_tissue = core::Vec3::Zero();
  for (const auto& load : tool.tissue_loads())
    on_tissue += load.force;
  EXPECT_TRUE((on_tissue + tool.force()).isZero(1e-12));  // action and reaction
}

TEST(RigidInstrument, pressing_with_the_tip_only_gives_the_lever_torque) {
  const viscera::testing::Sheet s = sheet();
  const ProxySurface surface(s.faces);
  RigidInstrument tool = RigidInstrument::shaft(0.1, 11, 100.0);
  // Tilted 30° below the horizontal, so only the tip (x = 0.0866 + x0) reaches below z = 0.
  InstrumentPose pose = lying(-0.05, 0.047);
  pose.orientation = Eigen::Quaterniond(
      Eigen::AngleAxisd(std::numbers::pi / 2 + std::numbers::pi / 6, core::Vec3::UnitY()));
  InstrumentPose above = pose;
  above.position.z() = 0.06;  // approach from above the tissue
  tool.reset(above);
  tool.update(pose, surface, s.positions);
  ASSERT_EQ(tool.tissue_loads().size(), 1u);
  const core::Vec3 tip = tool.point(10);
  EXPECT_LT(tip.z(), 0.0);
  const core::Vec3 torque = tool.torque_about(pose.position);
  EXPECT_TRUE(torque.isApprox((tip - pose.position).cross(tool.force()), 1e-12));
  // The device renders the torque within its pitch/yaw limit.
  const ClampedFeedback clamped = clamp_to_device(tool.force(), torque, tool.axis());
  EXPECT_LE(clamped.torque.norm(), 0.5 + 1e-12);
  EXPECT_THROW(RigidInstrument::shaft(0.1, 1, 100.0), core::UsageError);
}

}  // namespace
}  // namespace viscera::sim
