#include "exporters/mesh_writer.h"

#include <gtest/gtest.h>

#include <fstream>

#include "core/error.h"
#include "core/primitives/icosphere.h"
#include "importers/mesh_reader.h"
#include "tests/support/test_paths.h"
#include "tests/support/tet_block.h"

namespace viscera::exporters {
namespace {

class MeshRoundTrip : public ::testing::TestWithParam<std::string> {};

TEST_P(MeshRoundTrip, keeps_topology_area_and_volume) {
  const auto dir = viscera::testing::scratch_dir();
  const core::SurfaceMesh sphere = core::make_icosphere(0.05, 3);
  const auto path = dir / ("sphere" + GetParam());
  write_meshes({{"sphere", &sphere}}, path);
  const core::SurfaceMesh back = importers::read_mesh(path);
  EXPECT_EQ(back.triangles.size(), sphere.triangles.size());
  EXPECT_EQ(back.vertices.size(), sphere.vertices.size());
  EXPECT_TRUE(core::is_closed_and_consistently_oriented(back));
  // Files store single precision: compare measured quantities to float accuracy.
  EXPECT_NEAR(core::surface_area(back), core::surface_area(sphere),
              1e-6 * core::surface_area(sphere));
  EXPECT_NEAR(core::enclosed_volume(back), core::enclosed_volume(sphere),
              1e-6 * core::enclosed_volume(sphere));
  // No staging folder or partial file is left beside the result.
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    EXPECT_EQ(entry.path().string().find("partial"), std::string::npos) << entry.path();
    ++files;
  }
  EXPECT_LE(files, 2);  // the mesh, and for OBJ its .mtl, for glTF its .bin
}

INSTANTIATE_TEST_SUITE_P(Formats, MeshRoundTrip,
                         ::testing::Values(".obj", ".stl", ".ply", ".gltf", ".glb", ".vtp", ".vtk",
                                           ".msh"),
                         [](const auto& format) { return format.param.substr(1); });

class TetMeshRoundTrip : public ::testing::TestWithParam<std::string> {};

TEST_P(TetMeshRoundTrip, keeps_nodes_tets_labels_and_volume) {
  core::TetMesh block = viscera::testing::tet_block(3, 2, 2, 0.01);
  block.tet_labels.assign(block.tets.size(), 4);
  for (std::size_t t = 0; t < block.tets.size() / 2; ++t)
    block.tet_labels[t] = 9;
  const auto path = viscera::testing::scratch_dir() / ("block" + GetParam());
  write_tet_mesh(block, "block", path);
  const core::TetMesh back = importers::read_tet_mesh(path);
  EXPECT_EQ(back.tets, block.tets);
  EXPECT_EQ(back.tet_labels, block.tet_labels);
  ASSERT_EQ(back.nodes.size(), block.nodes.size());
  for (std::size_t i = 0; i < block.nodes.size(); ++i)
    EXPECT_LT((back.nodes[i] - block.nodes[i]).norm(), 1e-15);
  EXPECT_NEAR(core::total_volume(back), core::total_volume(block), 1e-15);
  EXPECT_EQ(back.surface_faces, block.surface_faces);
}

INSTANTIATE_TEST_SUITE_P(Formats, TetMeshRoundTrip, ::testing::Values(".vtu", ".vtk", ".msh"),
                         [](const auto& format) { return format.param.substr(1); });

TEST(MeshWriter, millimetre_files_are_read_in_metres) {
  const auto dir = viscera::testing::scratch_dir();
  const core::SurfaceMesh sphere = core::make_icosphere(50.0, 2);  // 50 "mm"
  write_meshes({{"sphere", &sphere}}, dir / "mm.stl");
  const auto back = importers::read_mesh(dir / "mm.stl", importers::LengthUnit::Millimetre);
  EXPECT_NEAR(core::bounds(back).size().x(), 0.1, 1e-6);
}

TEST(MeshWriter, refuses_unknown_extension_and_empty_mesh) {
  const auto dir = viscera::testing::scratch_dir();
  const core::SurfaceMesh empty;
  const core::SurfaceMesh sphere = core::make_icosphere(1.0, 1);
  EXPECT_THROW(write_meshes({{"s", &sphere}}, dir / "x.unknown"), core::UsageError);
  EXPECT_THROW(write_meshes({{"s", &empty}}, dir / "x.stl"), core::InputError);
  EXPECT_FALSE(std::filesystem::exists(dir / "x.stl"));
}

TEST(MeshReader, names_the_file_when_it_is_garbage) {
  const auto dir = viscera::testing::scratch_dir();
  const auto path = dir / "broken.ply";
  std::ofstream(path)
      << "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nend_header\n1\n";
  try {
    importers::read_mesh(path);
    FAIL() << "garbage accepted";
  } catch (const core::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("broken.ply"), std::string::npos) << e.what();
  }
  EXPECT_THROW(importers::read_mesh(dir / "missing.obj"), core::InputError);
}

}  // namespace
}  // namespace viscera::exporters
