// The texture, bake and vessels commands of DESIGN.md §9, run as the real `viscera` program:
// deterministic outputs, exit codes 2 (usage), 3 (unreadable or empty input, nothing written)
// and 4 (result written but failing its checks).

#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/image/image_volume_io.h"
#include "tests/support/command_runner.h"
#include "tests/support/test_paths.h"

namespace viscera {
namespace {

using testing::run_program;
using testing::shell_quote;

/// The quoted absolute path of `name` in `dir`: the programs run in the test's working folder.
std::string at(const std::filesystem::path& dir, const std::string& name) {
  return shell_quote((dir / name).string());
}

std::size_t line_count(const std::string& text) {
  return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
}

TEST(TextureCli, every_new_command_has_help) {
  const auto dir = testing::scratch_dir();
  for (const char* command : {"texture", "bake", "vessels"}) {
    const auto result = run_program("viscera", std::string(command) + " --help", dir);
    EXPECT_EQ(result.exit_code, 0) << command;
    EXPECT_NE(result.out.find("Usage"), std::string::npos) << command;
  }
}

TEST(TextureCli, noise_prints_the_reference_value) {
  const auto result = run_program("viscera", "noise 3.14 42 7", testing::scratch_dir());
  ASSERT_EQ(result.exit_code, 0);
  EXPECT_EQ(result.out, "0.13691995878400012\n");
}

TEST(TextureCli, same_seed_same_png_bytes_and_maps_on_request) {
  const auto dir = testing::scratch_dir();
  for (const char* name : {"a.png", "b.png"}) {
    const auto r = run_program(
        "viscera", "texture --preset endometrium --seed 4 --size 96x64 --maps -o " + at(dir, name),
        dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  EXPECT_EQ(viscera::testing::file_bytes(dir / "a.png"),
            viscera::testing::file_bytes(dir / "b.png"));
  EXPECT_EQ(viscera::testing::file_bytes(dir / "a_normal.png"),
            viscera::testing::file_bytes(dir / "b_normal.png"));
  EXPECT_TRUE(std::filesystem::exists(dir / "a_specular.png"));
  ASSERT_EQ(
      run_program("viscera",
                  "texture --preset endometrium --seed 5 --size 96x64 -o " + at(dir, "c.png"), dir)
          .exit_code,
      0);
  EXPECT_NE(viscera::testing::file_bytes(dir / "a.png"),
            viscera::testing::file_bytes(dir / "c.png"));
}

TEST(TextureCli, usage_errors_exit_2_and_unreadable_samples_exit_3_writing_nothing) {
  const auto dir = testing::scratch_dir();
  const std::string out = " -o " + at(dir, "x.png");
  EXPECT_EQ(run_program("viscera", "texture --preset spleen" + out, dir).exit_code, 2);
  EXPECT_EQ(run_program("viscera", "texture --preset liver --size 12by4" + out, dir).exit_code, 2);
  { std::ofstream(dir / "broken.png") << "not an image"; }
  const auto r =
      run_program("viscera", "texture --preset liver --sample " + at(dir, "broken.png") + out, dir);
  EXPECT_EQ(r.exit_code, 3);
  EXPECT_EQ(line_count(r.err), 1u) << r.err;
  EXPECT_NE(r.err.find("broken.png"), std::string::npos);
  EXPECT_EQ(
      run_program("viscera", "texture --preset liver --sample " + at(dir, "missing.jpg") + out, dir)
          .exit_code,
      3);
  EXPECT_FALSE(std::filesystem::exists(dir / "x.png"));
  EXPECT_FALSE(std::filesystem::exists(dir / "x.png.partial"));
}

TEST(TextureCli, a_sample_image_gives_the_texture_its_colours) {
  const auto dir = testing::scratch_dir();
  ASSERT_EQ(
      run_program("viscera",
                  "texture --preset liver --size 32 --no-vessels -o " + at(dir, "sample.png"), dir)
          .exit_code,
      0);
  const auto r = run_program("viscera",
                             "texture --preset endometrium --size 64 --sample " +
                                 at(dir, "sample.png") + " -o " + at(dir, "out.png") + " --json",
                             dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["sample"], (dir / "sample.png").string());
}

TEST(BakeCli, bakes_a_preset_onto_the_ball_into_a_valid_package) {
  const auto dir = testing::scratch_dir();
  ASSERT_EQ(run_program("viscera",
                        "new --template ball --seed 2 --set radius=0.02 --set cell_size=0.008 -o " +
                            at(dir, "ball.vscene"),
                        dir)
                .exit_code,
            0);
  const auto r = run_program("viscera",
                             "bake " + at(dir, "ball.vscene") +
                                 " --preset peritoneum --size 128 --scale 0.03 -o " +
                                 at(dir, "baked.vscene") + " --json",
                             dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto json = nlohmann::json::parse(r.out);
  EXPECT_EQ(json["objects"][0]["mapping"], "lscm-atlas");
  EXPECT_LT(json["objects"][0]["l2_stretch"].get<double>(), 1.05);
  EXPECT_TRUE(std::filesystem::exists(dir / "baked.vscene/textures/ball-peritoneum_albedo.png"));
  EXPECT_EQ(run_program("viscera", "validate " + at(dir, "baked.vscene"), dir).exit_code, 0);
  EXPECT_EQ(
      run_program("viscera",
                  "bake " + at(dir, "ball.vscene") + " --preset spleen -o " + at(dir, "x.vscene"),
                  dir)
          .exit_code,
      2);
  EXPECT_FALSE(std::filesystem::exists(dir / "x.vscene"));
}

TEST(VesselsCli, grows_a_deterministic_tree_and_its_pipe_mesh_in_a_package_organ) {
  const auto dir = testing::scratch_dir();
  ASSERT_EQ(run_program("viscera",
                        "new --template ball --seed 2 --set radius=0.03 --set cell_size=0.01 -o " +
                            at(dir, "ball.vscene"),
                        dir)
                .exit_code,
            0);
  for (const char* name : {"a.json", "b.json"}) {
    const auto r =
        run_program("viscera",
                    "vessels --domain " + at(dir, "ball.vscene") + " --terminals 60 --seed 7 -o " +
                        at(dir, name) + " --mesh " + at(dir, "pipes.vtp"),
                    dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  EXPECT_EQ(viscera::testing::file_bytes(dir / "a.json"),
            viscera::testing::file_bytes(dir / "b.json"));
  const auto json = nlohmann::json::parse(viscera::testing::file_bytes(dir / "a.json"));
  EXPECT_EQ(json["summary"]["terminals"], 60);
  EXPECT_EQ(json["summary"]["intersections"], 0);
  EXPECT_LT(json["summary"]["murray_max_deviation"].get<double>(), 0.01);
  EXPECT_EQ(json["tree"]["host_object"], "ball");
  EXPECT_GT(std::filesystem::file_size(dir / "pipes.vtp"), 1000u);
}

TEST(VesselsCli, an_empty_label_map_exits_3_and_writes_nothing) {
  const auto dir = testing::scratch_dir();
  core::LabelMap labels;
  labels.image.dims = {8, 8, 8};
  labels.image.spacing = core::Vec3::Constant(1e-3);
  labels.image.scalar_type = core::ScalarType::UInt16;
  labels.image.allocate();
  core::write_label_map_vti(labels, dir / "empty.vti");
  const auto r = run_program("viscera",
                             "vessels --domain " + at(dir, "empty.vti") + " -o " +
                                 at(dir, "tree.json") + " --mesh " + at(dir, "tree.vtp"),
                             dir);
  EXPECT_EQ(r.exit_code, 3);
  EXPECT_EQ(line_count(r.err), 1u) << r.err;
  EXPECT_NE(r.err.find("empty.vti"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "tree.json"));
  EXPECT_FALSE(std::filesystem::exists(dir / "tree.vtp"));
}

TEST(VesselsCli, a_drawn_tree_whose_vessels_cross_is_written_and_exits_4) {
  const auto dir = testing::scratch_dir();
  // The second branch leaves the first and comes back across it.
  std::ofstream(dir / "crossing.json") << R"({"branches": [
      {"points": [[0,0,0],[0,0.03,0],[0,0.06,0]]},
      {"points": [[0,0,0],[0.02,0.01,0],[0.0,0.045,0.0005],[-0.02,0.05,0]], "parent": 0, "attach": 0.1}]})";
  const auto r = run_program("viscera",
                             "vessels --method splines --splines " + at(dir, "crossing.json") +
                                 " --root-radius 0.001 -o " + at(dir, "drawn.json"),
                             dir);
  EXPECT_EQ(r.exit_code, 4) << r.err;
  EXPECT_TRUE(std::filesystem::exists(dir / "drawn.json"));
  EXPECT_NE(r.err.find("intersects"), std::string::npos) << r.err;
  EXPECT_EQ(run_program("viscera",
                        "vessels --method lsystem --generations 6 -o " + at(dir, "ls.json"), dir)
                .exit_code,
            0);
  EXPECT_EQ(
      run_program("viscera", "vessels --method fractal -o " + at(dir, "f.json"), dir).exit_code, 2);
}

}  // namespace
}  // namespace viscera
