// Label map → simulation mesh (issue 3 §9). Two inputs, both generated here:
// - a 256³ synthetic label volume (1 mm voxels: a spheroid, a sphere inside it, a torus beside),
//   through the surface pipeline (voxels/s) and through Mesh_3 (tets/s);
// - an organ-like 440×350×165 map (0.7×0.7×1.5 mm voxels: a lobed body with a nested lesion)
//   through the whole pipeline to ~180k tets: visual surface, tets, embedding, quality report.
// Peer in the same run: CGAL Mesh_3 alone, sequential, on the organ map (the step that dominates).
#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>

#include "importers/meshing/label_body.h"
#include "importers/meshing/label_surface.h"
#include "importers/meshing/label_tet_mesher.h"

namespace {

using viscera::core::LabelMap;
using viscera::core::Vec3;

LabelMap empty_map(std::array<int, 3> dims, const Vec3& spacing) {
  LabelMap map;
  map.image.scalar_type = viscera::core::ScalarType::UInt16;
  map.image.dims = dims;
  map.image.spacing = spacing;
  map.image.origin = Vec3(-0.1, 0.05, 0.2);
  map.image.allocate();
  return map;
}

const LabelMap& synthetic_256() {
  static const LabelMap map = [] {
    LabelMap m = empty_map({256, 256, 256}, Vec3::Constant(0.001));
    for (int k = 0; k < 256; ++k)
      for (int j = 0; j < 256; ++j)
        for (int i = 0; i < 256; ++i) {
          const Vec3 p(i - 100.0, j - 128.0, k - 128.0);
          int label = 0;
          if (std::pow(p.x() / 80, 2) + std::pow(p.y() / 60, 2) + std::pow(p.z() / 100, 2) <= 1)
            label = p.norm() <= 30.0 ? 2 : 1;
          const Vec3 q(i - 215.0, j - 128.0, k - 128.0);
          const double ring = std::hypot(q.y(), q.z()) - 60.0;
          if (ring * ring + q.x() * q.x() <= 18.0 * 18.0) label = 3;
          m.set_label(m.image.linear_index(i, j, k), static_cast<std::uint16_t>(label));
        }
    return m;
  }();
  return map;
}

/// A lobed organ (radius modulated by low spherical harmonics) with a lesion of label 2.
const LabelMap& organ_map() {
  static const LabelMap map = [] {
    const std::array<int, 3> dims{440, 350, 165};
    const Vec3 spacing(0.0007, 0.0007, 0.0015);
    LabelMap m = empty_map(dims, spacing);
    const Vec3 centre = 0.5 * spacing.cwiseProduct(Vec3(dims[0] - 1, dims[1] - 1, dims[2] - 1));
    const Vec3 axes(0.11, 0.085, 0.095);
    const Vec3 lesion = centre + Vec3(0.03, -0.02, 0.01);
    for (int k = 0; k < dims[2]; ++k)
      for (int j = 0; j < dims[1]; ++j)
        for (int i = 0; i < dims[0]; ++i) {
          const Vec3 p = spacing.cwiseProduct(Vec3(i, j, k));
          const Vec3 q = (p - centre).cwiseQuotient(axes);
          const double r = q.norm();
          const double theta = std::acos(std::clamp(q.z() / std::max(r, 1e-12), -1.0, 1.0));
          const double phi = std::atan2(q.y(), q.x());
          const double bound =
              1.0 + 0.12 * std::sin(3 * theta) * std::cos(2 * phi) + 0.06 * std::cos(4 * phi);
          int label = r <= bound ? 1 : 0;
          if (label && (p - lesion).norm() <= 0.025) label = 2;
          m.set_label(m.image.linear_index(i, j, k), static_cast<std::uint16_t>(label));
        }
    return m;
  }();
  return map;
}

void BM_LabelSurface256(benchmark::State& state) {
  const LabelMap& map = synthetic_256();
  viscera::importers::LabelSurfaceOptions options;
  options.target_triangles = 50000;
  std::size_t triangles = 0;
  for (auto _ : state) {
    const auto surface = viscera::importers::label_surface(map, 0, options, "synthetic");
    triangles = surface.mesh.triangles.size();
  }
  state.counters["voxels/s"] = benchmark::Counter(static_cast<double>(map.image.voxel_count()),
                                                  benchmark::Counter::kIsIterationInvariantRate);
  state.counters["triangles"] = static_cast<double>(triangles);
}
BENCHMARK(BM_LabelSurface256)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);

void BM_LabelTets256(benchmark::State& state) {
  const LabelMap& map = synthetic_256();
  viscera::importers::LabelTetMeshingOptions options;
  options.target_tets = 150000;
  options.threads = static_cast<int>(state.range(0));
  std::size_t tets = 0;
  for (auto _ : state)
    tets = viscera::importers::mesh_label_map(map, options, "synthetic").tets.size();
  state.counters["tets"] = static_cast<double>(tets);
  state.counters["tets/s"] =
      benchmark::Counter(static_cast<double>(tets), benchmark::Counter::kIsIterationInvariantRate);
  state.counters["voxels/s"] = benchmark::Counter(static_cast<double>(map.image.voxel_count()),
                                                  benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_LabelTets256)
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(3);

/// The whole pipeline on the organ map; Arg = Mesh_3 threads.
void BM_OrganToSimReadyMesh(benchmark::State& state) {
  const LabelMap& map = organ_map();
  viscera::importers::LabelBodyOptions options;
  options.tets.target_tets = 180000;
  options.tets.threads = static_cast<int>(state.range(0));
  options.surface.target_triangles = 50000;
  viscera::importers::LabelBody made;
  for (auto _ : state)
    made = viscera::importers::mesh_label_body(map, options, "organ");
  state.counters["tets"] = static_cast<double>(made.body.tets.size());
  state.counters["tets/s"] = benchmark::Counter(static_cast<double>(made.body.tets.size()),
                                                benchmark::Counter::kIsIterationInvariantRate);
  state.counters["inverted"] = static_cast<double>(made.quality.inverted);
  state.counters["min_dihedral"] = made.quality.min_dihedral_degrees;
  for (const auto& [stage, seconds] : made.seconds)
    state.counters[stage + "_s"] = seconds;
}
BENCHMARK(BM_OrganToSimReadyMesh)
    ->Arg(2)
    ->Arg(1)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(3);

/// Peer: Mesh_3 alone, sequential, same criteria as the pipeline.
void BM_OrganMesh3AloneSequential(benchmark::State& state) {
  const LabelMap& map = organ_map();
  viscera::importers::LabelTetMeshingOptions options;
  options.target_tets = 180000;
  std::size_t tets = 0;
  for (auto _ : state)
    tets = viscera::importers::mesh_label_map(map, options, "organ").tets.size();
  state.counters["tets"] = static_cast<double>(tets);
  state.counters["tets/s"] =
      benchmark::Counter(static_cast<double>(tets), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_OrganMesh3AloneSequential)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(3);

}  // namespace
