// CGAL's real liver → simulation-ready body (issue 20 §2): liver.inr.gz (Debian libcgal-demo,
// 438 × 353 × 165, 0.617 × 0.617 × 1.333 mm) segmented as `viscera segment` does — the organ's
// own label (255) or thresholded at 128 and opened by one voxel — then `mesh_label_body` with
// the tets' boundary as the visual surface (the default of `viscera mesh tets`) or the contour.
// Arg 0: map (0: label 255, 1: 128:255 opened); Arg 1: Mesh_3 threads; Arg 2: 1 = contour.
// Counters: tets, inverted tets, volume against the voxels (%), and each stage's seconds.
#include <benchmark/benchmark.h>

#include <array>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "core/segmentation/label_operations.h"
#include "core/segmentation/morphology.h"
#include "core/segmentation/threshold.h"
#include "importers/meshing/label_body.h"
#include "importers/volume/volume_reader.h"

namespace {

namespace fs = std::filesystem;
using viscera::core::LabelMap;

const LabelMap& liver_map(int which) {
  static const std::array<LabelMap, 2> maps = [] {
    const fs::path dir = fs::temp_directory_path() / "viscera-liver-bench";
    const fs::path file = dir / "data/images/liver.inr.gz";
    if (!fs::exists(file)) {
      fs::create_directories(dir);
      const std::string command = "tar -xzf /usr/share/doc/libcgal-dev/data.tar.gz -C '" +
                                  dir.string() + "' data/images/liver.inr.gz";
      if (std::system(command.c_str()) != 0) std::abort();
    }
    const auto volume = viscera::importers::read_volume(file).volume;
    namespace seg = viscera::core;
    return std::array<LabelMap, 2>{
        seg::keep_largest_component(seg::threshold(volume, 255, 255)),
        seg::keep_largest_component(seg::open_labels(seg::threshold(volume, 128, 255), 1))};
  }();
  return maps[static_cast<std::size_t>(which)];
}

void BM_LiverToSimReadyBody(benchmark::State& state) {
  const LabelMap& map = liver_map(static_cast<int>(state.range(0)));
  viscera::importers::LabelBodyOptions options;
  options.tets.threads = static_cast<int>(state.range(1));
  options.visual_surface = state.range(2) == 1
                               ? viscera::importers::VisualSurfaceSource::LabelContour
                               : viscera::importers::VisualSurfaceSource::TetBoundary;
  options.surface.target_triangles = 50000;
  viscera::importers::LabelBody made;
  for (auto _ : state)
    made = viscera::importers::mesh_label_body(map, options, "liver");
  std::size_t voxels = 0;
  for (const auto& [label, count] : viscera::core::label_counts(map))
    voxels += count;
  const double voxel_volume = static_cast<double>(voxels) * map.image.spacing.prod();
  state.counters["tets"] = static_cast<double>(made.body.tets.size());
  state.counters["inverted"] = static_cast<double>(made.quality.inverted);
  state.counters["volume_error_percent"] = 100.0 * (made.quality.total_volume / voxel_volume - 1.0);
  state.counters["surface_triangles"] = static_cast<double>(made.surface.mesh.triangles.size());
  for (const auto& [stage, seconds] : made.seconds)
    state.counters[stage + "_s"] = seconds;
}
BENCHMARK(BM_LiverToSimReadyBody)
    ->Args({0, 1, 0})
    ->Args({1, 1, 0})
    ->Args({0, 2, 0})
    ->Args({0, 1, 1})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(3);

}  // namespace
