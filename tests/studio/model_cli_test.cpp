// The modelling kernel's "Done when" from the command line (issue 4): a ball, a flat sheet and
// a branching pipe are created, edited by control point, layered into bodies and connected,
// with a material fitted from a CSV, stored in and read back from the asset library, and
// written into a package that `viscera validate` accepts and `viscera-sim` simulates.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "tests/support/command_runner.h"
#include "tests/support/test_paths.h"

namespace viscera {
namespace {

namespace fs = std::filesystem;
using testing::run_program;
using testing::shell_quote;

/// Runs `viscera <arguments>` in `dir` and expects success; returns standard output.
std::string viscera_ok(const std::string& arguments, const fs::path& dir) {
  const auto result = run_program("viscera", arguments, dir);
  EXPECT_EQ(result.exit_code, 0) << "viscera " << arguments << "\n" << result.err;
  return result.out;
}

nlohmann::json viscera_json(const std::string& arguments, const fs::path& dir) {
  const std::string out = viscera_ok(arguments + " --json", dir);
  try {
    return nlohmann::json::parse(out);
  } catch (const nlohmann::json::exception&) {
    ADD_FAILURE() << "viscera " << arguments << " printed no JSON: " << out;
    return nlohmann::json::object();
  }
}

std::string point_text(double x, double y, double z) {
  char text[128];
  std::snprintf(text, sizeof text, "%.17g,%.17g,%.17g", x, y, z);
  return text;
}

/// σ = c1 ε + c2 ε² + c3 ε³ sampled on [0, 0.3] in kPa with a header, as a lab exports it.
void write_measured_curve(const fs::path& path) {
  std::ofstream csv(path);
  csv << "# synthetic uniaxial test\nstrain,stress [kPa]\n";
  for (int i = 0; i <= 30; ++i) {
    const double e = 0.01 * i;
    csv << e << "," << (20.0e3 * e + 40.0e3 * e * e + 300.0e3 * e * e * e) / 1000.0 << "\n";
  }
}

TEST(ModelCommand, ball_flat_and_branching_pipe_become_a_package_the_simulator_runs) {
  const fs::path dir = testing::scratch_dir();
  fs::current_path(dir);  // the programs run where the test runs; relative names are in dir
  const std::string lib = " --library " + shell_quote((dir / "lib.sqlite").string());

  // Material fitted from a measured curve: the known coefficients come back.
  write_measured_curve(dir / "curve.csv");
  auto fit =
      viscera_json("material fit curve.csv --id test-tissue --base myometrium -o tissue.json", dir);
  ASSERT_TRUE(fit.contains("fit"));
  EXPECT_NEAR(fit["fit"]["cubic"][1].get<double>(), 20.0e3, 1.0);
  EXPECT_NEAR(fit["fit"]["cubic"][2].get<double>(), 40.0e3, 5.0);
  EXPECT_NEAR(fit["fit"]["cubic"][3].get<double>(), 300.0e3, 20.0);
  EXPECT_LT(fit["fit"]["rms_error"].get<double>(), 1.0);  // Pa, on stresses up to 17 kPa
  EXPECT_GT(fit["distance_stiffness"].get<double>(), 0.0);
  // In the library it gets a plot of its curve as thumbnail.
  EXPECT_TRUE(viscera_json("library add tissue.json --tags measured" + lib, dir)["thumbnail"]);

  // The three object types.
  viscera_ok(
      "model new ball --id ball --center 0,0,0.03 --radius 0.02 --subdivisions 2 -o ball.json",
      dir);
  viscera_ok(
      "model new flat --id sheet --origin=-0.04,-0.04,0 --u-edge 0.08,0,0 --v-edge 0,0.08,0 "
      "--rows 4 --cols 4 --open --steps 4 -o sheet.json",
      dir);
  viscera_ok(
      "model new pipe --id vessel --role vessel --point 0.05,-0.03,0.02 --point 0.05,0,0.02 "
      "--point 0.05,0.03,0.02 --radius 0.006 --ring-segments 8 -o pipe.json",
      dir);
  viscera_ok("model branch pipe.json --parent 0 --attach 0.5 --point 0.08,0,0.03 --radius 0.004",
             dir);
  EXPECT_EQ(viscera_json("model points pipe.json", dir)["points"].size(), 4u);

  // Editing by control point: a ball point pushed outward grows the ball's volume and is
  // where it was put.
  const auto before = viscera_json("model mesh ball.json -o before.vtp", dir);
  const auto points = viscera_json("model points ball.json", dir)["points"];
  ASSERT_EQ(points.size(), 12u);
  const double px = points[0][0], py = points[0][1], pz = points[0][2];
  const double dx = px, dy = py, dz = pz - 0.03;  // outward from the centre, length 0.02
  const std::string moved = point_text(px + 0.3 * dx, py + 0.3 * dy, pz + 0.3 * dz);
  viscera_ok("model move-point ball.json --point 0 --to=" + moved, dir);
  const auto moved_points = viscera_json("model points ball.json", dir)["points"];
  EXPECT_NEAR(moved_points[0][0].get<double>(), px + 0.3 * dx, 1e-12);
  EXPECT_NEAR(moved_points[0][2].get<double>(), pz + 0.3 * dz, 1e-12);
  const auto after = viscera_json("model mesh ball.json -o after.vtp", dir);
  EXPECT_TRUE(after["closed"].get<bool>());
  EXPECT_GT(after["volume"].get<double>(), before["volume"].get<double>() * 1.01);
  // The sheet's middle control point lifted 4 mm.
  viscera_ok("model move-point sheet.json --point 5 --to=-0.0133333,-0.0133333,0.004", dir);

  // Layers into bodies: a gmsh shell for the ball, KisMo's springs for the sheet and the pipe.
  viscera_ok("model layer ball.json --layers 1 --thickness 0.006", dir);
  viscera_ok("model layer sheet.json --layers 1 --thickness 0.003 --body mass-spring", dir);
  viscera_ok("model layer pipe.json --layers 1 --thickness 0.002 --body mass-spring", dir);
  const auto sheet_mesh = viscera_json("model mesh sheet.json -o sheet.vtp --body sheet.vtu", dir);
  EXPECT_EQ(sheet_mesh["body"], "mass-spring");
  EXPECT_GT(sheet_mesh["body_tets"].get<int>(), 0);

  // Materials: fitted (through the library), shipped, and a shipped one written to a file.
  viscera_ok("model material ball.json --from-library test-tissue" + lib, dir);
  viscera_ok("model material sheet.json --shipped myometrium", dir);
  viscera_ok("material get vein -o vein.json", dir);
  viscera_ok("model material pipe.json --file vein.json", dir);
  viscera_ok("model fix sheet.json --center=-0.04,-0.04,0 --radius 0.015", dir);
  viscera_ok("model fix sheet.json --center 0.04,0.04,0 --radius 0.015", dir);
  viscera_ok("model fix sheet.json --center=-0.04,0.04,0 --radius 0.015", dir);
  viscera_ok("model fix sheet.json --center=0.04,-0.04,0 --radius 0.015", dir);
  viscera_ok("model fix pipe.json --center 0.05,-0.03,0.02 --radius 0.008", dir);
  viscera_ok("model fix pipe.json --center 0.05,0.03,0.02 --radius 0.008", dir);
  viscera_ok("model fix pipe.json --center 0.08,0,0.03 --radius 0.006", dir);  // the branch's end
  viscera_ok("model fix ball.json --center 0,0,0.05 --radius 0.008", dir);

  // Connected at the nearest knots, in one organ group.
  const auto connected =
      viscera_json("model connect ball.json sheet.json --distance 0.012 --group pelvis", dir);
  EXPECT_GT(connected["node_pairs"].get<int>(), 0);
  const auto too_far =
      run_program("viscera", "model connect ball.json pipe.json --distance 0.001", dir);
  EXPECT_EQ(too_far.exit_code, 4) << too_far.err;  // no knots that close: validation failed

  // The ball model goes into the library and comes back byte for byte.
  viscera_ok("library add ball.json --tags organ" + lib, dir);
  viscera_ok("library get ball -o ball-from-library.json --thumbnail ball.png" + lib, dir);
  const std::string png =
      viscera::testing::file_bytes(dir / "ball.png");  // rendered when the model was added
  ASSERT_GT(png.size(), 24u);
  EXPECT_EQ(png.substr(1, 3), "PNG");
  EXPECT_EQ(static_cast<unsigned char>(png[19]), 128u);  // IHDR width, big-endian
  EXPECT_EQ(viscera::testing::file_bytes(dir / "ball-from-library.json"),
            viscera::testing::file_bytes(dir / "ball.json"));

  const auto package = viscera_json(
      "model package ball-from-library.json sheet.json pipe.json --name pelvis -o scene.vscene",
      dir);
  ASSERT_EQ(package["objects"].size(), 3u);
  EXPECT_EQ(package["objects"][0]["body"], "tet-mesh");
  EXPECT_EQ(package["objects"][1]["body"], "mass-spring");
  EXPECT_EQ(package["objects"][2]["body"], "mass-spring");
  for (const auto& object : package["objects"]) {
    EXPECT_TRUE(object["closed"].get<bool>() || object["id"] == "sheet") << object["id"];
    EXPECT_GT(object["body_volume"].get<double>(), 0.0) << object["id"];
  }
  ASSERT_EQ(package["connections"].size(), 1u);
  EXPECT_EQ(package["connections"][0]["node_pairs"], connected["node_pairs"]);
  EXPECT_EQ(package["groups"]["pelvis"], (nlohmann::json{"ball", "sheet"}));

  EXPECT_EQ(run_program("viscera", "validate scene.vscene", dir).exit_code, 0);
  const auto run =
      run_program("viscera-sim", "run scene.vscene --headless --duration 0.5 --json", dir);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto report = nlohmann::json::parse(run.out);
  EXPECT_NEAR(report["simulated_time"].get<double>(), 0.5, 1e-6);
  ASSERT_EQ(report["bodies"].size(), 3u);
  const double displacement = report["max_displacement"].get<double>();
  EXPECT_TRUE(std::isfinite(displacement));
  // Held in place, nothing falls: a free fall would drop 1.2 m in 0.5 s.
  EXPECT_LT(displacement, 0.05);
  for (const auto& value : report["energy"]["total"])
    EXPECT_TRUE(std::isfinite(value.get<double>()));
}

TEST(ModelCommand, every_new_command_has_help_and_a_package_is_the_same_bytes_twice) {
  const fs::path dir = testing::scratch_dir();
  fs::current_path(dir);
  for (const char* command :
       {"model", "model new", "model move-point", "model branch", "model layer", "model connect",
        "model package", "material fit", "library", "library add", "library get"}) {
    const auto result = run_program("viscera", std::string(command) + " --help", dir);
    EXPECT_EQ(result.exit_code, 0) << command;
    EXPECT_NE(result.out.find("Usage"), std::string::npos) << command;
  }
  viscera_ok("model new ball --id b --radius 0.02 --subdivisions 2 -o b.json", dir);
  viscera_ok("model layer b.json --layers 2 --thickness 0.004 --mode scale", dir);
  viscera_ok("model package b.json -o one.vscene", dir);
  viscera_ok("model package b.json -o two.vscene", dir);
  for (const char* file : {"manifest.json", "objects/b/surface.vtp", "objects/b/body.vtu"})
    EXPECT_EQ(viscera::testing::file_bytes(dir / "one.vscene" / file),
              viscera::testing::file_bytes(dir / "two.vscene" / file))
        << file;
}

TEST(ModelCommand, bad_edits_have_typed_exit_codes_and_leave_the_model_alone) {
  const fs::path dir = testing::scratch_dir();
  fs::current_path(dir);  // the programs run where the test runs; relative names are in dir
  viscera_ok("model new ball --id b --radius 0.02 -o b.json", dir);
  const std::string original = viscera::testing::file_bytes(dir / "b.json");
  EXPECT_EQ(run_program("viscera", "model move-point b.json --point 12 --to 0,0,0", dir).exit_code,
            2);
  EXPECT_EQ(run_program("viscera", "model move-point b.json --point 0 --to 0,0", dir).exit_code, 2);
  EXPECT_EQ(
      run_program("viscera", "model branch b.json --point 0,0,1 --radius 0.01", dir).exit_code, 2);
  EXPECT_EQ(
      run_program("viscera", "model new ball --origin 0,0,0 --radius 1 -o x.json", dir).exit_code,
      2);
  EXPECT_EQ(viscera::testing::file_bytes(dir / "b.json"), original);
  EXPECT_FALSE(fs::exists(dir / "x.json"));
  std::ofstream(dir / "broken.json") << R"({"format": "viscera-model", "version": 1, "id": "x",
    "primitive": {"type": "ball", "center": [0, 0], "radius": 0.01}})";
  const auto broken = run_program("viscera", "model points broken.json", dir);
  EXPECT_EQ(broken.exit_code, 3);
  EXPECT_NE(broken.err.find("broken.json: /primitive/center"), std::string::npos) << broken.err;
  const auto missing = run_program("viscera", "material fit nothing.csv -o m.json", dir);
  EXPECT_EQ(missing.exit_code, 3);
  EXPECT_FALSE(fs::exists(dir / "m.json"));
}

}  // namespace
}  // namespace viscera
