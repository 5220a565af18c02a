// Exported .gltf and .glb checked against the glTF 2.0 specification by the Khronos validator
// (npm gltf-validator, installed by dev.sh into the build folder). Without Node.js or the
// validator the test fails: a skipped spec check would hide broken exports in CI.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>

#include "exporters/scenario_exporter.h"
#include "tests/exporters/export_fixtures.h"
#include "tests/support/command_runner.h"
#include "tests/support/test_paths.h"

namespace viscera::exporters {
namespace {

namespace fs = std::filesystem;

nlohmann::json validate(const fs::path& file) {
  const fs::path modules = fs::path(VISCERA_BINARY_DIR) / "node" / "node_modules";
  if (std::system("command -v node >/dev/null 2>&1") != 0) {
    ADD_FAILURE() << "Node.js is missing: install the Debian package nodejs (dev.sh lists it)";
    return nullptr;
  }
  if (!fs::exists(modules / "gltf-validator" / "package.json")) {
    ADD_FAILURE() << "the Khronos glTF validator is missing from " << modules
                  << ": ./dev.sh test installs it (npm install --prefix build/node gltf-validator)";
    return nullptr;
  }
  const fs::path report = file.parent_path() / (file.filename().string() + ".report.json");
  const fs::path script = testing::source_dir() / "tests" / "exporters" / "validate_gltf.js";
  const std::string command = "NODE_PATH=" + testing::shell_quote(modules.string()) + " node " +
                              testing::shell_quote(script.string()) + " " +
                              testing::shell_quote(file.string()) + " > " +
                              testing::shell_quote(report.string());
  const int status = std::system(command.c_str());
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    ADD_FAILURE() << "the validator did not run on " << file;
    return nullptr;
  }
  return nlohmann::json::parse(testing::file_bytes(report));
}

class KhronosValidator : public ::testing::TestWithParam<ExportFormat> {};

TEST_P(KhronosValidator, finds_no_error_in_an_export_with_maps_colours_and_several_objects) {
  const auto file = testing::export_fixture(
      GetParam(), GetParam() == ExportFormat::Glb ? "patient.glb" : "patient.gltf");
  const nlohmann::json report = validate(file);
  ASSERT_FALSE(report.is_null());
  EXPECT_EQ(report.at("errors").get<int>(), 0) << report.at("messages").dump(1);
}

TEST_P(KhronosValidator, finds_no_error_after_non_finite_normals_and_uvs_were_sanitised) {
  core::Scenario scenario = testing::export_scenario_fixture();
  scenario.objects[0].surface.normals[5] = core::Vec3(std::nan(""), 1, 0);
  scenario.objects[0].surface.uvs[7].x() = -std::numeric_limits<double>::infinity();
  const auto file = testing::scratch_dir() /
                    (GetParam() == ExportFormat::Glb ? "sanitised.glb" : "sanitised.gltf");
  export_scenario(scenario, GetParam(), file, testing::export_textures_fixture());
  const nlohmann::json report = validate(file);
  ASSERT_FALSE(report.is_null());
  EXPECT_EQ(report.at("errors").get<int>(), 0) << report.at("messages").dump(1);
}

TEST(KhronosValidator, reports_errors_in_a_broken_file_so_a_pass_means_something) {
  const auto file = testing::scratch_dir() / "broken.gltf";
  std::ofstream(file) << R"({"asset": {"version": "2.0"}, "scene": 3, "scenes": [{"nodes": [7]}]})";
  const nlohmann::json report = validate(file);
  ASSERT_FALSE(report.is_null());
  EXPECT_GT(report.at("errors").get<int>(), 0);
}

INSTANTIATE_TEST_SUITE_P(Formats, KhronosValidator,
                         ::testing::Values(ExportFormat::Gltf, ExportFormat::Glb),
                         [](const auto& format) { return to_string(format.param); });

}  // namespace
}  // namespace viscera::exporters
