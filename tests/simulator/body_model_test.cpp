#include "simulator/dynamics/body_model.h"

#include <gtest/gtest.h>

namespace viscera::sim {
namespace {

TEST(BodyModel, node_distance_stiffness_of_one_tet_sums_a_third_of_k_d_over_d0_squared_per_edge) {
  // The corner tet of a cube of side L: the corner node has three edges of length L, each other
  // node one edge of L (to the corner) and two of √2 L. A fifth node lies on no tet.
  const double side = 0.01;
  BodyModel model;
  model.mesh.nodes = {core::Vec3::Zero(), core::Vec3(side, 0.0, 0.0), core::Vec3(0.0, side, 0.0),
                      core::Vec3(0.0, 0.0, side), core::Vec3(1.0, 1.0, 1.0)};
  model.mesh.tets = {{0, 1, 2, 3}};
  core::Material material;
  material.distance_stiffness = 20e3;  // Pa
  model.materials = {material};
  model.tet_material = {0};

  const std::vector<double> k = node_distance_stiffness(model, model.mesh.nodes);

  // k_D = 20 kPa × V0/6 with V0 = L³/6, for every edge of the one tet.
  const double k_d = 20e3 * (side * side * side / 6.0) / 6.0;
  const double l2 = side * side;
  ASSERT_EQ(k.size(), 5u);
  EXPECT_NEAR(k[0], (3.0 * k_d / l2) / 3.0, 1e-12);
  for (int i = 1; i <= 3; ++i)
    EXPECT_NEAR(k[static_cast<std::size_t>(i)], (k_d / l2 + 2.0 * k_d / (2.0 * l2)) / 3.0, 1e-12);
  EXPECT_EQ(k[4], 0.0);
}

}  // namespace
}  // namespace viscera::sim
