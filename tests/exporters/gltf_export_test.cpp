// glTF 2.0 exports read back as a viewer reads them (accessors, materials, images) and through
// our own reader (assimp).
#include <gtest/gtest.h>

#include "core/error.h"
#include "exporters/scenario_exporter.h"
#include "importers/mesh_reader.h"
#include "tests/exporters/export_fixtures.h"
#include "tests/exporters/gltf_document.h"
#include "tests/support/test_paths.h"

namespace viscera::exporters {
namespace {

using testing::GltfDocument;

class GltfExport : public ::testing::TestWithParam<std::string> {
 protected:
  std::filesystem::path exported() {
    return testing::export_fixture(GetParam() == ".glb" ? ExportFormat::Glb : ExportFormat::Gltf,
                                   "patient" + GetParam());
  }
};

const core::SceneObject& object(const std::string& id) {
  return *testing::export_scenario_fixture().find_object(id);
}

TEST_P(GltfExport, accessors_hold_positions_unit_normals_uvs_and_colours_of_every_object) {
  const GltfDocument doc(exported());
  const auto& json = doc.json();
  ASSERT_EQ(json.at("nodes").size(), 4u);  // the root and one node per object
  int checked = 0;
  for (const auto& node : json.at("nodes")) {
    if (!node.contains("mesh")) continue;
    const core::SceneObject& source = object(node.at("name").get<std::string>());
    const auto& primitive =
        json.at("meshes").at(node.at("mesh").get<std::size_t>()).at("primitives").at(0);
    const auto& attributes = primitive.at("attributes");
    const auto positions = doc.accessor(attributes.at("POSITION").get<int>());
    const auto normals = doc.accessor(attributes.at("NORMAL").get<int>());
    const auto indices = doc.accessor(primitive.at("indices").get<int>());
    ASSERT_EQ(positions.size(), 3 * source.surface.vertices.size());
    ASSERT_EQ(indices.size(), 3 * source.surface.triangles.size());
    for (std::size_t v = 0; v < source.surface.vertices.size(); ++v) {
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(positions[3 * v + c], source.surface.vertices[v][c], 1e-8);
      const core::Vec3 n(normals[3 * v], normals[3 * v + 1], normals[3 * v + 2]);
      EXPECT_NEAR(n.norm(), 1.0, 1e-6);
      if (!source.surface.normals.empty()) {
        EXPECT_GT(n.dot(source.surface.normals[v].normalized()), 1.0 - 1e-6);
      }
    }
    for (std::size_t t = 0; t < source.surface.triangles.size(); ++t) {
      for (int c = 0; c < 3; ++c)
        EXPECT_EQ(indices[3 * t + c], source.surface.triangles[t][c]);
    }
    if (!source.surface.uvs.empty()) {
      // glTF puts the texture origin top-left: v' = 1 − v.
      const auto uvs = doc.accessor(attributes.at("TEXCOORD_0").get<int>());
      ASSERT_EQ(uvs.size(), 2 * source.surface.uvs.size());
      for (std::size_t v = 0; v < source.surface.uvs.size(); ++v) {
        EXPECT_NEAR(uvs[2 * v], source.surface.uvs[v].x(), 1e-6);
        EXPECT_NEAR(uvs[2 * v + 1], 1.0 - source.surface.uvs[v].y(), 1e-6);
      }
    }
    if (source.surface.vertex_attributes.contains("albedo_r")) {
      const auto colours = doc.accessor(attributes.at("COLOR_0").get<int>());
      const auto& red = source.surface.vertex_attributes.at("albedo_r");
      for (std::size_t v = 0; v < red.size(); ++v)
        EXPECT_NEAR(colours[4 * v], std::clamp(red[v], 0.0, 1.0), 1e-6);
    }
    ++checked;
  }
  EXPECT_EQ(checked, 3);
}

TEST_P(GltfExport, the_ball_material_carries_the_baked_albedo_and_normal_map) {
  const GltfDocument doc(exported());
  const auto& json = doc.json();
  const auto& textures = testing::export_textures_fixture();
  const auto& spec = testing::export_scenario_fixture().textures.at("ball-skin");
  int ball_mesh = -1;
  for (const auto& node : json.at("nodes")) {
    if (node.value("name", "") == "ball") ball_mesh = node.at("mesh").get<int>();
  }
  ASSERT_GE(ball_mesh, 0);
  const auto& material = json.at("materials")
                             .at(json.at("meshes")
                                     .at(ball_mesh)
                                     .at("primitives")
                                     .at(0)
                                     .at("material")
                                     .get<std::size_t>());
  const auto image_of = [&](const nlohmann::json& info) {
    const int texture = info.at("index").get<int>();
    return doc.image_bytes(
        json.at("textures").at(static_cast<std::size_t>(texture)).at("source").get<int>());
  };
  EXPECT_EQ(image_of(material.at("pbrMetallicRoughness").at("baseColorTexture")),
            textures.at(spec.maps.at("albedo")));
  EXPECT_EQ(image_of(material.at("normalTexture")), textures.at(spec.maps.at("normal")));
  EXPECT_EQ(material.at("pbrMetallicRoughness").value("metallicFactor", 1.0), 0.0);
}

TEST_P(GltfExport, our_reader_gets_the_same_geometry_back) {
  const core::SurfaceMesh back = importers::read_mesh(exported());
  std::size_t triangles = 0;
  double area = 0.0;
  for (const auto& o : testing::export_scenario_fixture().objects) {
    triangles += o.surface.triangles.size();
    area += core::surface_area(o.surface);
  }
  EXPECT_EQ(back.triangles.size(), triangles);
  EXPECT_NEAR(core::surface_area(back), area, 1e-6 * area);
}

INSTANTIATE_TEST_SUITE_P(Formats, GltfExport, ::testing::Values(".gltf", ".glb"),
                         [](const auto& format) { return format.param.substr(1); });

TEST(GltfExport, non_finite_normals_and_uvs_are_sanitised_and_counted) {
  core::Scenario scenario = testing::export_scenario_fixture();
  auto& surface = scenario.objects[0].surface;
  surface.normals[0] = core::Vec3(std::nan(""), 0, 0);
  surface.normals[1] = core::Vec3::Zero();
  surface.uvs[2].y() = std::numeric_limits<double>::infinity();
  const auto out = testing::scratch_dir() / "sanitised.glb";
  const ExportReport report =
      export_scenario(scenario, ExportFormat::Glb, out, testing::export_textures_fixture());
  EXPECT_EQ(report.sanitized_values, 3u);
  const GltfDocument doc(out);
  const auto normals = doc.accessor(doc.json()
                                        .at("meshes")
                                        .at(0)
                                        .at("primitives")
                                        .at(0)
                                        .at("attributes")
                                        .at("NORMAL")
                                        .get<int>());
  for (double value : normals)
    EXPECT_TRUE(std::isfinite(value));
  EXPECT_NEAR(core::Vec3(normals[0], normals[1], normals[2]).norm(), 1.0, 1e-6);
}

TEST(GltfExport, a_non_finite_position_is_refused_naming_object_and_vertex_and_nothing_is_written) {
  core::Scenario scenario = testing::export_scenario_fixture();
  scenario.objects[0].surface.vertices[3].z() = std::nan("");
  const auto dir = testing::scratch_dir();
  try {
    export_scenario(scenario, ExportFormat::Glb, dir / "bad.glb",
                    testing::export_textures_fixture());
    FAIL() << "a NaN position was exported";
  } catch (const core::InputError& e) {
    EXPECT_TRUE(testing::message_has(e.what(), {"object ball surface", "vertex 3", "not finite"}))
        << e.what();
  }
  EXPECT_TRUE(std::filesystem::is_empty(dir));
}

}  // namespace
}  // namespace viscera::exporters
