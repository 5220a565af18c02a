// VTK and gmsh exports read back: VTK's own multiblock reader, our package readers, our gmsh
// reader and the gmsh program itself.
#include <gtest/gtest.h>
#include <vtkInformation.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkXMLMultiBlockDataReader.h>

#include "core/error.h"
#include "core/package/vtk_mesh_io.h"
#include "exporters/scenario_exporter.h"
#include "importers/mesh_reader.h"
#include "tests/exporters/export_fixtures.h"
#include "tests/support/test_paths.h"

namespace viscera::exporters {
namespace {

const core::Scenario& scenario() {
  return testing::export_scenario_fixture();
}

TEST(VtkExport, multiblock_names_every_object_and_its_pieces_hold_the_package_meshes_exactly) {
  const auto path = testing::export_fixture(ExportFormat::Vtk, "patient.vtm");
  vtkNew<vtkXMLMultiBlockDataReader> reader;
  reader->SetFileName(path.string().c_str());
  reader->Update();
  auto* blocks = vtkMultiBlockDataSet::SafeDownCast(reader->GetOutput());
  ASSERT_NE(blocks, nullptr);
  ASSERT_EQ(blocks->GetNumberOfBlocks(), 3u);
  for (unsigned b = 0; b < 3; ++b) {
    const core::SceneObject& object = scenario().objects[b];
    EXPECT_STREQ(blocks->GetMetaData(b)->Get(vtkMultiBlockDataSet::NAME()), object.id.c_str());
    auto* pieces = vtkMultiBlockDataSet::SafeDownCast(blocks->GetBlock(b));
    ASSERT_NE(pieces, nullptr);
    EXPECT_EQ(pieces->GetNumberOfBlocks(), object.body_kind == core::BodyKind::None ? 1u : 2u);

    core::SurfaceMesh surface;
    core::SurfaceEmbedding embedding;
    core::read_surface_vtp(path.parent_path() / "patient" / (object.id + "_surface.vtp"), surface,
                           embedding);
    EXPECT_EQ(surface.vertices, object.surface.vertices);
    EXPECT_EQ(surface.triangles, object.surface.triangles);
    EXPECT_EQ(surface.uvs, object.surface.uvs);
    EXPECT_EQ(embedding, object.embedding);
    if (object.body_kind != core::BodyKind::None) {
      EXPECT_EQ(core::read_body_vtu(path.parent_path() / "patient" / (object.id + "_body.vtu")),
                object.body);
    }
  }
}

TEST(VtkExport, one_object_goes_to_a_single_vtp_or_vtu_and_several_are_refused_leaving_nothing) {
  const auto vtp = testing::export_fixture(ExportFormat::Vtk, "ball.vtp", {{"ball"}});
  EXPECT_EQ(importers::read_mesh(vtp).triangles, scenario().objects[0].surface.triangles);
  const auto vtu = testing::export_fixture(ExportFormat::Vtk, "ball.vtu", {{"ball"}});
  const core::TetMesh body = importers::read_tet_mesh(vtu);
  const core::TetMesh& ball = scenario().objects[0].body;
  EXPECT_EQ(body.nodes, ball.nodes);
  EXPECT_EQ(body.tets, ball.tets);
  EXPECT_EQ(body.node_mass, ball.node_mass);
  EXPECT_EQ(body.fixed, ball.fixed);
  EXPECT_EQ(body.surface_faces.size(), ball.surface_faces.size());

  const auto dir = testing::scratch_dir();
  try {
    export_scenario(scenario(), ExportFormat::Vtk, dir / "all.vtp",
                    testing::export_textures_fixture());
    FAIL() << "three objects written into one .vtp";
  } catch (const core::UsageError& e) {
    EXPECT_TRUE(testing::message_has(e.what(), {".vtp", "one object", ".vtm"})) << e.what();
  }
  EXPECT_THROW(export_scenario(scenario(), ExportFormat::Vtk, dir / "plate.vtu", {}, {{"plate"}}),
               core::UsageError);
  EXPECT_TRUE(std::filesystem::is_empty(dir));
}

TEST(MshExport, bodies_come_back_bit_identical_with_one_label_per_object) {
  const auto path = testing::export_fixture(ExportFormat::Msh, "patient.msh");
  const core::TetMesh back = importers::read_tet_mesh(path);
  const core::TetMesh& ball = scenario().objects[0].body;
  const core::TetMesh& twin = scenario().objects[1].body;
  ASSERT_EQ(back.nodes.size(), ball.nodes.size() + twin.nodes.size());
  ASSERT_EQ(back.tets.size(), ball.tets.size() + twin.tets.size());
  for (std::size_t i = 0; i < ball.nodes.size(); ++i)
    EXPECT_EQ(back.nodes[i], ball.nodes[i]);
  for (std::size_t i = 0; i < twin.nodes.size(); ++i)
    EXPECT_EQ(back.nodes[ball.nodes.size() + i], twin.nodes[i]);
  for (std::size_t t = 0; t < ball.tets.size(); ++t)
    EXPECT_EQ(back.tets[t], ball.tets[t]);
  EXPECT_EQ(std::count(back.tet_labels.begin(), back.tet_labels.end(), back.tet_labels.front()),
            static_cast<std::ptrdiff_t>(ball.tets.size()));
  EXPECT_NEAR(core::total_volume(back), core::total_volume(ball) + core::total_volume(twin), 1e-15);

  // The surface view: both bodies' boundaries and the plate.
  const core::SurfaceMesh surfaces = importers::read_mesh(path);
  EXPECT_EQ(surfaces.triangles.size(), ball.surface_faces.size() + twin.surface_faces.size() +
                                           scenario().objects[2].surface.triangles.size());
}

TEST(MshExport, the_gmsh_program_reads_the_file_and_writes_the_same_mesh_as_format_2) {
  const auto path = testing::export_fixture(ExportFormat::Msh, "patient.msh");
  const auto legacy = path.parent_path() / "patient-v2.msh";
  const std::string command =
      "gmsh " + path.string() + " -0 -format msh22 -o " + legacy.string() + " -v 1 >/dev/null 2>&1";
  ASSERT_EQ(std::system(command.c_str()), 0)
      << "gmsh (Debian package gmsh) could not read the export";
  const core::TetMesh ours = importers::read_tet_mesh(path);
  const core::TetMesh gmsh = importers::read_tet_mesh(legacy);
  EXPECT_EQ(gmsh.tets.size(), ours.tets.size());
  EXPECT_EQ(gmsh.nodes.size(), ours.nodes.size());
  EXPECT_NEAR(core::total_volume(gmsh), core::total_volume(ours), 1e-12 * core::total_volume(ours));
}

TEST(MshExport, the_same_scenario_gives_the_same_bytes) {
  const auto first = testing::export_fixture(ExportFormat::Msh, "a.msh");
  const auto second = first.parent_path() / "b.msh";
  export_scenario(scenario(), ExportFormat::Msh, second, testing::export_textures_fixture());
  EXPECT_EQ(testing::file_bytes(first), testing::file_bytes(second));
}

}  // namespace
}  // namespace viscera::exporters
