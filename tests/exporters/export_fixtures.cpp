#include "tests/exporters/export_fixtures.h"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "core/error.h"
#include "core/primitives/icosphere.h"
#include "importers/mesh_reader.h"
#include "templates/template_catalog.h"
#include "tests/support/command_runner.h"
#include "tests/support/test_paths.h"
#include "textures/scenario_baking.h"

namespace viscera::testing {
namespace {

namespace fs = std::filesystem;

struct Fixture {
  core::Scenario scenario;
  exporters::TextureFiles textures;
};

const Fixture& fixture() {
  static const Fixture built = [] {
    Fixture f;
    f.scenario =
        templates::build_from_template("ball", {{"radius", "0.02"}, {"cell_size", "0.008"}}, 3);
    core::TextureSpec spec;
    spec.id = "ball-skin";
    spec.preset = "endometrium";
    spec.seed = 4;
    spec.width = spec.height = 64;
    f.scenario.textures[spec.id] = spec;
    f.scenario.objects[0].texture = spec.id;
    f.textures = textures::bake_textures_into(f.scenario, {.texture_scale = 0.03}).files;

    core::SceneObject twin = f.scenario.objects[0];
    twin.id = "twin";
    twin.name = "twin";
    twin.texture.clear();
    twin.body_kind = core::BodyKind::MassSpring;
    const core::Vec3 shift(0.06, 0.0, 0.0);
    for (auto& p : twin.surface.vertices)
      p += shift;
    for (auto& p : twin.body.nodes)
      p += shift;
    auto& r = twin.surface.vertex_attributes["albedo_r"];
    auto& g = twin.surface.vertex_attributes["albedo_g"];
    auto& b = twin.surface.vertex_attributes["albedo_b"];
    for (const auto& p : twin.surface.vertices) {
      r.push_back(0.5 + 5.0 * (p.x() - shift.x()));
      g.push_back(0.3);
      b.push_back(0.2);
    }
    twin.surface.vertex_attributes.erase("seam_vertex");
    f.scenario.objects.push_back(twin);

    core::SceneObject plate;
    plate.id = "plate";
    plate.name = "plate";
    plate.role = core::ObjectRole::Fixture;
    plate.surface = core::make_icosphere(0.01, 1);
    for (auto& p : plate.surface.vertices)
      p += core::Vec3(0.0, 0.06, 0.0);
    f.scenario.objects.push_back(plate);

    core::Connection connection;
    connection.id = "ball-twin";
    connection.object_a = "ball";
    connection.object_b = "twin";
    connection.node_pairs = {{0, 0}, {1, 1}};
    connection.stiffness = 250.0;
    f.scenario.connections.push_back(connection);
    return f;
  }();
  return built;
}

/// Runs a shell command in `dir`; returns its exit code and puts its standard error in `err`.
int run_shell(const std::string& command, const fs::path& dir, std::string& err) {
  const fs::path err_path = dir / (".stderr-" + std::to_string(getpid()));
  const int status =
      std::system((command + " 2>" + shell_quote(err_path.string()) + " </dev/null").c_str());
  err = file_bytes(err_path);
  fs::remove(err_path);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

/// A name no other test process uses at the same time (tests run in parallel processes).
std::string private_name(const std::string& base) {
  return "." + base + "-" + std::to_string(getpid());
}

}  // namespace

fs::path shared_test_folder() {
  const char* root = std::getenv("VISCERA_TEST_TMP");
  fs::path dir =
      fs::path(root != nullptr ? root : fs::temp_directory_path().string()) / "real-files";
  fs::create_directories(dir);
  return dir;
}

const core::Scenario& export_scenario_fixture() {
  return fixture().scenario;
}
const exporters::TextureFiles& export_textures_fixture() {
  return fixture().textures;
}

fs::path export_fixture(exporters::ExportFormat format, const std::string& name,
                        const exporters::ExportOptions& options) {
  const fs::path out = scratch_dir() / name;
  exporters::export_scenario(export_scenario_fixture(), format, out, export_textures_fixture(),
                             options);
  return out;
}

fs::path cgal_mesh(const std::string& name) {
  const fs::path archive = "/usr/share/doc/libcgal-dev/data.tar.gz";
  if (!fs::exists(archive)) {
    ADD_FAILURE() << archive
                  << " is missing: install the Debian package libcgal-demo (dev.sh lists it)";
    return {};
  }
  const fs::path dir = shared_test_folder() / "cgal";
  const fs::path path = dir / "data" / "meshes" / name;
  if (!fs::exists(path)) {
    const fs::path staging = dir / private_name("extract");
    fs::create_directories(staging);
    fs::create_directories(path.parent_path());
    std::string err;
    const int code =
        run_shell("tar -xzf " + shell_quote(archive.string()) + " -C " +
                      shell_quote(staging.string()) + " " + shell_quote("data/meshes/" + name),
                  dir, err);
    EXPECT_EQ(code, 0) << err;
    if (code == 0) fs::rename(staging / "data" / "meshes" / name, path);
    fs::remove_all(staging);
  }
  return path;
}

std::vector<fs::path> cgal_meshes_ending(const std::string& extension) {
  const fs::path dir = shared_test_folder() / "cgal";
  const fs::path meshes = dir / "data" / "meshes";
  const fs::path done = dir / ("all" + extension);
  if (!fs::exists(done)) {
    const fs::path staging = dir / private_name("extract");
    fs::create_directories(staging);
    fs::create_directories(meshes);
    std::string err;
    const int code = run_shell("tar -xzf /usr/share/doc/libcgal-dev/data.tar.gz -C " +
                                   shell_quote(staging.string()) + " --wildcards " +
                                   shell_quote("data/meshes/*" + extension),
                               dir, err);
    EXPECT_EQ(code, 0) << err << " (the Debian package libcgal-demo has the archive)";
    std::error_code none;  // nothing extracted: the EXPECT above reports it
    for (const auto& entry : fs::directory_iterator(staging / "data" / "meshes", none))
      if (!fs::exists(meshes / entry.path().filename()))
        fs::rename(entry.path(), meshes / entry.path().filename());
    fs::remove_all(staging);
    if (code == 0) std::ofstream(done).close();
  }
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(meshes))
    if (entry.path().string().ends_with(extension)) files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

fs::path assimp_model(const std::string& relative) {
  const fs::path path = fs::path("/usr/share/assimp/models") / relative;
  if (!fs::exists(path))
    ADD_FAILURE() << path
                  << " is missing: install the Debian package assimp-testmodels (dev.sh lists it)";
  return path;
}

fs::path gmsh_tutorial_mesh(const std::string& tutorial, const std::string& arguments,
                            const std::string& name) {
  const fs::path docs = "/usr/share/doc/gmsh-doc/doc/gmsh/tutorial";
  const fs::path dir = shared_test_folder() / "gmsh";
  fs::create_directories(dir);
  const fs::path out = dir / name;
  if (fs::exists(out)) return out;
  if (!fs::exists(docs / (tutorial + ".geo")) && !fs::exists(docs / (tutorial + ".geo.gz"))) {
    ADD_FAILURE() << docs / tutorial
                  << ".geo is missing: install the Debian package gmsh-doc (dev.sh lists it)";
    return {};
  }
  // The tutorials include each other ("t3.geo" includes "t1.geo"): unpack them all, under their
  // own names, into a folder of this process.
  const fs::path work = dir / private_name("tutorials");
  fs::create_directories(work);
  std::string err;
  EXPECT_EQ(
      run_shell("cp " + shell_quote(docs.string()) + "/t*.geo* " + shell_quote(work.string()) +
                    " && gzip -df " + shell_quote(work.string()) + "/*.gz",
                dir, err),
      0)
      << err;
  // gmsh writes the file itself; a private name keeps a half-written mesh from being reused.
  const fs::path staged = work / name;
  const int code =
      run_shell("cd " + shell_quote(work.string()) + " && gmsh " + tutorial + ".geo " + arguments +
                    " -o " + shell_quote(staged.string()) + " -v 1 >/dev/null",
                dir, err);
  EXPECT_EQ(code, 0) << "gmsh (Debian package gmsh) failed: " << err;
  if (code == 0) fs::rename(staged, out);
  fs::remove_all(work);
  return out;
}

bool message_has(const std::string& message, std::initializer_list<std::string> parts) {
  for (const auto& part : parts) {
    if (message.find(part) == std::string::npos) return false;
  }
  return true;
}

std::string mesh_read_error(const std::filesystem::path& path) {
  try {
    importers::read_mesh(path);
  } catch (const core::InputError& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace viscera::testing
