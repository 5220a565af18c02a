// Exports are all-or-nothing and reproducible: same scenario, same bytes; a failure leaves no
// file; an older export is replaced whole.
#include <gtest/gtest.h>

#include <fstream>

#include "core/error.h"
#include "exporters/scenario_exporter.h"
#include "tests/exporters/export_fixtures.h"
#include "tests/support/test_paths.h"

namespace viscera::exporters {
namespace {

namespace fs = std::filesystem;

std::map<std::string, std::string> tree(const fs::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& entry : fs::recursive_directory_iterator(dir)) {
    if (entry.is_regular_file())
      files[fs::relative(entry.path(), dir).string()] = testing::file_bytes(entry.path());
  }
  return files;
}

TEST(StagedExport, every_format_gives_the_same_bytes_twice) {
  const auto& scenario = testing::export_scenario_fixture();
  const fs::path dir = testing::scratch_dir();
  for (const auto& [format, name] :
       std::vector<std::pair<ExportFormat, std::string>>{{ExportFormat::Vtk, "p.vtm"},
                                                         {ExportFormat::Gltf, "p.gltf"},
                                                         {ExportFormat::Glb, "p.glb"},
                                                         {ExportFormat::Obj, "p.obj"},
                                                         {ExportFormat::Stl, "p.stl"},
                                                         {ExportFormat::Ply, "p.ply"},
                                                         {ExportFormat::Msh, "p.msh"},
                                                         {ExportFormat::Sofa, "p.scn"}}) {
    fs::create_directories(dir / "a");
    fs::create_directories(dir / "b");
    export_scenario(scenario, format, dir / "a" / name, testing::export_textures_fixture());
    export_scenario(scenario, format, dir / "b" / name, testing::export_textures_fixture());
    const auto a = tree(dir / "a"), b = tree(dir / "b");
    EXPECT_EQ(a.size(), b.size()) << name;
    for (const auto& [file, bytes] : a)
      EXPECT_TRUE(b.contains(file) && b.at(file) == bytes) << name << ": " << file;
    fs::remove_all(dir / "a");
    fs::remove_all(dir / "b");
  }
}

TEST(StagedExport, a_missing_map_or_folder_leaves_nothing_and_an_older_export_is_replaced_whole) {
  const auto& scenario = testing::export_scenario_fixture();
  const fs::path dir = testing::scratch_dir();
  try {
    export_scenario(scenario, ExportFormat::Obj, dir / "p.obj", {});
    FAIL() << "exported without its maps";
  } catch (const core::InputError& e) {
    EXPECT_TRUE(testing::message_has(e.what(), {"object ball", "texture map", "missing"}))
        << e.what();
  }
  // A file where a folder of the output path should be: an error, nothing written.
  std::ofstream(dir / "no") << "a file";
  EXPECT_THROW(export_scenario(scenario, ExportFormat::Glb, dir / "no" / "p.glb",
                               testing::export_textures_fixture()),
               core::OutputError);
  fs::remove(dir / "no");
  EXPECT_TRUE(fs::is_empty(dir));

  // An older multiblock with an extra piece is replaced by the new one, piece folder included.
  export_scenario(scenario, ExportFormat::Vtk, dir / "p.vtm", {}, {{"plate"}});
  std::ofstream(dir / "p" / "stale.vtp") << "old";
  export_scenario(scenario, ExportFormat::Vtk, dir / "p.vtm", testing::export_textures_fixture());
  EXPECT_FALSE(fs::exists(dir / "p" / "stale.vtp"));
  EXPECT_TRUE(fs::exists(dir / "p" / "ball_body.vtu"));
  // A folder where the export's file should go is not an older export: refused, kept.
  fs::create_directories(dir / "q.stl");
  EXPECT_THROW(export_scenario(scenario, ExportFormat::Stl, dir / "q.stl",
                               testing::export_textures_fixture()),
               core::OutputError);
  EXPECT_TRUE(fs::is_directory(dir / "q.stl"));
  for (const auto& entry : fs::directory_iterator(dir)) {
    EXPECT_EQ(entry.path().filename().string().rfind('.', 0), std::string::npos)
        << "left behind: " << entry.path();
  }
}

TEST(StagedExport, missing_output_folders_are_made_and_removed_again_when_the_export_fails) {
  const fs::path dir = testing::scratch_dir();
  export_scenario(testing::export_scenario_fixture(), ExportFormat::Glb,
                  dir / "new" / "deeper" / "p.glb", testing::export_textures_fixture());
  EXPECT_TRUE(fs::is_regular_file(dir / "new" / "deeper" / "p.glb"));
  // The SOFA writer refuses a urethra lattice while writing: the folders it made go too.
  core::Scenario scenario = testing::export_scenario_fixture();
  scenario.objects[2].body_kind = core::BodyKind::UrethraLattice;
  EXPECT_THROW(export_scenario(scenario, ExportFormat::Sofa, dir / "made" / "for" / "p.scn",
                               testing::export_textures_fixture()),
               core::UsageError);
  EXPECT_FALSE(fs::exists(dir / "made"));
}

}  // namespace
}  // namespace viscera::exporters
