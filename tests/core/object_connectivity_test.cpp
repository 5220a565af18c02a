#include "core/modelling/object_connectivity.h"

#include <gtest/gtest.h>

#include <limits>
#include <set>

#include "core/error.h"
#include "core/modelling/layered_body.h"
#include "core/primitives/ball_primitive.h"
#include "core/random.h"

namespace viscera::core {
namespace {

/// Index of the nearest point by brute force, lowest index on ties.
int brute_nearest(const std::vector<Vec3>& points, const Vec3& p) {
  int best = -1;
  double best_distance = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double d = (points[i] - p).squaredNorm();
    if (d < best_distance) {
      best_distance = d;
      best = static_cast<int>(i);
    }
  }
  return best;
}

TEST(ObjectConnectivity, pairs_are_exactly_the_nearest_knots_within_the_distance) {
  Rng rng(7);
  std::vector<Vec3> a, b;
  for (int i = 0; i < 400; ++i)
    a.emplace_back(rng.uniform(0, 0.05), rng.uniform(0, 0.05), rng.uniform(0, 0.01));
  for (int j = 0; j < 150; ++j)
    b.emplace_back(rng.uniform(0, 0.05), rng.uniform(0, 0.05), rng.uniform(0.008, 0.02));
  const double within = 0.004;
  const auto pairs = nearest_knot_pairs(a, b, within);
  ASSERT_FALSE(pairs.empty());
  const std::set<std::array<int, 2>> found(pairs.begin(), pairs.end());
  EXPECT_EQ(found.size(), pairs.size());
  for (const auto& [i, j] : pairs) {
    EXPECT_LT((a[static_cast<std::size_t>(i)] - b[static_cast<std::size_t>(j)]).norm(), within);
    EXPECT_TRUE(brute_nearest(b, a[static_cast<std::size_t>(i)]) == j ||
                brute_nearest(a, b[static_cast<std::size_t>(j)]) == i);
  }
  // And nothing is missed: every knot whose nearest partner is within reach is paired with it.
  for (std::size_t i = 0; i < a.size(); ++i) {
    const int j = brute_nearest(b, a[i]);
    if ((a[i] - b[static_cast<std::size_t>(j)]).norm() < within) {
      EXPECT_TRUE(found.contains({static_cast<int>(i), j})) << i;
    }
  }
  for (std::size_t j = 0; j < b.size(); ++j) {
    const int i = brute_nearest(a, b[j]);
    if ((a[static_cast<std::size_t>(i)] - b[j]).norm() < within) {
      EXPECT_TRUE(found.contains({i, static_cast<int>(j)})) << j;
    }
  }
}

Scenario two_touching_balls(double gap) {
  Scenario scenario;
  for (const auto& [id, x] :
       {std::pair<std::string, double>{"uterus", 0.0}, {"ovary", 0.05 + gap}}) {
    SceneObject object;
    object.id = id;
    object.surface = tessellate_ball(make_ball(Vec3(x, 0, 0), 0.025, 0, 3));
    object.body_kind = BodyKind::MassSpring;
    object.body =
        mass_spring_body(layered_mass_spring_net(object.surface, {1, 0.004, LayerMode::Offset}));
    scenario.objects.push_back(object);
  }
  return scenario;
}

TEST(ObjectConnectivity, connects_two_organs_where_they_touch_and_groups_them) {
  Scenario scenario = two_touching_balls(0.001);
  const Connection c = connect_objects(scenario, "uterus", "ovary", 0.005, 250.0);
  ASSERT_FALSE(c.node_pairs.empty());
  EXPECT_EQ(c.object_a, "uterus");
  EXPECT_EQ(c.stiffness, 250.0);
  for (const auto& [i, j] : c.node_pairs) {
    const Vec3 pa = scenario.objects[0].body.nodes[static_cast<std::size_t>(i)];
    const Vec3 pb = scenario.objects[1].body.nodes[static_cast<std::size_t>(j)];
    EXPECT_LT((pa - pb).norm(), 0.005);
    EXPECT_GT(pa.x(), 0.015);  // only knots facing the other ball
    EXPECT_LT(pb.x(), 0.036);
  }
  EXPECT_TRUE(connect_objects(scenario, "uterus", "ovary", 0.0009).node_pairs.empty());
  assign_organ_group(scenario, "adnexa", {"uterus", "ovary"});
  EXPECT_EQ(organ_groups(scenario).at("adnexa"), (std::vector<std::string>{"uterus", "ovary"}));
  EXPECT_THROW(assign_organ_group(scenario, "adnexa", {"tube"}), UsageError);
  EXPECT_THROW(connect_objects(scenario, "uterus", "uterus", 0.01), UsageError);
  EXPECT_THROW(connect_objects(scenario, "uterus", "bladder", 0.01), UsageError);
}

}  // namespace
}  // namespace viscera::core
