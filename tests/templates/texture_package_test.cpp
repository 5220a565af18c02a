// Textures, vessel trees and active-deformation specs stored in scenario packages: the maps
// baked onto a ball's surface land in textures/ with their checksums, and pulse and motility
// specs come back from a package exactly as written.

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "core/error.h"
#include "core/package/scenario_package.h"
#include "templates/template_catalog.h"
#include "templates/vessels/cco_vessel_generator.h"
#include "templates/vessels/vessel_tree_analysis.h"
#include "tests/support/test_paths.h"
#include "textures/active_deformation_specs.h"
#include "textures/png_io.h"
#include "textures/scenario_baking.h"
#include "textures/uv_atlas.h"

namespace viscera {
namespace {

core::Scenario small_ball() {
  return templates::build_from_template("ball", {{"radius", "0.02"}, {"cell_size", "0.008"}}, 3);
}

core::Scenario textured_ball(std::uint64_t seed, textures::BakedTextures& baked) {
  core::Scenario scenario = small_ball();
  core::TextureSpec spec;
  spec.id = "ball-skin";
  spec.preset = "myoma-surface";
  spec.seed = seed;
  spec.width = spec.height = 256;
  scenario.textures[spec.id] = spec;
  scenario.objects[0].texture = spec.id;
  baked = textures::bake_textures_into(scenario, {.texture_scale = 0.03});
  return scenario;
}

TEST(TexturePackage, maps_baked_onto_a_ball_are_stored_and_read_back) {
  textures::BakedTextures baked;
  const core::Scenario scenario = textured_ball(5, baked);
  ASSERT_EQ(baked.objects.size(), 1u);
  EXPECT_EQ(baked.objects[0].mapping, textures::TextureMapping::Atlas);
  EXPECT_LT(baked.objects[0].distortion.l2_stretch, 1.05);
  ASSERT_EQ(baked.files.size(), 3u);

  const auto dir = testing::scratch_dir();
  for (const char* name : {"ball.vscene", "ball.vscz"}) {
    const auto path = dir / name;
    core::write_package(scenario, baked.files, path);
    EXPECT_TRUE(core::validate_package(path).empty()) << name;
    const core::Scenario back = core::read_package(path);
    const auto& spec = back.textures.at("ball-skin");
    EXPECT_EQ(spec.maps.at("albedo"), "textures/ball-skin_albedo.png");
    EXPECT_EQ(spec.maps.at("normal"), "textures/ball-skin_normal.png");
    EXPECT_EQ(spec.maps.at("specular"), "textures/ball-skin_specular.png");
    const auto& ball = back.objects[0];
    EXPECT_TRUE(textures::has_usable_uvs(ball.surface));
    EXPECT_EQ(ball.embedding.tet.size(), ball.surface.vertices.size());
    EXPECT_FALSE(core::is_closed_and_consistently_oriented(ball.surface));  // seams split it
    // Welding the copies by their recorded original index gives back the closed ball.
    core::SurfaceMesh welded = ball.surface;
    const auto& original = ball.surface.vertex_attributes.at(textures::kSeamVertexAttribute);
    for (auto& t : welded.triangles) {
      for (int& v : t)
        v = static_cast<int>(original[static_cast<std::size_t>(v)]);
    }
    EXPECT_TRUE(core::is_closed_and_consistently_oriented(welded));
  }
  const auto folder = dir / "ball.vscene";
  const auto albedo = textures::decode_image(
      viscera::testing::file_bytes(folder / "textures/ball-skin_albedo.png"), "albedo");
  EXPECT_EQ(albedo.width, 256);
  EXPECT_EQ(albedo.channels, 3);
  EXPECT_EQ(
      textures::decode_image(
          viscera::testing::file_bytes(folder / "textures/ball-skin_specular.png"), "specular")
          .channels,
      1);
}

TEST(TexturePackage, same_seed_gives_the_same_png_bytes) {
  textures::BakedTextures a, b, c;
  textured_ball(5, a);
  textured_ball(5, b);
  textured_ball(6, c);
  EXPECT_EQ(a.files, b.files);
  EXPECT_NE(a.files.at("textures/ball-skin_albedo.png"),
            c.files.at("textures/ball-skin_albedo.png"));
}

TEST(TexturePackage, keep_topology_bakes_vertex_colours_and_flat_maps) {
  core::Scenario scenario = small_ball();
  const std::size_t vertices = scenario.objects[0].surface.vertices.size();
  scenario.textures["skin"] = core::TextureSpec{"skin", "liver", 2, 64, 64, {}};
  scenario.objects[0].texture = "skin";
  const auto baked = textures::bake_textures_into(scenario, {.keep_topology = true});
  EXPECT_EQ(baked.objects[0].mapping, textures::TextureMapping::VertexColors);
  EXPECT_EQ(scenario.objects[0].surface.vertices.size(), vertices);
  EXPECT_EQ(scenario.objects[0].surface.vertex_attributes.at("albedo_r").size(), vertices);
  const auto path = testing::scratch_dir() / "ball.vscene";
  core::write_package(scenario, baked.files, path);
  EXPECT_TRUE(core::validate_package(path).empty());
  EXPECT_EQ(core::read_package(path).objects[0].surface.vertex_attributes.at("albedo_r"),
            scenario.objects[0].surface.vertex_attributes.at("albedo_r"));
}

TEST(TexturePackage, unknown_presets_are_reported_with_their_pointer) {
  core::Scenario scenario = small_ball();
  scenario.textures["skin"] = core::TextureSpec{"skin", "spleen", 1, 64, 64, {}};
  scenario.objects[0].texture = "skin";
  try {
    textures::bake_textures_into(scenario, {});
    FAIL();
  } catch (const core::ValidationError& e) {
    EXPECT_EQ(e.location().json_pointer, "/scenario/textures/skin/preset");
  }
}

TEST(ActiveDeformationPackage, pulse_and_motility_round_trip_through_packages) {
  core::Scenario scenario = small_ball();
  const templates::SurfaceMeshDomain domain(scenario.objects[0].surface);
  templates::CcoOptions cco;
  cco.terminals = 40;
  cco.tree_id = "ball-artery";
  cco.host_object = "ball";
  scenario.vessel_trees.push_back(templates::grow_cco_tree(domain, cco));
  scenario.active_deformations.push_back(
      textures::make_pulse("heartbeat", "ball", scenario.vessel_trees[0], 72.0, 7.5, 0.04));
  core::MotilitySpec motility;
  motility.amplitude_mean = 0.0015;
  motility.amplitude_variance = 2.5e-7;
  motility.wave_speed = 0.008;
  motility.wave_direction = core::Vec3(0, 0.6, 0.8);
  motility.frequency = 0.08;
  motility.frequency_disturbance = 0.02;
  motility.contraction_interval_mean = 30.0;
  motility.contraction_interval_variance = 16.0;
  scenario.active_deformations.push_back(textures::make_motility("peristalsis", "ball", motility));
  EXPECT_TRUE(textures::validate_active_deformations(scenario).empty());

  const auto dir = testing::scratch_dir();
  for (const char* name : {"living.vscene", "living.vscz"}) {
    const auto path = dir / name;
    core::write_package(scenario, path);
    ASSERT_TRUE(core::validate_package(path).empty()) << name;
    const core::Scenario back = core::read_package(path);
    EXPECT_EQ(back.active_deformations, scenario.active_deformations) << name;
    EXPECT_EQ(back.vessel_trees, scenario.vessel_trees) << name;
    EXPECT_TRUE(textures::validate_active_deformations(back).empty()) << name;
    EXPECT_LT(templates::murray_deviation(back.vessel_trees[0]), 0.01);
  }
}

}  // namespace
}  // namespace viscera
