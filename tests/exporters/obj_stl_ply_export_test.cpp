// OBJ (with MTL and maps), STL and PLY exports read back through our reader (assimp).
#include <gtest/gtest.h>

#include "exporters/scenario_exporter.h"
#include "importers/mesh_reader.h"
#include "tests/exporters/export_fixtures.h"

namespace viscera::exporters {
namespace {

const core::Scenario& scenario() {
  return testing::export_scenario_fixture();
}

std::size_t all_triangles() {
  std::size_t n = 0;
  for (const auto& o : scenario().objects)
    n += o.surface.triangles.size();
  return n;
}

double all_area() {
  double a = 0.0;
  for (const auto& o : scenario().objects)
    a += core::surface_area(o.surface);
  return a;
}

TEST(ObjExport, one_object_keeps_positions_normals_and_uvs_and_its_mtl_names_the_maps_beside_it) {
  const auto path = testing::export_fixture(ExportFormat::Obj, "ball.obj", {{"ball"}});
  const core::SceneObject& ball = scenario().objects[0];
  const core::SurfaceMesh back = importers::read_mesh(path);
  ASSERT_EQ(back.vertices.size(), ball.surface.vertices.size());
  ASSERT_EQ(back.uvs.size(), back.vertices.size());
  EXPECT_EQ(back.triangles.size(), ball.surface.triangles.size());
  EXPECT_NEAR(core::enclosed_volume(back), core::enclosed_volume(ball.surface),
              1e-6 * core::enclosed_volume(ball.surface));
  // assimp joins identical vertices, so match each vertex read back to the one it came from.
  for (std::size_t v = 0; v < back.vertices.size(); ++v) {
    double best = 1e9;
    std::size_t match = 0;
    for (std::size_t w = 0; w < ball.surface.vertices.size(); ++w) {
      const double d = (ball.surface.vertices[w] - back.vertices[v]).norm() +
                       (ball.surface.uvs[w] - back.uvs[v]).norm();
      if (d < best) best = d, match = w;
    }
    EXPECT_LT(best, 1e-6) << "vertex " << v;
    EXPECT_GT(back.normals[v].dot(ball.surface.normals[match].normalized()), 1.0 - 1e-5);
  }
  const std::string mtl = testing::file_bytes(path.parent_path() / "ball.mtl");
  const auto& maps = scenario().textures.at("ball-skin").maps;
  const auto& textures = testing::export_textures_fixture();
  for (const auto& [key, map] :
       {std::pair{"map_Kd ", "albedo"}, {"map_Ks ", "specular"}, {"bump ", "normal"}}) {
    const std::string file = "ball_ball-skin_" + std::string(map) + ".png";
    EXPECT_NE(mtl.find(std::string(key) + file), std::string::npos) << mtl;
    EXPECT_EQ(testing::file_bytes(path.parent_path() / file), textures.at(maps.at(map)));
  }
}

TEST(ObjExport, every_object_is_read_back) {
  const core::SurfaceMesh back =
      importers::read_mesh(testing::export_fixture(ExportFormat::Obj, "patient.obj"));
  EXPECT_EQ(back.triangles.size(), all_triangles());
  EXPECT_NEAR(core::surface_area(back), all_area(), 1e-6 * all_area());
}

TEST(StlExport, every_triangle_is_read_back_with_its_area_and_closed_volume) {
  const core::SurfaceMesh back =
      importers::read_mesh(testing::export_fixture(ExportFormat::Stl, "patient.stl"));
  EXPECT_EQ(back.triangles.size(), all_triangles());
  EXPECT_NEAR(core::surface_area(back), all_area(), 1e-6 * all_area());
  double volume = 0.0;
  for (const auto& o : scenario().objects)
    volume += core::enclosed_volume(o.surface);
  EXPECT_NEAR(core::enclosed_volume(back), volume, 1e-6 * volume);
}

TEST(PlyExport, vertices_normals_colours_and_triangles_are_read_back) {
  const auto path = testing::export_fixture(ExportFormat::Ply, "patient.ply");
  const core::SurfaceMesh back = importers::read_mesh(path);
  std::size_t vertices = 0;
  for (const auto& o : scenario().objects)
    vertices += o.surface.vertices.size();
  EXPECT_EQ(back.vertices.size(), vertices);
  EXPECT_EQ(back.triangles.size(), all_triangles());
  ASSERT_EQ(back.normals.size(), back.vertices.size());
  for (const auto& n : back.normals)
    EXPECT_NEAR(n.norm(), 1.0, 1e-5);
  EXPECT_NEAR(core::surface_area(back), all_area(), 1e-6 * all_area());
  // assimp's binary PLY writer garbles colours, so coloured exports are ASCII.
  EXPECT_NE(testing::file_bytes(path).find("format ascii"), std::string::npos);
}

TEST(PlyExport, uncoloured_objects_are_binary_with_uvs) {
  const auto path = testing::export_fixture(ExportFormat::Ply, "ball.ply", {{"ball"}});
  EXPECT_NE(testing::file_bytes(path).find("format binary_little_endian"), std::string::npos);
  const core::SurfaceMesh back = importers::read_mesh(path);
  const core::SurfaceMesh& ball = scenario().objects[0].surface;
  ASSERT_EQ(back.uvs.size(), ball.uvs.size());
  for (std::size_t v = 0; v < ball.uvs.size(); ++v)
    EXPECT_LT((back.uvs[v] - ball.uvs[v]).norm(), 1e-6);
}

}  // namespace
}  // namespace viscera::exporters
