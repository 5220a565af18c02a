// `viscera mesh surface|tets|quality` run as the real program (issue 3 §3, §4, §7): a phantom
// label map → tets → quality with no inverted tets; closed surfaces through gmsh; bad input
// refused with exit code 3, the file named and nothing written.

#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "core/image/image_volume_io.h"
#include "core/package/vtk_mesh_io.h"
#include "tests/meshing/label_phantoms.h"
#include "tests/support/command_runner.h"
#include "tests/support/test_paths.h"

namespace viscera {
namespace {

using testing::run_program;
using testing::shell_quote;

std::string at(const std::filesystem::path& dir, const std::string& name) {
  return shell_quote((dir / name).string());
}

std::filesystem::path write_spheroid(const std::filesystem::path& dir) {
  auto labels = testing::spheroid_phantom(0.016, 0.022, testing::PhantomFrame::rotated(25));
  labels.names[1] = "uterus";
  const auto path = dir / "labels.vti";
  core::write_label_map_vti(labels, path);
  return path;
}

TEST(LabelMeshCli, label_map_to_tets_then_quality_has_no_inverted_tets) {
  const auto dir = testing::scratch_dir();
  const auto labels = write_spheroid(dir);
  const auto tets = run_program("viscera",
                                "mesh tets " + shell_quote(labels.string()) +
                                    " --cell-size 0.0025 -o " + at(dir, "body.vtu") + " --json",
                                dir);
  ASSERT_EQ(tets.exit_code, 0) << tets.err;
  const auto made = nlohmann::json::parse(tets.out);
  EXPECT_EQ(made["quality"]["inverted"], 0);
  EXPECT_GT(made["quality"]["tets"].get<int>(), 1000);
  EXPECT_LT(made["embedding_max_error_m"].get<double>(), 1e-12);
  EXPECT_EQ(made["criteria"]["mesher"], "CGAL Mesh_3");
  ASSERT_TRUE(std::filesystem::exists(dir / "body.vtu"));
  ASSERT_TRUE(std::filesystem::exists(dir / "body_surface.vtp"));

  core::SurfaceMesh surface;
  core::SurfaceEmbedding embedding;
  core::read_surface_vtp(dir / "body_surface.vtp", surface, embedding);
  EXPECT_EQ(embedding.tet.size(), surface.vertices.size());
  EXPECT_EQ(surface.triangles.size(), made["surface_triangles"].get<std::size_t>());

  const auto quality =
      run_program("viscera", "mesh quality " + at(dir, "body.vtu") + " --json", dir);
  ASSERT_EQ(quality.exit_code, 0) << quality.err;
  const auto report = nlohmann::json::parse(quality.out);
  EXPECT_EQ(report["inverted"], 0);
  EXPECT_EQ(report["tets"], made["quality"]["tets"]);
  EXPECT_EQ(report["tets_per_label"]["1"], made["quality"]["tets"]);
  EXPECT_GT(report["min_dihedral_degrees"].get<double>(), 0.0);
  EXPECT_NEAR(report["total_volume_m3"].get<double>() /
                  (4.0 / 3.0 * 3.14159265358979 * 0.016 * 0.016 * 0.022),
              1.0, 0.02);
}

TEST(LabelMeshCli, surface_per_label_with_area_and_volume) {
  const auto dir = testing::scratch_dir();
  const auto labels = dir / "shell.vti";
  core::write_label_map_vti(
      testing::shell_phantom(0.015, 0.02, 0.008, testing::PhantomFrame::rotated(0)), labels);
  const auto r = run_program("viscera",
                             "mesh surface " + shell_quote(labels.string()) +
                                 " --triangles 5000 -o " + at(dir, "s.vtp") + " --json",
                             dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto json = nlohmann::json::parse(r.out);
  ASSERT_EQ(json["surfaces"].size(), 2u);
  EXPECT_EQ(json["surfaces"][1]["label"], 2);
  EXPECT_NEAR(
      json["surfaces"][1]["volume_m3"].get<double>() / testing::spheroid_volume(0.008, 0.008), 1.0,
      0.03);
  EXPECT_LE(json["surfaces"][0]["triangles"].get<int>(), 5050);
  core::SurfaceMesh surface;
  core::SurfaceEmbedding none;
  core::read_surface_vtp(dir / "s.vtp", surface, none);
  ASSERT_EQ(surface.vertex_attributes.count("label"), 1u);
}

TEST(LabelMeshCli, closed_surface_to_tets_with_gmsh) {
  const auto dir = testing::scratch_dir();
  const auto labels = write_spheroid(dir);
  ASSERT_EQ(run_program("viscera",
                        "mesh surface " + shell_quote(labels.string()) + " --triangles 3000 -o " +
                            at(dir, "s.stl"),
                        dir)
                .exit_code,
            0);
  const auto r = run_program(
      "viscera",
      "mesh tets " + at(dir, "s.stl") + " --cell-size 0.004 -o " + at(dir, "g.msh") + " --json",
      dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto json = nlohmann::json::parse(r.out);
  EXPECT_EQ(json["criteria"]["mesher"], "gmsh");
  EXPECT_EQ(json["quality"]["inverted"], 0);
  EXPECT_TRUE(std::filesystem::exists(dir / "g_surface.vtp"));
}

TEST(LabelMeshCli, empty_label_map_exits_3_naming_the_file_and_writes_nothing) {
  const auto dir = testing::scratch_dir();
  core::LabelMap empty;
  empty.image.scalar_type = core::ScalarType::UInt16;
  empty.image.dims = {10, 10, 10};
  empty.image.allocate();
  core::write_label_map_vti(empty, dir / "empty.vti");
  for (const std::string command : {"tets", "surface"}) {
    const std::string out = command == "tets" ? "out.vtu" : "out.vtp";
    const auto r = run_program(
        "viscera", "mesh " + command + " " + at(dir, "empty.vti") + " -o " + at(dir, out), dir);
    EXPECT_EQ(r.exit_code, 3) << command << ": " << r.err;
    EXPECT_NE(r.err.find("empty.vti"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("empty"), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / out));
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "out_surface.vtp"));
}

TEST(LabelMeshCli, nan_or_self_intersecting_surface_exits_3_and_writes_nothing) {
  const auto dir = testing::scratch_dir();
  {
    std::ofstream nan(dir / "nan.obj");
    nan << "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 nan\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 3 1 4\n";
    // Two tetrahedra as one surface, crossing each other.
    std::ofstream crossing(dir / "crossing.obj");
    crossing << "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
                "v 0.2 0.2 0.2\nv 1.2 0.2 0.2\nv 0.2 1.2 0.2\nv 0.2 0.2 1.2\n"
                "f 1 3 2\nf 1 2 4\nf 2 3 4\nf 3 1 4\nf 5 7 6\nf 5 6 8\nf 6 7 8\nf 7 5 8\n";
  }
  for (const std::string name : {"nan.obj", "crossing.obj"}) {
    const auto r =
        run_program("viscera", "mesh tets " + at(dir, name) + " -o " + at(dir, "t.vtu"), dir);
    EXPECT_EQ(r.exit_code, 3) << name << ": " << r.err;
    EXPECT_NE(r.err.find(name), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "t.vtu"));
    EXPECT_FALSE(std::filesystem::exists(dir / "t_surface.vtp"));
  }
}

TEST(LabelMeshCli, quality_of_an_unreadable_file_exits_3) {
  const auto dir = testing::scratch_dir();
  std::ofstream(dir / "junk.vtu") << "not a mesh";
  const auto r = run_program("viscera", "mesh quality " + at(dir, "junk.vtu"), dir);
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_NE(r.err.find("junk.vtu"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace viscera
