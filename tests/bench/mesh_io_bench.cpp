// Throughput of mesh export and import on a ~40k-tet package (the ball template at 5 mm cells:
// 38,515 tets, 20,480 visual triangles, 256×256 baked maps). Peers in the same run: the gmsh
// 4.8 library opening the same .msh, VTK's XML reader alone on the same .vtu, and assimp alone
// on the same STL — the difference is what our checks and conversions cost.
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <benchmark/benchmark.h>
#include <gmsh.h>
#include <vtkNew.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <assimp/Importer.hpp>
#include <filesystem>

#include "exporters/scenario_exporter.h"
#include "importers/mesh_reader.h"
#include "templates/template_catalog.h"
#include "textures/scenario_baking.h"

namespace {

namespace fs = std::filesystem;
using viscera::exporters::ExportFormat;

struct Patient {
  viscera::core::Scenario scenario;
  viscera::exporters::TextureFiles textures;
  fs::path dir;
};

const Patient& patient() {
  static const Patient built = [] {
    Patient p;
    p.scenario = viscera::templates::build_from_template("ball", {{"cell_size", "0.005"}}, 1);
    viscera::core::TextureSpec spec;
    spec.id = "skin";
    spec.preset = "endometrium";
    spec.width = spec.height = 256;
    p.scenario.textures[spec.id] = spec;
    p.scenario.objects[0].texture = spec.id;
    p.textures = viscera::textures::bake_textures_into(p.scenario, {}).files;
    p.dir = fs::temp_directory_path() / "viscera-bench-mesh-io";
    fs::create_directories(p.dir);
    return p;
  }();
  return built;
}

const std::pair<ExportFormat, const char*> kFormats[] = {
    {ExportFormat::Vtk, "p.vtm"}, {ExportFormat::Gltf, "p.gltf"}, {ExportFormat::Glb, "p.glb"},
    {ExportFormat::Obj, "p.obj"}, {ExportFormat::Stl, "p.stl"},   {ExportFormat::Ply, "p.ply"},
    {ExportFormat::Msh, "p.msh"}, {ExportFormat::Sofa, "p.scn"}};

fs::path exported(int index) {
  const auto& [format, name] = kFormats[index];
  const fs::path path = patient().dir / name;
  if (!fs::exists(path))
    viscera::exporters::export_scenario(patient().scenario, format, path, patient().textures);
  return path;
}

void counters(benchmark::State& state, double triangles, double tets) {
  state.counters["triangles_per_s"] =
      benchmark::Counter(triangles, benchmark::Counter::kIsIterationInvariantRate);
  if (tets > 0)
    state.counters["tets_per_s"] =
        benchmark::Counter(tets, benchmark::Counter::kIsIterationInvariantRate);
}

void BM_ExportScenario(benchmark::State& state) {
  const auto& [format, name] = kFormats[state.range(0)];
  const auto& p = patient();
  const fs::path out = p.dir / (std::string("export-") + name);
  viscera::exporters::ExportReport report;
  for (auto _ : state)
    report = viscera::exporters::export_scenario(p.scenario, format, out, p.textures);
  state.SetLabel(viscera::exporters::to_string(format));
  counters(state, static_cast<double>(report.triangles), static_cast<double>(report.tets));
}
BENCHMARK(BM_ExportScenario)->DenseRange(0, 7)->Unit(benchmark::kMillisecond);

void BM_ReadTetMesh(benchmark::State& state) {
  const fs::path path = state.range(0) == 0 ? exported(6) : patient().dir / "p" / "ball_body.vtu";
  if (state.range(0) == 1) exported(0);
  std::size_t tets = 0;
  for (auto _ : state)
    tets = viscera::importers::read_tet_mesh(path).tets.size();
  state.SetLabel(path.extension().string());
  counters(state, 0, static_cast<double>(tets));
}
BENCHMARK(BM_ReadTetMesh)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

void BM_GmshLibraryOpen(benchmark::State& state) {
  const fs::path path = exported(6);
  gmsh::initialize();
  gmsh::option::setNumber("General.Terminal", 0);
  std::size_t tets = 0;
  for (auto _ : state) {
    gmsh::clear();
    gmsh::open(path.string());
    std::vector<std::size_t> tags, nodes;
    gmsh::model::mesh::getElementsByType(4, tags, nodes);
    tets = tags.size();
  }
  gmsh::finalize();
  counters(state, 0, static_cast<double>(tets));
}
BENCHMARK(BM_GmshLibraryOpen)->Unit(benchmark::kMillisecond);

void BM_VtkXmlReaderAlone(benchmark::State& state) {
  exported(0);
  const fs::path path = patient().dir / "p" / "ball_body.vtu";
  vtkIdType cells = 0;
  for (auto _ : state) {
    vtkNew<vtkXMLUnstructuredGridReader> reader;
    reader->SetFileName(path.string().c_str());
    reader->Update();
    cells = reader->GetOutput()->GetNumberOfCells();
  }
  counters(state, 0, static_cast<double>(cells));
}
BENCHMARK(BM_VtkXmlReaderAlone)->Unit(benchmark::kMillisecond);

void BM_ReadMesh(benchmark::State& state) {
  const fs::path path = exported(static_cast<int>(state.range(0)));
  std::size_t triangles = 0;
  for (auto _ : state)
    triangles = viscera::importers::read_mesh(path).triangles.size();
  state.SetLabel(path.extension().string());
  counters(state, static_cast<double>(triangles), 0);
}
// glTF, GLB, OBJ, STL, PLY: every check of mesh_integrity.h included.
BENCHMARK(BM_ReadMesh)->Arg(1)->Arg(2)->Arg(3)->Arg(4)->Arg(5)->Unit(benchmark::kMillisecond);

void BM_AssimpAloneStl(benchmark::State& state) {
  const fs::path path = exported(4);
  unsigned faces = 0;
  for (auto _ : state) {
    Assimp::Importer importer;
    const aiScene* scene =
        importer.ReadFile(path.string(), aiProcess_Triangulate | aiProcess_JoinIdenticalVertices);
    faces = scene->mMeshes[0]->mNumFaces;
  }
  counters(state, static_cast<double>(faces), 0);
}
BENCHMARK(BM_AssimpAloneStl)->Unit(benchmark::kMillisecond);

}  // namespace
