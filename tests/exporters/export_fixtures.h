#pragma once
/// Scenarios and real files shared by the export and import tests.

#include <filesystem>
#include <string>
#include <vector>

#include "core/scenario/scenario.h"
#include "exporters/scenario_exporter.h"
#include "tests/support/test_paths.h"

namespace viscera::testing {

/// A small patient with every kind of object an export meets: "ball" (tet body from the ball
/// template, fixed base, baked 64×64 texture maps on an LSCM atlas), "twin" (the same ball
/// moved 6 cm along x as a KisMo mass-spring body, vertex colours, a connection to "ball"),
/// and "plate" (a surface without body). Built once per test program.
const core::Scenario& export_scenario_fixture();
/// The baked maps of export_scenario_fixture() (package path → PNG bytes).
const exporters::TextureFiles& export_textures_fixture();

/// Exports the fixture (with its maps) into a fresh file `name` of the running test's scratch
/// folder and returns the path written.
std::filesystem::path export_fixture(exporters::ExportFormat format, const std::string& name,
                                     const exporters::ExportOptions& options = {});

/// A mesh from CGAL's data (Debian libcgal-demo: /usr/share/doc/libcgal-dev/data.tar.gz),
/// extracted once into the test temp folder, e.g. cgal_mesh("elephant.off"). Fails the test
/// (ADD_FAILURE) naming the package when it is not installed.
std::filesystem::path cgal_mesh(const std::string& name);

/// Every mesh of CGAL's data/meshes whose name ends with `extension` (".off", ".ply"), extracted
/// once like cgal_mesh(), sorted by name.
std::vector<std::filesystem::path> cgal_meshes_ending(const std::string& extension);

/// A model of assimp's test set (Debian assimp-testmodels: /usr/share/assimp/models), e.g.
/// assimp_model("glTF2/BoxTextured-glTF/BoxTextured.gltf").
std::filesystem::path assimp_model(const std::string& relative);

/// A gmsh tutorial (Debian gmsh-doc) meshed by the gmsh program with `arguments` (e.g.
/// "-3 -format msh41 -bin"), written once into the test temp folder as `name`.
std::filesystem::path gmsh_tutorial_mesh(const std::string& tutorial, const std::string& arguments,
                                         const std::string& name);

/// A folder shared by the test processes of this build for data made once (real files unpacked
/// or meshed, packages built through the CLI): VISCERA_TEST_TMP/real-files.
std::filesystem::path shared_test_folder();

/// True when the message of `thrown` contains every one of `parts`.
bool message_has(const std::string& message, std::initializer_list<std::string> parts);

/// What importers::read_mesh says of `path`: the InputError's message, or "no error".
std::string mesh_read_error(const std::filesystem::path& path);

}  // namespace viscera::testing
