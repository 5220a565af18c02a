#include "templates/variability/scenario_variation.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "core/mesh/surface_embedding.h"
#include "core/meshing/tet_mesher.h"
#include "core/primitives/icosphere.h"

namespace viscera::templates {
namespace {

core::SceneObject ball_object(const std::string& id, double radius, const core::Vec3& centre,
                              double cell, core::ObjectRole role) {
  core::SceneObject o;
  o.id = id;
  o.name = id;
  o.role = role;
  o.material = "tissue";
  o.body_kind = core::BodyKind::TetMesh;
  o.surface = core::make_icosphere(radius, 2, centre);
  core::compute_vertex_normals(o.surface);
  core::TetMeshingOptions meshing;
  meshing.cell_size = cell;
  o.body = core::mesh_closed_surface(o.surface, meshing);
  o.body.node_mass = core::lumped_node_masses(o.body, 1000.0);
  o.embedding = core::embed_points(o.surface.vertices, o.body);
  return o;
}

/// A host ball of radius 4 cm and a 1 cm pathology ball resting on top of it, joined by the
/// pathology's four lowest nodes.
core::Scenario host_and_pathology() {
  core::Scenario s;
  s.metadata.name = "segmented";
  core::Material tissue;
  tissue.id = "tissue";
  tissue.density = 1000.0;
  s.materials["tissue"] = tissue;
  s.objects.push_back(
      ball_object("organ", 0.04, core::Vec3::Zero(), 0.02, core::ObjectRole::Organ));
  s.objects.push_back(
      ball_object("myoma", 0.005, core::Vec3(0, 0, 0.0455), 0.004, core::ObjectRole::Pathology));
  core::Pathology p;
  p.id = "myoma-1";
  p.kind = "myoma-submucosal";
  p.host_object = "organ";
  p.object = "myoma";
  p.position = core::Vec3(0, 0, 0.0455);
  p.size = 0.01;
  s.pathologies.push_back(p);
  core::Connection c;
  c.id = "myoma-1-attachment";
  c.object_a = "myoma";
  c.object_b = "organ";
  const auto& nodes = s.objects[1].body.nodes;
  std::vector<int> order(nodes.size());
  for (std::size_t i = 0; i < order.size(); ++i)
    order[i] = static_cast<int>(i);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return nodes[a].z() < nodes[b].z(); });
  for (int i = 0; i < 4; ++i)
    c.node_pairs.push_back({order[i], 0});
  s.connections.push_back(c);
  core::Landmark l;
  l.id = "top";
  l.object = "organ";
  l.position = s.objects[0].surface.vertices[0];
  l.normal = core::Vec3(0, 0, 1);
  s.landmarks.push_back(l);
  return s;
}

double total_mass(const core::SceneObject& o) {
  double m = 0.0;
  for (const double x : o.body.node_mass)
    m += x;
  return m;
}

TEST(ScenarioVariation, redrawn_pathology_sizes_scale_the_object_about_its_attachment) {
  const core::Scenario base = host_and_pathology();
  ScenarioVariation variation;
  variation.amplitude_fraction = 0.0;  // the identity field: only the size changes
  core::Rng rng(11);
  const ScenarioDraw draw = vary_scenario(base, rng, variation);
  const double ratio = draw.scenario.pathologies[0].size / base.pathologies[0].size;
  EXPECT_GE(ratio, 0.8);
  EXPECT_LT(ratio, 1.2);
  EXPECT_GT(std::abs(ratio - 1.0), 1e-6);
  EXPECT_DOUBLE_EQ(draw.drawn["pathology_sizes"]["myoma-1"]["to"].get<double>(),
                   draw.scenario.pathologies[0].size);
  // The host did not move; the pathology's attachment nodes' mean is the fixed point.
  EXPECT_EQ(draw.scenario.objects[0].surface.vertices, base.objects[0].surface.vertices);
  core::Vec3 anchor = core::Vec3::Zero();
  for (const auto& pair : base.connections[0].node_pairs)
    anchor += base.objects[1].body.nodes[pair[0]] / 4.0;
  const auto& before = base.objects[1].surface.vertices;
  const auto& after = draw.scenario.objects[1].surface.vertices;
  for (std::size_t i = 0; i < before.size(); ++i)
    EXPECT_NEAR((after[i] - anchor).norm(), ratio * (before[i] - anchor).norm(), 1e-12);
  // Mass follows the volume: ratio³.
  EXPECT_NEAR(total_mass(draw.scenario.objects[1]) / total_mass(base.objects[1]),
              ratio * ratio * ratio, 1e-9);
}

TEST(ScenarioVariation, the_smooth_field_moves_everything_consistently_and_deterministically) {
  const core::Scenario base = host_and_pathology();
  core::Rng a(5), b(5), c(6);
  const ScenarioDraw first = vary_scenario(base, a), again = vary_scenario(base, b);
  const ScenarioDraw other = vary_scenario(base, c);
  EXPECT_TRUE(first.scenario == again.scenario);
  EXPECT_FALSE(first.scenario == other.scenario);

  const core::SceneObject& organ = first.scenario.objects[0];
  double largest = 0.0;
  for (std::size_t i = 0; i < organ.surface.vertices.size(); ++i)
    largest =
        std::max(largest, (organ.surface.vertices[i] - base.objects[0].surface.vertices[i]).norm());
  EXPECT_GT(largest, 1e-4);  // it varied …
  EXPECT_LT(largest, 0.03);  // … but stayed an organ of the same size
  // Lipschitz < 1: no tet turned over, the surface stays closed and outward.
  EXPECT_LE(first.drawn["lipschitz_bound"].get<double>(), 0.5 + 1e-12);
  for (std::size_t t = 0; t < organ.body.tets.size(); ++t)
    EXPECT_GT(core::signed_volume(organ.body, static_cast<int>(t)), 0.0);
  EXPECT_TRUE(core::is_closed_and_consistently_oriented(organ.surface));
  EXPECT_GT(core::enclosed_volume(organ.surface), 0.0);
  // The landmark on vertex 0 stays on vertex 0; the embedding was rebuilt for the new body.
  EXPECT_NEAR((first.scenario.landmarks[0].position - organ.surface.vertices[0]).norm(), 0.0,
              1e-12);
  EXPECT_NEAR(first.scenario.landmarks[0].normal.norm(), 1.0, 1e-9);
  const auto embedded =
      core::embedded_positions(organ.embedding, organ.body.tets, organ.body.nodes);
  for (std::size_t i = 0; i < embedded.size(); ++i)
    EXPECT_LT((embedded[i] - organ.surface.vertices[i]).norm(), 1e-9);
}

TEST(ScenarioVariation, refuses_bad_options_and_a_scenario_without_geometry) {
  const core::Scenario base = host_and_pathology();
  core::Rng rng(1);
  ScenarioVariation bad;
  bad.pathology_size_spread = 1.0;
  EXPECT_THROW(vary_scenario(base, rng, bad), core::UsageError);
  bad = {};
  bad.width_fraction = 0.0;
  EXPECT_THROW(vary_scenario(base, rng, bad), core::UsageError);
  EXPECT_THROW(vary_scenario(core::Scenario{}, rng), core::InputError);
}

}  // namespace
}  // namespace viscera::templates
