// `viscera export` and `viscera mesh convert` run as a user runs them: every format written and
// read back, exit codes of DESIGN.md §9, one line naming the file on bad input, nothing written.
#include <gtest/gtest.h>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include "importers/mesh_reader.h"
#include "tests/exporters/export_fixtures.h"
#include "tests/exporters/gltf_document.h"
#include "tests/support/command_runner.h"
#include "tests/support/test_paths.h"

namespace viscera {
namespace {

namespace fs = std::filesystem;
using testing::run_program;
using testing::shell_quote;

/// A textured ball package made with `viscera new` and `viscera bake`, built once for all the
/// test processes (in the shared real-files folder) and copied into `dir`.
fs::path textured_package(const fs::path& dir) {
  // Named after the build of `viscera` that made it, so a rebuilt program makes a new one.
  const auto built = fs::last_write_time(fs::path(VISCERA_BINARY_DIR) / "bin" / "viscera");
  const fs::path shared =
      testing::shared_test_folder() /
      ("cli-textured-" + std::to_string(built.time_since_epoch().count()) + ".vscene");
  if (!fs::exists(shared)) {
    const fs::path work = testing::shared_test_folder() / (".cli-" + std::to_string(::getpid()));
    fs::create_directories(work);
    const fs::path plain = work / "ball.vscene", textured = work / "textured.vscene";
    EXPECT_EQ(
        run_program("viscera",
                    "new --template ball --seed 3 --set radius=0.02 --set cell_size=0.008 -o " +
                        shell_quote(plain.string()),
                    work)
            .exit_code,
        0);
    const auto baked =
        run_program("viscera",
                    "bake " + shell_quote(plain.string()) +
                        " --preset endometrium --size 64x64 -o " + shell_quote(textured.string()),
                    work);
    EXPECT_EQ(baked.exit_code, 0) << baked.err;
    std::error_code taken;  // another test process may have put its copy in place first
    fs::rename(textured, shared, taken);
    fs::remove_all(work);
  }
  const fs::path copy = dir / "textured.vscene";
  fs::copy(shared, copy, fs::copy_options::recursive);
  return copy;
}

TEST(ExportCommand, export_and_mesh_convert_have_help) {
  const fs::path dir = testing::scratch_dir();
  for (const char* command : {"export", "mesh convert"}) {
    const auto result = run_program("viscera", std::string(command) + " --help", dir);
    EXPECT_EQ(result.exit_code, 0) << command;
    EXPECT_NE(result.out.find("Usage"), std::string::npos) << command;
  }
}

TEST(ExportCommand, writes_every_format_and_each_reads_back) {
  const fs::path dir = testing::scratch_dir();
  const fs::path package = textured_package(dir);
  const std::pair<const char*, const char*> formats[] = {
      {"vtk", "out.vtm"}, {"gltf", "out.gltf"}, {"glb", "out.glb"}, {"obj", "out.obj"},
      {"stl", "out.stl"}, {"ply", "out.ply"},   {"msh", "out.msh"}, {"sofa", "out.scn"}};
  for (const auto& [format, name] : formats) {
    const fs::path out = dir / name;
    const auto result = run_program("viscera",
                                    "export " + shell_quote(package.string()) + " --format " +
                                        format + " -o " + shell_quote(out.string()) + " --json",
                                    dir);
    ASSERT_EQ(result.exit_code, 0) << format << ": " << result.err;
    const auto json = nlohmann::json::parse(result.out);
    EXPECT_EQ(json.at("format"), format);
    EXPECT_EQ(json.at("files").at(0), fs::absolute(out).string());
    for (const auto& file : json.at("files"))
      EXPECT_TRUE(fs::exists(file.get<std::string>())) << file;
    EXPECT_GT(json.at("triangles").get<int>(), 0);
    EXPECT_GT(json.at("tets").get<int>(), 0);
  }
  const auto triangles = importers::read_mesh(dir / "out.stl").triangles.size();
  for (const char* name : {"out.glb", "out.gltf", "out.obj", "out.ply"}) {
    EXPECT_EQ(importers::read_mesh(dir / name).triangles.size(), triangles) << name;
  }
  // The .msh holds the body: its tets, and its boundary as the surface.
  const core::TetMesh body = importers::read_tet_mesh(dir / "out" / "ball_body.vtu");
  EXPECT_EQ(importers::read_tet_mesh(dir / "out.msh").tets.size(), body.tets.size());
  EXPECT_EQ(importers::read_mesh(dir / "out.msh").triangles.size(), body.surface_faces.size());
  EXPECT_TRUE(fs::exists(dir / "out_meshes" / "ball_body.vtk"));
}

TEST(ExportCommand, a_zipped_package_exports_its_maps_too) {
  const fs::path dir = testing::scratch_dir();
  const fs::path package = textured_package(dir);
  ASSERT_EQ(run_program("viscera",
                        "pack " + shell_quote(package.string()) + " -o " +
                            shell_quote((dir / "p.vscz").string()),
                        dir)
                .exit_code,
            0);
  ASSERT_EQ(run_program("viscera",
                        "export " + shell_quote((dir / "p.vscz").string()) + " --format glb -o " +
                            shell_quote((dir / "p.glb").string()),
                        dir)
                .exit_code,
            0);
  const testing::GltfDocument doc(dir / "p.glb");
  fs::path albedo;
  for (const auto& entry : fs::directory_iterator(package / "textures")) {
    if (entry.path().string().find("albedo") != std::string::npos) albedo = entry.path();
  }
  EXPECT_EQ(doc.image_bytes(0), testing::file_bytes(albedo));
}

TEST(ExportCommand, bad_arguments_and_inputs_give_the_contract_exit_codes_and_write_nothing) {
  const fs::path dir = testing::scratch_dir();
  const fs::path package = textured_package(dir);
  const auto export_with = [&](const std::string& arguments) {
    return run_program("viscera", "export " + arguments, dir / "textured.vscene" / "..");
  };
  const std::string p = shell_quote(package.string());
  EXPECT_EQ(export_with(p + " --format fbx -o " + shell_quote((dir / "x.fbx").string())).exit_code,
            2);
  EXPECT_EQ(export_with(p + " --format glb -o " + shell_quote((dir / "x.gltf").string())).exit_code,
            2);
  EXPECT_EQ(
      export_with(p + " --format glb --object liver -o " + shell_quote((dir / "x.glb").string()))
          .exit_code,
      2);
  const auto missing = export_with(shell_quote((dir / "none.vscene").string()) +
                                   " --format glb -o " + shell_quote((dir / "x.glb").string()));
  EXPECT_EQ(missing.exit_code, 3);
  EXPECT_NE(missing.err.find("none.vscene"), std::string::npos) << missing.err;
  for (const char* name : {"x.fbx", "x.gltf", "x.glb"})
    EXPECT_FALSE(fs::exists(dir / name)) << name;
}

TEST(MeshConvertCommand, tets_stay_tets_and_surfaces_are_taken_from_volume_files) {
  const fs::path dir = testing::scratch_dir();
  const fs::path t5 =
      testing::gmsh_tutorial_mesh("t5", "-3 -format msh41 -bin", "t5-msh41-bin.msh");
  const auto tets = run_program("viscera",
                                "mesh convert " + shell_quote(t5.string()) + " -o " +
                                    shell_quote((dir / "t5.vtu").string()) + " --units mm --json",
                                dir);
  ASSERT_EQ(tets.exit_code, 0) << tets.err;
  const auto json = nlohmann::json::parse(tets.out);
  EXPECT_EQ(json.at("kind"), "tetrahedra");
  const core::TetMesh body = importers::read_tet_mesh(dir / "t5.vtu");
  EXPECT_EQ(json.at("tets").get<std::size_t>(), body.tets.size());
  EXPECT_NEAR(core::total_volume(body), core::total_volume(importers::read_tet_mesh(t5)) * 1e-9,
              1e-18);

  const auto surface = run_program("viscera",
                                   "mesh convert " + shell_quote((dir / "t5.vtu").string()) +
                                       " -o " + shell_quote((dir / "t5.stl").string()) + " --json",
                                   dir);
  ASSERT_EQ(surface.exit_code, 0) << surface.err;
  EXPECT_EQ(nlohmann::json::parse(surface.out).at("kind"), "surface");
  EXPECT_EQ(importers::read_mesh(dir / "t5.stl").triangles.size(), body.surface_faces.size());
}

TEST(MeshConvertCommand, a_bad_mesh_exits_3_with_one_line_naming_the_file_and_writes_nothing) {
  const fs::path dir = testing::scratch_dir();
  const fs::path bad = testing::cgal_mesh("tetra_intersected_by_triangle.off");
  const auto result = run_program("viscera",
                                  "mesh convert " + shell_quote(bad.string()) + " -o " +
                                      shell_quote((dir / "out.glb").string()),
                                  dir);
  EXPECT_EQ(result.exit_code, 3);
  EXPECT_TRUE(testing::message_has(result.err, {"viscera: ", bad.string(), "intersects itself"}))
      << result.err;
  EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
  EXPECT_FALSE(fs::exists(dir / "out.glb"));
  // A surface cannot become a .vtu: a usage error.
  EXPECT_EQ(run_program("viscera",
                        "mesh convert " + shell_quote(testing::cgal_mesh("elephant.off").string()) +
                            " -o " + shell_quote((dir / "e.vtu").string()),
                        dir)
                .exit_code,
            2);
}

}  // namespace
}  // namespace viscera
