// `viscera library list|add|get|rm|export|import` as a user runs them: the library chosen by
// --library or VISCERA_LIBRARY, payloads read back byte for byte, typed exit codes.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>

#include "tests/support/command_runner.h"
#include "tests/support/test_paths.h"

namespace viscera {
namespace {

namespace fs = std::filesystem;
using testing::run_program;
using testing::shell_quote;

TEST(LibraryCommand, add_list_get_rm_round_trip_through_the_library_option) {
  const fs::path dir = testing::scratch_dir();
  fs::current_path(dir);  // the programs run where the test runs; relative names are in dir
  const std::string lib = "--library " + shell_quote((dir / "lib.sqlite").string());
  const fs::path material = dir / "tissue.json";
  std::ofstream(material) << R"({"format": "viscera-material", "version": 1,
    "material": {"id": "tissue", "density": 1060.0}, "report": null})";
  // A PNG thumbnail: the 8-byte signature and a header chunk are all the library checks.
  std::ofstream(dir / "thumb.png", std::ios::binary)
      << std::string("\x89PNG\r\n\x1a\n\0\0\0\rIHDR", 16);

  auto added = run_program("viscera",
                           "library " + lib + " add " + shell_quote(material.string()) +
                               " --tags measured,uterus --thumbnail " +
                               shell_quote((dir / "thumb.png").string()) + " --json",
                           dir);
  ASSERT_EQ(added.exit_code, 0) << added.err;
  auto json = nlohmann::json::parse(added.out);
  EXPECT_EQ(json["name"], "tissue");  // the id inside the material file
  EXPECT_EQ(json["type"], "material");
  EXPECT_EQ(json["version"], 1);
  EXPECT_EQ(json["tags"], (nlohmann::json{"measured", "uterus"}));
  // --library may also follow the action.
  added = run_program("viscera", "library add " + shell_quote(material.string()) + " " + lib, dir);
  ASSERT_EQ(added.exit_code, 0) << added.err;

  const auto listed = run_program("viscera", "library " + lib + " list --all-versions --json", dir);
  ASSERT_EQ(listed.exit_code, 0) << listed.err;
  json = nlohmann::json::parse(listed.out);
  ASSERT_EQ(json["entries"].size(), 2u);
  EXPECT_EQ(json["entries"][1]["version"], 2);
  EXPECT_TRUE(json["entries"][0]["thumbnail"].get<bool>());

  const auto got = run_program("viscera",
                               "library " + lib + " get tissue --version 1 -o " +
                                   shell_quote((dir / "back.json").string()) + " --thumbnail " +
                                   shell_quote((dir / "back.png").string()),
                               dir);
  ASSERT_EQ(got.exit_code, 0) << got.err;
  EXPECT_EQ(viscera::testing::file_bytes(dir / "back.json"),
            viscera::testing::file_bytes(material));
  EXPECT_EQ(viscera::testing::file_bytes(dir / "back.png"),
            viscera::testing::file_bytes(dir / "thumb.png"));

  const auto exported = run_program(
      "viscera", "library " + lib + " export tissue -o " + shell_quote((dir / "t.vasset").string()),
      dir);
  ASSERT_EQ(exported.exit_code, 0) << exported.err;
  const std::string other = "--library " + shell_quote((dir / "other.sqlite").string());
  const auto imported = run_program(
      "viscera", "library " + other + " import " + shell_quote((dir / "t.vasset").string()), dir);
  ASSERT_EQ(imported.exit_code, 0) << imported.err;
  ASSERT_EQ(
      run_program(
          "viscera",
          "library " + other + " get tissue -o " + shell_quote((dir / "other.json").string()), dir)
          .exit_code,
      0);
  EXPECT_EQ(viscera::testing::file_bytes(dir / "other.json"),
            viscera::testing::file_bytes(material));

  const auto removed = run_program("viscera", "library " + lib + " rm tissue --json", dir);
  ASSERT_EQ(removed.exit_code, 0) << removed.err;
  EXPECT_EQ(nlohmann::json::parse(removed.out)["removed_versions"], 2);
  const auto missing = run_program("viscera", "library " + lib + " get tissue -o x.json", dir);
  EXPECT_EQ(missing.exit_code, 3);
  EXPECT_NE(missing.err.find("tissue"), std::string::npos) << missing.err;
  EXPECT_FALSE(fs::exists(dir / "x.json"));
}

/// Width and height from a PNG's IHDR chunk.
std::pair<int, int> png_size(const std::string& png) {
  const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(png.at(i)); };
  return {(byte(16) << 24) | (byte(17) << 16) | (byte(18) << 8) | byte(19),
          (byte(20) << 24) | (byte(21) << 16) | (byte(22) << 8) | byte(23)};
}

TEST(LibraryCommand, textures_and_packages_get_thumbnails_of_themselves) {
  const fs::path dir = testing::scratch_dir();
  fs::current_path(dir);
  const std::string lib = " --library lib.sqlite";
  ASSERT_EQ(
      run_program("viscera", "texture --preset liver --size 96x48 -o liver.png", dir).exit_code, 0);
  const auto texture = run_program("viscera", "library add liver.png --json" + lib, dir);
  ASSERT_EQ(texture.exit_code, 0) << texture.err;
  EXPECT_EQ(nlohmann::json::parse(texture.out)["type"], "texture");
  ASSERT_EQ(
      run_program("viscera", "library get liver -o l.png --thumbnail lt.png" + lib, dir).exit_code,
      0);
  EXPECT_EQ(png_size(viscera::testing::file_bytes(dir / "lt.png")),
            std::make_pair(128, 64));  // aspect kept

  ASSERT_EQ(run_program("viscera", "new --template ball --set cell_size=0.012 -o ball.vscz", dir)
                .exit_code,
            0);
  const auto package = run_program("viscera", "library add ball.vscz --json" + lib, dir);
  ASSERT_EQ(package.exit_code, 0) << package.err;
  const auto json = nlohmann::json::parse(package.out);
  EXPECT_EQ(json["type"], "template");
  EXPECT_TRUE(json["thumbnail"].get<bool>());
  ASSERT_EQ(run_program("viscera", "library get ball -o back.vscz --thumbnail bt.png" + lib, dir)
                .exit_code,
            0);
  EXPECT_EQ(png_size(viscera::testing::file_bytes(dir / "bt.png")), std::make_pair(128, 128));
  EXPECT_EQ(viscera::testing::file_bytes(dir / "back.vscz"),
            viscera::testing::file_bytes(dir / "ball.vscz"));
  EXPECT_EQ(run_program("viscera", "validate back.vscz", dir).exit_code, 0);
}

TEST(LibraryCommand, environment_variable_chooses_the_library_and_errors_have_exit_codes) {
  const fs::path dir = testing::scratch_dir();
  fs::current_path(dir);  // the programs run where the test runs; relative names are in dir
  const fs::path file = dir / "env" / "library.sqlite";
  ::setenv("VISCERA_LIBRARY", file.c_str(), 1);
  std::ofstream(dir / "notes.txt") << "plain words";
  const auto untyped = run_program("viscera", "library add notes.txt", dir);
  EXPECT_EQ(untyped.exit_code, 2) << untyped.err;  // the type cannot be told: --type
  const auto typed =
      run_program("viscera", "library add notes.txt --type template --name notes", dir);
  EXPECT_EQ(typed.exit_code, 0) << typed.err;
  EXPECT_TRUE(fs::exists(file));
  const auto bad_type = run_program("viscera", "library list --type organ", dir);
  EXPECT_EQ(bad_type.exit_code, 2);
  const auto unreadable = run_program("viscera", "library add missing.json --type model", dir);
  EXPECT_EQ(unreadable.exit_code, 3);
  EXPECT_NE(unreadable.err.find("missing.json"), std::string::npos);
  std::ofstream(dir / "broken.sqlite") << "this is not a database file, only some plain words";
  const auto broken = run_program("viscera", "library list --library broken.sqlite", dir);
  EXPECT_EQ(broken.exit_code, 3);
  EXPECT_NE(broken.err.find("broken.sqlite"), std::string::npos) << broken.err;
  ::unsetenv("VISCERA_LIBRARY");
}

}  // namespace
}  // namespace viscera
