// The headers of OFF and PLY files are checked before assimp reads them (importers/mesh/
// off_header.h, ply_header.h), and VTK's failed allocations are typed (vtk_mesh_file.cpp): the
// fuzz findings of mesh_off, mesh_ply, mesh_vtk and mesh_vtp are refused with one sentence, the
// sentence of the check that runs before the library (so the library never met the file), and
// every real OFF and PLY file of CGAL's data and assimp's test models passes the checks. These
// tests live beside the other MeshImport tests, whose real-file fixtures they share.
#include <gtest/gtest.h>

#include <fstream>

#include "core/error.h"
#include "importers/mesh/off_header.h"
#include "importers/mesh/ply_header.h"
#include "importers/mesh_reader.h"
#include "tests/exporters/export_fixtures.h"
#include "tests/support/test_paths.h"

namespace viscera::importers {
namespace {

namespace fs = std::filesystem;

using testing::mesh_read_error;

fs::path regression(const std::string& target, const std::string& name) {
  return testing::source_dir() / "tests" / "fuzz" / "regressions" / target / name;
}

/// A copy of `source` named `name` in this test's scratch folder with the first `from` replaced
/// by `to`.
fs::path patched(const fs::path& source, const std::string& from, const std::string& to,
                 const std::string& name) {
  std::string bytes = testing::file_bytes(source);
  const auto at = bytes.find(from);
  EXPECT_NE(at, std::string::npos) << from << " is not in " << source;
  if (at != std::string::npos) bytes.replace(at, from.size(), to);
  const fs::path path = testing::scratch_dir() / name;
  std::ofstream(path, std::ios::binary) << bytes;
  return path;
}

TEST(MeshHeaderChecks, the_off_finding_is_refused_for_its_vertex_count_before_assimp_reads_it) {
  const fs::path path = regression("mesh_off", "vertex_count_past_32_bits.off");
  EXPECT_TRUE(testing::message_has(
      mesh_read_error(path),
      {path.string(), "line 2", "declares 499999999999999 vertices", "32-bit count"}))
      << mesh_read_error(path);
  // assimp's own test file for the same fault.
  const fs::path assimps = testing::assimp_model("invalid/OutOfMemory.off");
  EXPECT_TRUE(testing::message_has(mesh_read_error(assimps), {"declares 353535235358 vertices"}))
      << mesh_read_error(assimps);
}

TEST(MeshHeaderChecks, an_off_file_declaring_more_vertices_than_it_has_lines_is_refused) {
  const fs::path cube = testing::assimp_model("OFF/Cube.off");
  const fs::path path = patched(cube, "8 6 0", "100000000 6 0", "many.off");
  EXPECT_TRUE(testing::message_has(
      mesh_read_error(path), {"many.off", "declares 100000000 vertices and 6 faces", "at least"}))
      << mesh_read_error(path);
  EXPECT_EQ(read_mesh(patched(cube, "8 6 0", "8 6 0", "same.off")).triangles.size(), 12u);
}

TEST(MeshHeaderChecks, the_ply_finding_is_refused_for_its_missing_end_header) {
  const fs::path path = regression("mesh_ply", "no_end_header.ply");
  EXPECT_TRUE(
      testing::message_has(mesh_read_error(path), {path.string(), "has no end_header line"}))
      << mesh_read_error(path);
  // Assimp picks its reader by content when the extension is not one it knows: still checked.
  const fs::path renamed = testing::scratch_dir() / "no_end_header.scan";
  fs::copy_file(path, renamed);
  EXPECT_TRUE(testing::message_has(mesh_read_error(renamed), {"has no end_header line"}))
      << mesh_read_error(renamed);
}

TEST(MeshHeaderChecks, a_file_is_read_as_what_its_extension_says_or_refused) {
  // Assimp would hand a .glb its glTF readers refuse to any reader whose signature matches: a
  // PLY cube named .glb was read as PLY, and the mesh_glb finding went on to OpenGEX.
  const fs::path ply_as_glb = testing::scratch_dir() / "cube_in_disguise.glb";
  fs::copy_file(testing::assimp_model("PLY/cube.ply"), ply_as_glb,
                fs::copy_options::overwrite_existing);
  EXPECT_TRUE(testing::message_has(mesh_read_error(ply_as_glb), {"cube_in_disguise.glb"}))
      << mesh_read_error(ply_as_glb);
  // A name assimp does not know still lets the content choose.
  const fs::path ply_as_scan = testing::scratch_dir() / "cube.scan";
  fs::copy_file(testing::assimp_model("PLY/cube.ply"), ply_as_scan,
                fs::copy_options::overwrite_existing);
  EXPECT_EQ(read_mesh(ply_as_scan).triangles.size(), 12u);
  // The finding itself, as a .glb and under OpenGEX's own name (that reader is taken out).
  const fs::path finding = regression("mesh_glb", "opengex_text_after_a_failed_gltf_read.glb");
  EXPECT_TRUE(testing::message_has(mesh_read_error(finding), {finding.string()}));
  const fs::path as_ogex = testing::scratch_dir() / "finding.ogex";
  fs::copy_file(finding, as_ogex, fs::copy_options::overwrite_existing);
  EXPECT_TRUE(testing::message_has(mesh_read_error(as_ogex), {"finding.ogex"}))
      << mesh_read_error(as_ogex);
}

TEST(MeshHeaderChecks, ascii_and_binary_ply_declaring_more_elements_than_they_hold_are_refused) {
  const fs::path ascii = patched(testing::assimp_model("PLY/cube.ply"), "element vertex 8",
                                 "element vertex 400000000", "ascii.ply");
  EXPECT_TRUE(testing::message_has(mesh_read_error(ascii), {"ascii.ply", "400000000 \"vertex\"",
                                                            "bytes in ascii", "follow end_header"}))
      << mesh_read_error(ascii);
  const fs::path binary = patched(testing::assimp_model("PLY/cube_binary.ply"), "element vertex 8",
                                  "element vertex 400000000", "binary.ply");
  EXPECT_TRUE(testing::message_has(mesh_read_error(binary),
                                   {"binary.ply", "at least 4800000", "binary_little_endian"}))
      << mesh_read_error(binary);
  const fs::path wide = patched(testing::assimp_model("PLY/cube.ply"), "element face 6",
                                "element face 99999999999", "wide.ply");
  EXPECT_TRUE(testing::message_has(mesh_read_error(wide), {"99999999999 \"face\"", "32-bit count"}))
      << mesh_read_error(wide);
  EXPECT_EQ(read_mesh(testing::assimp_model("PLY/cube_binary.ply")).triangles.size(), 12u);
}

TEST(MeshHeaderChecks, every_real_off_and_ply_file_passes_the_header_checks) {
  std::vector<fs::path> files = testing::cgal_meshes_ending(".off");
  const auto plys = testing::cgal_meshes_ending(".ply");
  files.insert(files.end(), plys.begin(), plys.end());
  for (const char* model :
       {"OFF/Cube.off", "OFF/Wuson.off", "PLY/Wuson.ply", "PLY/cube.ply", "PLY/cube_binary.ply",
        "PLY/cube_uv.ply", "PLY/float-color.ply", "PLY/issue623.ply", "PLY/points.ply"})
    files.push_back(testing::assimp_model(model));
  EXPECT_GE(files.size(), 150u);
  for (const fs::path& file : files) {
    try {
      if (file.extension() == ".off")
        check_off_counts(file);
      else
        check_ply_header(file);
    } catch (const core::InputError& e) {
      ADD_FAILURE() << e.what();
    }
  }
}

TEST(MeshHeaderChecks, a_real_binary_ply_cut_short_is_refused_as_such) {
  // assimp's pond.0.ply: 70051 vertices of 31 bytes need 2171581 bytes; 2171512 follow its header.
  const fs::path pond = testing::assimp_model("PLY/pond.0.ply");
  EXPECT_TRUE(testing::message_has(
      mesh_read_error(pond),
      {"70051 \"vertex\"", "at least 2171581 bytes", "only 2171512 follow end_header"}))
      << mesh_read_error(pond);
}

TEST(MeshHeaderChecks, the_vtk_findings_are_refused_without_a_crash_or_an_untyped_error) {
  const fs::path legacy = regression("mesh_vtk", "read_string_crashes_vtk.vtk");
  EXPECT_TRUE(
      testing::message_has(mesh_read_error(legacy), {legacy.string(), "VTK's reader crashes"}))
      << mesh_read_error(legacy);
  // NumberOfPoints of 8.9·10¹⁸: the allocation fails at once in the guard's child, which is
  // bounded in memory (core/crash_guard.h), and the file is refused without being read here.
  const fs::path xml = regression("mesh_vtp", "number_of_points_beyond_memory.vtp");
  EXPECT_TRUE(testing::message_has(mesh_read_error(xml), {xml.string(), "exhausts its memory"}))
      << mesh_read_error(xml);
  // Cells the legacy reader takes without a check, each a SEGV in vtkTriangleFilter once.
  const fs::path past = regression("mesh_vtk", "cell_names_a_point_past_the_file.vtk");
  EXPECT_TRUE(testing::message_has(mesh_read_error(past), {past.string(), "a cell names point"}))
      << mesh_read_error(past);
  const fs::path negative = regression("mesh_vtk", "negative_point_count.vtk");
  EXPECT_TRUE(testing::message_has(mesh_read_error(negative),
                                   {negative.string(), "negative number of points"}))
      << mesh_read_error(negative);
}

}  // namespace
}  // namespace viscera::importers
