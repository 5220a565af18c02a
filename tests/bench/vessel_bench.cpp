// Vessel trees and texture mapping (docs/performance.md, "Textures and vessels"): CCO growth to
// 1,000 terminals in a 4 cm ball (target ≤ 2 s), its pipe mesh, and an LSCM atlas plus a baked
// preset on the ball's surface.

#include <benchmark/benchmark.h>

#include "core/primitives/icosphere.h"
#include "templates/vessels/cco_vessel_generator.h"
#include "templates/vessels/vessel_pipe_mesh.h"
#include "textures/solid_texture.h"
#include "textures/surface_projector.h"
#include "textures/texture_baker.h"
#include "textures/texture_preset.h"
#include "textures/uv_atlas.h"

namespace {

using namespace viscera;

const templates::SurfaceMeshDomain& ball_domain() {
  static const templates::SurfaceMeshDomain domain(core::make_icosphere(0.04, 4));
  return domain;
}

// range(0) terminals.
void BM_CcoVesselTree(benchmark::State& state) {
  templates::CcoOptions options;
  options.terminals = static_cast<int>(state.range(0));
  options.seed = 1;
  std::size_t segments = 0;
  for (auto _ : state) {
    const auto tree = templates::grow_cco_tree(ball_domain(), options);
    segments = tree.segments.size();
    benchmark::DoNotOptimize(segments);
  }
  state.counters["segments"] = static_cast<double>(segments);
}
BENCHMARK(BM_CcoVesselTree)->Arg(250)->Arg(1000)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_VesselPipeMesh(benchmark::State& state) {
  templates::CcoOptions options;
  options.terminals = 1000;
  const auto tree = templates::grow_cco_tree(ball_domain(), options);
  std::size_t triangles = 0;
  for (auto _ : state) {
    triangles = templates::vessel_pipe_mesh(tree).triangles.size();
    benchmark::DoNotOptimize(triangles);
  }
  state.counters["triangles"] = static_cast<double>(triangles);
}
BENCHMARK(BM_VesselPipeMesh)->Unit(benchmark::kMillisecond)->UseRealTime();

// LSCM atlas of an icosphere with range(0) subdivisions (5: 20,480 triangles).
void BM_UvAtlas(benchmark::State& state) {
  const auto sphere = core::make_icosphere(0.04, static_cast<int>(state.range(0)));
  for (auto _ : state) {
    const auto atlas = textures::build_uv_atlas(sphere);
    benchmark::DoNotOptimize(atlas.mesh.uvs.data());
  }
  state.counters["triangles"] = static_cast<double>(sphere.triangles.size());
}
BENCHMARK(BM_UvAtlas)->Arg(4)->Arg(5)->Unit(benchmark::kMillisecond)->UseRealTime();

// Baking the myoma-surface preset (solid texture with surface vessels) into a 1024² atlas.
void BM_BakeBall1024(benchmark::State& state) {
  const auto atlas = textures::build_uv_atlas(core::make_icosphere(0.04, 4), {1024, 4});
  const auto& preset = textures::find_texture_preset("myoma-surface");
  const textures::SurfaceProjector surface(atlas.mesh);
  const textures::SolidTissueTexture solid(
      preset, 1, 0.04, nullptr, textures::grow_surface_vessels(preset, surface, 0.04, 1));
  for (auto _ : state) {
    const auto maps = textures::bake_surface_texture(atlas.mesh, solid, {1024, 1024, 4, 0});
    benchmark::DoNotOptimize(maps.albedo.pixels.data());
  }
}
BENCHMARK(BM_BakeBall1024)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
