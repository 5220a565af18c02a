#include "core/modelling/model_document.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/error.h"
#include "core/materials/shipped_materials.h"
#include "core/modelling/model_scene.h"
#include "core/modelling/object_connectivity.h"

namespace viscera::core {
namespace {

ModelDocument ball_model(const std::string& id, const Vec3& center, double radius) {
  ModelDocument m;
  m.id = id;
  m.kind = ModelKind::Ball;
  m.ball = make_ball(center, radius, 0, 2);
  return m;
}

ModelDocument pipe_model() {
  ModelDocument m;
  m.id = "vessel";
  m.kind = ModelKind::Pipe;
  m.pipe =
      make_pipe_network({Vec3(0, 0, 0), Vec3(0, 0, 0.03), Vec3(0, 0, 0.06)}, {0.004, 0.004, 0.004});
  m.pipe.ring_segments = 12;
  PipeBranch child;
  child.points = {Vec3(0.025, 0, 0.04)};
  child.radii = {0.003};
  child.parent = 0;
  child.attach = 0.5;
  EXPECT_EQ(add_model_branch(m, child), 1);
  return m;
}

TEST(ModelDocument, json_round_trips_every_kind_to_the_same_bytes) {
  ModelDocument ball = ball_model("ball", Vec3(0, 0, 0.1), 0.02);
  ball.layering = ModelLayering{{2, 0.004, LayerMode::Scale}, true, 0.0};
  ball.material = shipped_material("liver");
  ball.fixed = {{Vec3(0, 0, 0.08), 0.005}};
  ball.connections = {{"vessel", 0.01, 50.0}};
  ball.group = "abdomen";
  ModelDocument flat;
  flat.id = "sheet";
  flat.kind = ModelKind::Flat;
  flat.flat = make_flat(Vec3::Zero(), Vec3(0.05, 0, 0), Vec3(0, 0.04, 0), 3, 5, 0.002);
  flat.flat.open = true;
  for (const ModelDocument& m : {ball, flat, pipe_model()}) {
    const nlohmann::json json = model_to_json(m);
    const ModelDocument back = model_from_json(json, "m.json");
    EXPECT_EQ(back, m) << m.id;
    EXPECT_EQ(model_to_json(back).dump(), json.dump()) << m.id;
  }
}

TEST(ModelDocument, control_points_of_a_pipe_network_are_its_branches_points_in_order) {
  ModelDocument m = pipe_model();
  const auto points = model_control_points(m);
  ASSERT_EQ(points.size(), 4u);
  move_model_control_point(m, 3, Vec3(0.03, 0.0, 0.045));
  EXPECT_EQ(m.pipe.branches[1].points[0], Vec3(0.03, 0.0, 0.045));
  move_model_control_point(m, 1, Vec3(0.001, 0.0, 0.03));
  EXPECT_EQ(m.pipe.branches[0].points[1], Vec3(0.001, 0.0, 0.03));
  EXPECT_THROW(move_model_control_point(m, 4, Vec3::Zero()), UsageError);
  EXPECT_THROW(move_model_control_point(m, -1, Vec3::Zero()), UsageError);
  ModelDocument ball = ball_model("b", Vec3::Zero(), 0.01);
  PipeBranch branch;
  branch.points = {Vec3(0, 0, 1)};
  branch.radii = {0.001};
  EXPECT_THROW(add_model_branch(ball, branch), UsageError);
  ModelDocument bad_parent = pipe_model();
  branch.parent = 5;
  EXPECT_THROW(add_model_branch(bad_parent, branch), UsageError);
  EXPECT_EQ(bad_parent.pipe.branches.size(), 2u);  // unchanged
}

TEST(ModelDocument, errors_name_the_file_and_the_member) {
  nlohmann::json json = model_to_json(ball_model("ball", Vec3::Zero(), 0.02));
  json["primitive"]["radius"] = "big";
  try {
    model_from_json(json, "ball.json");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.location().file, "ball.json");
    EXPECT_EQ(e.location().json_pointer, "/primitive/radius");
  }
  json = model_to_json(ball_model("ball", Vec3::Zero(), 0.02));
  json["version"] = 2;
  EXPECT_THROW(model_from_json(json, "ball.json"), UnsupportedVersionError);
  json = model_to_json(ball_model("Ball!", Vec3::Zero(), 0.02));
  EXPECT_THROW(model_from_json(json, "ball.json"), ValidationError);
  json = model_to_json(ball_model("ball", Vec3::Zero(), 0.02));
  json["primitive"]["control_points"].erase(0);
  EXPECT_THROW(model_from_json(json, "ball.json"), ValidationError);
}

TEST(ModelScene, layered_ball_body_is_the_shell_with_its_mass_and_fixed_nodes) {
  const double r = 0.02, t = 0.005;
  ModelDocument m = ball_model("ball", Vec3(0, 0, 0.05), r);
  m.ball.subdivisions = 3;
  m.layering = ModelLayering{{1, t, LayerMode::Offset}, false, 0.0};
  m.material = shipped_material("myometrium");
  m.fixed = {{Vec3(0, 0, 0.05 - r), 0.006}};
  const SceneObject object = build_model_object(m);
  EXPECT_EQ(object.body_kind, BodyKind::TetMesh);
  EXPECT_EQ(object.material, "myometrium");
  const double pi = std::numbers::pi;
  const double shell = 4.0 / 3.0 * pi * (std::pow(r, 3) - std::pow(r - t, 3));
  // The polyhedral sphere of 1280 triangles is 0.5 % smaller than the sphere.
  EXPECT_NEAR(total_volume(object.body), shell, 0.03 * shell);
  double mass = 0.0;
  for (const double node_mass : object.body.node_mass)
    mass += node_mass;
  EXPECT_NEAR(mass, m.material->density * total_volume(object.body), 1e-9 * mass);
  int fixed = 0;
  for (std::size_t n = 0; n < object.body.nodes.size(); ++n) {
    const bool inside = (object.body.nodes[n] - m.fixed[0].center).norm() <= 0.006;
    EXPECT_EQ(object.body.fixed[n] != 0, inside);
    fixed += inside;
  }
  EXPECT_GT(fixed, 0);
  // The visual surface rides on the body's first nodes.
  ASSERT_EQ(object.embedding.tet.size(), object.surface.vertices.size());
  for (std::size_t v = 0; v < object.surface.vertices.size(); ++v)
    EXPECT_EQ(object.body.nodes[v], object.surface.vertices[v]);

  m.fixed = {{Vec3(1, 1, 1), 0.001}};
  EXPECT_THROW(build_model_object(m), ValidationError);
}

TEST(ModelScene, scene_connects_nearest_knots_groups_and_refuses_dangling_links) {
  ModelDocument upper = ball_model("upper", Vec3(0, 0, 0.021), 0.02);
  ModelDocument lower = ball_model("lower", Vec3(0, 0, -0.021), 0.02);
  upper.group = lower.group = "pair";
  upper.connections = {{"lower", 0.01, 80.0}};
  const Scenario scenario = build_model_scenario({upper, lower});
  EXPECT_EQ(build_model_scenario({upper, lower}), scenario);  // same models, same scene
  ASSERT_EQ(scenario.connections.size(), 1u);
  const Connection& c = scenario.connections.front();
  EXPECT_EQ(c.stiffness, 80.0);
  const Connection direct = connect_objects(scenario, "upper", "lower", 0.01, 80.0);
  EXPECT_EQ(c.node_pairs, direct.node_pairs);
  ASSERT_FALSE(c.node_pairs.empty());
  for (const auto& [a, b] : c.node_pairs) {
    const Vec3 pa = scenario.objects[0].body.nodes[static_cast<std::size_t>(a)];
    const Vec3 pb = scenario.objects[1].body.nodes[static_cast<std::size_t>(b)];
    EXPECT_LT((pa - pb).norm(), 0.01);
    EXPECT_LT(pa.z(), 0.011);  // only knots near where the balls touch
  }
  EXPECT_EQ(organ_groups(scenario).at("pair"), (std::vector<std::string>{"upper", "lower"}));

  upper.connections = {{"missing", 0.01, 80.0}};
  EXPECT_THROW(build_model_scenario({upper, lower}), ValidationError);
  upper.connections = {{"lower", 1e-4, 80.0}};
  EXPECT_THROW(build_model_scenario({upper, lower}), ValidationError);
  upper.connections.clear();
  upper.material = shipped_material("liver");
  lower.material = shipped_material("liver");
  lower.material->density += 1.0;
  EXPECT_THROW(build_model_scenario({upper, lower}), ValidationError);
  EXPECT_THROW(build_model_scenario({upper, upper}), UsageError);
}

}  // namespace
}  // namespace viscera::core
