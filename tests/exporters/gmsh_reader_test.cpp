// The gmsh reader on meshes the gmsh program makes from its own tutorials (Debian gmsh-doc), in
// every format version and encoding, and on files that are broken in each way a reader meets.
#include <gtest/gtest.h>

#include <bit>
#include <cstring>
#include <fstream>

#include "core/error.h"
#include "importers/mesh_reader.h"
#include "tests/exporters/export_fixtures.h"
#include "tests/support/test_paths.h"

namespace viscera::importers {
namespace {

namespace fs = std::filesystem;

fs::path t5(const std::string& format, bool binary) {
  return testing::gmsh_tutorial_mesh("t5", "-3 -format " + format + (binary ? " -bin" : ""),
                                     "t5-" + format + (binary ? "-bin" : "") + ".msh");
}

std::string error_of(const std::function<void()>& read) {
  try {
    read();
  } catch (const core::InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(GmshReader, every_version_and_encoding_of_a_tutorial_mesh_gives_the_same_tetrahedra) {
  const core::TetMesh reference = read_tet_mesh(t5("msh41", false));
  EXPECT_GT(reference.tets.size(), 1000u);
  EXPECT_GT(core::total_volume(reference), 0.0);
  EXPECT_FALSE(reference.tet_labels.empty());
  for (const auto& [format, binary] :
       {std::pair{"msh41", true}, {"msh40", false}, {"msh22", false}, {"msh22", true}}) {
    const core::TetMesh mesh = read_tet_mesh(t5(format, binary));
    ASSERT_EQ(mesh.nodes.size(), reference.nodes.size());
    double largest = 0.0;  // ASCII files round coordinates to 16 or 17 digits
    for (std::size_t i = 0; i < mesh.nodes.size(); ++i)
      largest = std::max(largest, (mesh.nodes[i] - reference.nodes[i]).norm());
    EXPECT_LT(largest, 1e-15) << format << (binary ? " binary" : " ASCII");
    EXPECT_EQ(mesh.tets, reference.tets) << format << (binary ? " binary" : " ASCII");
    EXPECT_EQ(mesh.tet_labels, reference.tet_labels) << format << (binary ? " binary" : " ASCII");
  }
  // gmsh's own legacy VTK output of the same mesh, through VTK's reader.
  const core::TetMesh vtk =
      read_tet_mesh(testing::gmsh_tutorial_mesh("t5", "-3 -format vtk", "t5.vtk"));
  EXPECT_EQ(vtk.tets.size(), reference.tets.size());
  EXPECT_NEAR(core::total_volume(vtk), core::total_volume(reference),
              1e-9 * core::total_volume(reference));
}

TEST(GmshReader, the_surface_of_a_volume_mesh_is_closed_and_encloses_the_tet_volume) {
  const core::TetMesh body = read_tet_mesh(t5("msh41", true));
  const core::SurfaceMesh surface = read_mesh(t5("msh41", true));
  // t5's surface elements are the boundaries of its volumes: the cube minus its holes and the
  // balls that fill some of them, so together they enclose the tets' volume.
  EXPECT_NEAR(std::abs(core::enclosed_volume(surface)), core::total_volume(body),
              0.5 * core::total_volume(body));
  EXPECT_GT(surface.triangles.size(), 100u);
}

TEST(GmshReader, a_two_dimensional_tutorial_gives_its_triangles_and_no_tetrahedra) {
  const fs::path t1 = testing::gmsh_tutorial_mesh("t1", "-2 -format msh41", "t1.msh");
  const core::SurfaceMesh surface = read_mesh(t1, LengthUnit::Centimetre);
  EXPECT_NEAR(core::surface_area(surface), 0.03 * 1e-4, 1e-15);  // 0.1 × 0.3 cm²
  EXPECT_THROW(read_tet_mesh(t1), NoTetrahedraError);
}

TEST(GmshReader, quadrangles_of_a_real_file_are_split_into_triangles) {
  const fs::path view5 = "/usr/share/doc/gmsh-doc/doc/gmsh/tutorial/view5.msh";
  ASSERT_TRUE(fs::exists(view5)) << "install the Debian package gmsh-doc (dev.sh lists it)";
  const core::SurfaceMesh surface = read_mesh(view5);
  EXPECT_EQ(surface.triangles.size(), 4u);
  EXPECT_NEAR(core::surface_area(surface), 0.03, 1e-15);
}

TEST(GmshReader, prisms_and_hexahedra_are_refused_naming_the_file) {
  const fs::path t3 = testing::gmsh_tutorial_mesh("t3", "-3 -format msh41", "t3.msh");
  const std::string message = error_of([&] { read_tet_mesh(t3); });
  EXPECT_TRUE(testing::message_has(message, {"t3.msh", "only tetrahedral meshes are read"}))
      << message;
}

/// A file that is `fraction` of `source`, as a copy cut off in transfer.
fs::path truncated_copy(const fs::path& source, double fraction, const std::string& name) {
  const std::string bytes = testing::file_bytes(source);
  const fs::path path = testing::scratch_dir() / name;
  std::ofstream(path, std::ios::binary)
      << bytes.substr(0, static_cast<std::size_t>(fraction * static_cast<double>(bytes.size())));
  return path;
}

TEST(GmshReader, truncated_files_name_the_file_and_the_section_where_they_end) {
  for (const auto& [format, binary] :
       {std::pair{"msh41", false}, {"msh41", true}, {"msh22", false}, {"msh22", true}}) {
    const fs::path cut = truncated_copy(
        t5(format, binary), 0.6, std::string("cut-") + format + (binary ? "-bin" : "") + ".msh");
    const std::string message = error_of([&] { read_tet_mesh(cut); });
    EXPECT_TRUE(testing::message_has(message, {cut.filename().string(), "$Elements"})) << message;
    EXPECT_NE(message.find("ends"), std::string::npos) << message;
  }
}

fs::path written(const std::string& name, const std::string& text) {
  const fs::path path = testing::scratch_dir() / name;
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

const char* kTetV2 =
    "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 "
    "1\n$EndNodes\n"
    "$Elements\n1\n1 4 2 7 1 1 2 3 4\n$EndElements\n";

TEST(GmshReader, a_hand_written_tetrahedron_reads_with_its_physical_label) {
  const core::TetMesh mesh = read_tet_mesh(written("tet.msh", kTetV2), LengthUnit::Millimetre);
  ASSERT_EQ(mesh.tets.size(), 1u);
  EXPECT_EQ(mesh.tet_labels, std::vector<int>{7});
  EXPECT_NEAR(core::total_volume(mesh), 1e-9 / 6.0, 1e-24);
  EXPECT_EQ(mesh.surface_faces.size(), 4u);
}

TEST(GmshReader, broken_headers_and_references_are_named) {
  std::string text = kTetV2;
  const auto replaced = [&](const std::string& from, const std::string& to) {
    std::string copy = text;
    copy.replace(copy.find(from), from.size(), to);
    return copy;
  };
  const std::pair<std::string, std::vector<std::string>> cases[] = {
      {"solid cube\n", {"not a gmsh file"}},
      {replaced("2.2 0 8", "3.0 0 8"), {"format version 3 is not read"}},
      {replaced("2.2 0 8", "4 1 8"), {"binary format 4.0 is not read"}},
      {replaced("$Nodes\n4\n", "$Nodes\n99999999999\n"),
       {"claims 99999999999 nodes", "ends before them", "$Nodes"}},
      {replaced("1 4 2 7 1 1 2 3 4", "1 4 2 7 1 1 2 3 9"), {"refers to node 9", "does not define"}},
      {replaced("4 0 0 1\n", "4 0 0 nan\n"), {"node 3", "not finite"}},
      {replaced("3 0 1 0", "3 0 1 x"), {"\"x\" is not a number", "$Nodes", "node 3 of 4"}},
      {replaced("4 0 0 1", "4 1 1 0"), {"degenerate"}},
  };
  int index = 0;
  for (const auto& [content, parts] : cases) {
    const fs::path path = written("broken-" + std::to_string(index++) + ".msh", content);
    const std::string message = error_of([&] { read_tet_mesh(path); });
    auto expected = parts;
    expected.push_back(path.filename().string());
    for (const auto& part : expected)
      EXPECT_NE(message.find(part), std::string::npos) << part << " in: " << message;
  }
}

TEST(GmshReader, a_face_shared_by_three_tetrahedra_is_refused_as_not_manifold) {
  const std::string fan =
      "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n6\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n5 0 0 "
      "-1\n6 0.1 0.1 2\n"
      "$EndNodes\n$Elements\n3\n1 4 0 1 2 3 4\n2 4 0 1 3 2 5\n3 4 0 1 2 3 6\n$EndElements\n";
  const fs::path path = written("fan.msh", fan);
  const std::string message = error_of([&] { read_tet_mesh(path); });
  EXPECT_TRUE(testing::message_has(
      message, {"fan.msh", "not manifold", "shared by more than two tetrahedra"}))
      << message;
}

/// Big-endian bytes of a value, for files written on machines of the other byte order.
template <typename T>
std::string big_endian(T value) {
  std::string bytes(sizeof(T), '\0');
  std::memcpy(bytes.data(), &value, sizeof(T));
  if constexpr (std::endian::native == std::endian::little)
    std::reverse(bytes.begin(), bytes.end());
  return bytes;
}

TEST(GmshReader, binary_files_of_the_other_byte_order_are_read) {
  // Format 2.2 binary, big-endian: the byte-order mark 1, nodes as (int, 3 doubles), one run of
  // one tetrahedron with two tags.
  std::string v2 =
      "$MeshFormat\n2.2 1 8\n" + big_endian<std::int32_t>(1) + "\n$EndMeshFormat\n$Nodes\n4\n";
  const double corners[4][3] = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {0, 0, 2}};
  for (int n = 0; n < 4; ++n) {
    v2 += big_endian<std::int32_t>(n + 1);
    for (double c : corners[n])
      v2 += big_endian(c);
  }
  v2 += "\n$EndNodes\n$Elements\n1\n";
  for (std::int32_t value : {4, 1, 2, 1, 3, 1, 1, 2, 3, 4})
    v2 += big_endian(value);
  v2 += "\n$EndElements\n";
  const core::TetMesh two = read_tet_mesh(written("big-endian-22.msh", v2));
  EXPECT_NEAR(core::total_volume(two), 8.0 / 6.0, 1e-15);
  EXPECT_EQ(two.tet_labels, std::vector<int>{3});

  // Format 4.1 binary, big-endian: no entities, one node block, one element block.
  std::string v4 =
      "$MeshFormat\n4.1 1 8\n" + big_endian<std::int32_t>(1) + "\n$EndMeshFormat\n$Nodes\n";
  for (std::uint64_t value : {1, 4, 1, 4})
    v4 += big_endian(value);
  v4 += big_endian<std::int32_t>(3) + big_endian<std::int32_t>(1) + big_endian<std::int32_t>(0) +
        big_endian<std::uint64_t>(4);
  for (std::uint64_t tag = 1; tag <= 4; ++tag)
    v4 += big_endian(tag);
  for (const auto& c : corners) {
    for (double x : c)
      v4 += big_endian(x);
  }
  v4 += "\n$EndNodes\n$Elements\n";
  for (std::uint64_t value : {1, 1, 1, 1})
    v4 += big_endian(value);
  v4 += big_endian<std::int32_t>(3) + big_endian<std::int32_t>(1) + big_endian<std::int32_t>(4) +
        big_endian<std::uint64_t>(1);
  for (std::uint64_t value : {1, 1, 2, 3, 4})
    v4 += big_endian(value);
  v4 += "\n$EndElements\n";
  const core::TetMesh four = read_tet_mesh(written("big-endian-41.msh", v4));
  EXPECT_EQ(four.nodes, two.nodes);
  EXPECT_EQ(four.tets, two.tets);
}

}  // namespace
}  // namespace viscera::importers
