// read_mesh and read_tet_mesh on real files that no one in this project wrote (CGAL's data,
// assimp's test models) and on every kind of bad mesh input: one clear message naming the file
// and the reason.
#include <gtest/gtest.h>

#include <fstream>

#include "core/error.h"
#include "core/package/vtk_mesh_io.h"
#include "exporters/scenario_exporter.h"
#include "importers/mesh_reader.h"
#include "tests/exporters/export_fixtures.h"
#include "tests/support/test_paths.h"

namespace viscera::importers {
namespace {

namespace fs = std::filesystem;

using testing::mesh_read_error;

TEST(MeshImport, real_closed_meshes_of_cgal_read_closed_with_their_vertex_counts) {
  // elephant.off and sphere.ply/.stl from CGAL's data; counts from their headers.
  const core::SurfaceMesh elephant = read_mesh(testing::cgal_mesh("elephant.off"));
  EXPECT_EQ(elephant.vertices.size(), 2775u);
  EXPECT_EQ(elephant.triangles.size(), 5558u);
  EXPECT_TRUE(core::is_closed_and_consistently_oriented(elephant));
  const core::SurfaceMesh ply = read_mesh(testing::cgal_mesh("sphere.ply"));
  const core::SurfaceMesh stl = read_mesh(testing::cgal_mesh("sphere.stl"));
  EXPECT_EQ(ply.triangles.size(), stl.triangles.size());
  EXPECT_NEAR(core::surface_area(ply), core::surface_area(stl), 1e-3 * core::surface_area(ply));
}

TEST(MeshImport, the_same_textured_box_as_gltf_and_glb_reads_with_its_uvs) {
  const core::SurfaceMesh gltf =
      read_mesh(testing::assimp_model("glTF2/BoxTextured-glTF/BoxTextured.gltf"));
  const core::SurfaceMesh glb =
      read_mesh(testing::assimp_model("glTF2/BoxTextured-glTF-Binary/BoxTextured.glb"));
  EXPECT_EQ(gltf.vertices.size(), 24u);  // 4 per face: faces do not share normals or UVs
  EXPECT_EQ(gltf.triangles.size(), 12u);
  ASSERT_EQ(gltf.uvs.size(), 24u);
  EXPECT_EQ(gltf.vertices, glb.vertices);
  EXPECT_EQ(gltf.uvs, glb.uvs);
  EXPECT_NEAR(core::surface_area(gltf), 6.0, 1e-12);
  // 1 mm in the file is 1 mm in metres.
  EXPECT_NEAR(
      core::surface_area(read_mesh(testing::assimp_model("glTF2/BoxTextured-glTF/BoxTextured.gltf"),
                                   LengthUnit::Millimetre)),
      6e-6, 1e-18);
}

TEST(MeshImport, a_package_body_vtu_reads_as_tets_with_masses_and_fixed_nodes) {
  const auto& ball = testing::export_scenario_fixture().objects[0];
  const fs::path path = testing::scratch_dir() / "body.vtu";
  core::write_body_vtu(ball.body, path);
  const core::TetMesh body = read_tet_mesh(path);
  EXPECT_EQ(body.nodes, ball.body.nodes);
  EXPECT_EQ(body.tets, ball.body.tets);
  EXPECT_EQ(body.node_mass, ball.body.node_mass);
  EXPECT_EQ(body.fixed, ball.body.fixed);
  // Its surface view is the boundary of the tets.
  EXPECT_EQ(read_mesh(path).triangles.size(), ball.body.surface_faces.size());
}

TEST(MeshImport, a_self_intersecting_real_mesh_is_refused_naming_two_triangles) {
  const fs::path path = testing::cgal_mesh("tetra_intersected_by_triangle.off");
  const std::string message = mesh_read_error(path);
  EXPECT_TRUE(testing::message_has(
      message, {"tetra_intersected_by_triangle.off", "intersects itself", "triangle 4"}))
      << message;
}

TEST(MeshImport, a_real_mesh_with_pinched_vertices_is_refused_as_not_manifold) {
  const std::string message = mesh_read_error(testing::cgal_mesh("pig.stl"));
  EXPECT_TRUE(testing::message_has(message, {"pig.stl", "not manifold", "separate fans"}))
      << message;
}

TEST(MeshImport, an_edge_shared_by_three_triangles_is_refused_as_not_manifold) {
  const fs::path path = testing::scratch_dir() / "fin.obj";
  std::ofstream(path)
      << "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nf 1 2 3\nf 2 1 4\nf 1 2 5\n";
  const std::string message = mesh_read_error(path);
  EXPECT_TRUE(testing::message_has(
      message, {"fin.obj", "not manifold", "edge is shared by more than two triangles"}))
      << message;
}

TEST(MeshImport, degenerate_triangles_of_a_real_model_are_refused_naming_the_triangle) {
  const std::string message = mesh_read_error(testing::assimp_model("STL/Spider_binary.stl"));
  EXPECT_TRUE(testing::message_has(
      message, {"Spider_binary.stl", "triangle 924", "two corners at the same position"}))
      << message;
  const fs::path flat = testing::scratch_dir() / "flat.obj";
  std::ofstream(flat) << "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n";
  EXPECT_TRUE(testing::message_has(mesh_read_error(flat),
                                   {"flat.obj", "triangle 0", "corners lie on one line"}));
}

TEST(MeshImport, non_finite_coordinates_are_refused_naming_the_vertex) {
  // assimp's own test model with infinite coordinates, and a NaN in an OBJ.
  const std::string message = mesh_read_error(
      testing::assimp_model("glTF2/BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb"));
  EXPECT_TRUE(testing::message_has(message, {"BoxWithInfinites.glb", "vertex", "not finite"}))
      << message;
  const fs::path path = testing::scratch_dir() / "nan.obj";
  std::ofstream(path) << "v 0 0 0\nv 1 0 0\nv 0 nan 0\nf 1 2 3\n";
  EXPECT_TRUE(testing::message_has(mesh_read_error(path), {"nan.obj", "vertex 2", "not finite"}))
      << mesh_read_error(path);
}

TEST(MeshImport, truncated_and_corrupt_files_are_refused_naming_the_file) {
  const fs::path dir = testing::scratch_dir();
  // A binary STL cut in the middle of its triangles.
  const std::string stl = testing::file_bytes(testing::cgal_mesh("pig.stl"));
  std::ofstream(dir / "cut.stl", std::ios::binary) << stl.substr(0, stl.size() / 2);
  EXPECT_TRUE(
      testing::message_has(mesh_read_error(dir / "cut.stl"), {"cut.stl", "cannot read mesh"}))
      << mesh_read_error(dir / "cut.stl");
  // A VTK XML file cut off, and one that is not XML at all.
  const auto& ball = testing::export_scenario_fixture().objects[0];
  core::write_body_vtu(ball.body, dir / "whole.vtu");
  const std::string vtu = testing::file_bytes(dir / "whole.vtu");
  std::ofstream(dir / "cut.vtu", std::ios::binary) << vtu.substr(0, vtu.size() / 3);
  EXPECT_TRUE(testing::message_has(mesh_read_error(dir / "cut.vtu"),
                                   {"cut.vtu", "VTK cannot read the file"}))
      << mesh_read_error(dir / "cut.vtu");
  std::ofstream(dir / "text.vtp") << "this is not a VTK file\n";
  EXPECT_TRUE(testing::message_has(mesh_read_error(dir / "text.vtp"),
                                   {"text.vtp", "VTK cannot read the file"}))
      << mesh_read_error(dir / "text.vtp");
  // assimp's broken OFF of its test set, a PLY without faces from CGAL's data, a missing file.
  EXPECT_TRUE(testing::message_has(mesh_read_error(testing::assimp_model("OFF/invalid.off")),
                                   {"invalid.off"}));
  EXPECT_TRUE(
      testing::message_has(mesh_read_error(testing::cgal_mesh("b9.ply")), {"b9.ply", "no faces"}))
      << mesh_read_error(testing::cgal_mesh("b9.ply"));
  EXPECT_TRUE(
      testing::message_has(mesh_read_error(dir / "missing.obj"), {"missing.obj", "no such file"}));
  EXPECT_THROW(read_tet_mesh(dir / "whole.obj"), core::UsageError);
}

TEST(MeshImport, a_glb_whose_chunk_runs_past_the_end_is_refused_before_assimp_allocates_it) {
  // The mesh_glb fuzz target's finding: a JSON chunk declaring 3.4 GB in a 624-byte file made
  // assimp allocate it. The real binary box with each length patched in turn.
  const fs::path dir = testing::scratch_dir();
  const std::string glb =
      testing::file_bytes(testing::assimp_model("glTF2/BoxTextured-glTF-Binary/BoxTextured.glb"));
  ASSERT_GT(glb.size(), 20u);
  const auto patched = [&](std::size_t at, std::uint32_t value, const std::string& name) {
    std::string bytes = glb;
    for (int k = 0; k < 4; ++k)
      bytes[at + static_cast<std::size_t>(k)] = static_cast<char>((value >> (8 * k)) & 0xFFu);
    std::ofstream(dir / name, std::ios::binary) << bytes;
    return dir / name;
  };
  const std::string chunk = mesh_read_error(patched(12, 0xCF00020Cu, "chunk.glb"));
  EXPECT_TRUE(testing::message_has(chunk, {"chunk.glb", "byte 12", "declares 3472884236 bytes"}))
      << chunk;
  const std::string total = mesh_read_error(patched(8, 1u << 30, "total.glb"));
  EXPECT_TRUE(testing::message_has(total, {"total.glb", "declares 1073741824 bytes"})) << total;
  const std::string version = mesh_read_error(patched(4, 1, "version.glb"));
  EXPECT_TRUE(testing::message_has(version, {"version.glb", "GLB version 1"})) << version;
  // The unpatched file still reads: the check refuses only what is damaged.
  EXPECT_EQ(read_mesh(patched(4, 2, "same.glb")).triangles.size(), 12u);
}

}  // namespace
}  // namespace viscera::importers
