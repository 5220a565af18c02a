// Reading and segmenting a 256³ CT-sized volume (int16, 1 mm voxels, a 100-voxel-radius ball of
// 60 HU in air at −1000 HU): read_volume per format, then each segmentation step.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstring>
#include <filesystem>

#include "core/segmentation/label_operations.h"
#include "core/segmentation/morphology.h"
#include "core/segmentation/region_growing.h"
#include "core/segmentation/threshold.h"
#include "exporters/volume/volume_writer.h"
#include "importers/volume/volume_reader.h"

namespace {

namespace fs = std::filesystem;
using namespace viscera;

const core::ImageVolume& phantom() {
  static const core::ImageVolume volume = [] {
    core::ImageVolume v;
    v.dims = {256, 256, 256};
    v.spacing = core::Vec3::Constant(0.001);
    v.scalar_type = core::ScalarType::Int16;
    v.allocate();
    auto* voxels = reinterpret_cast<std::int16_t*>(v.voxels.data());
    for (int k = 0; k < 256; ++k)
      for (int j = 0; j < 256; ++j)
        for (int i = 0; i < 256; ++i)
          voxels[v.linear_index(i, j, k)] =
              std::hypot(i - 127.5, j - 127.5, k - 127.5) <= 100.0 ? 60 : -1000;
    return v;
  }();
  return volume;
}

fs::path phantom_file(const std::string& name) {
  const fs::path path = fs::temp_directory_path() / ("viscera-bench-" + name);
  if (!fs::exists(path)) exporters::write_volume(phantom(), path);
  return path;
}

void ReadVolume(benchmark::State& state, const std::string& name) {
  const fs::path path = phantom_file(name);
  for (auto _ : state)
    benchmark::DoNotOptimize(importers::read_volume(path));
  state.SetItemsProcessed(state.iterations() * 256 * 256 * 256);
}
BENCHMARK_CAPTURE(ReadVolume, nii, std::string("phantom.nii"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(ReadVolume, nii_gz, std::string("phantom.nii.gz"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(ReadVolume, mha, std::string("phantom.mha"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(ReadVolume, vti, std::string("phantom.vti"))->Unit(benchmark::kMillisecond);

void Threshold256(benchmark::State& state) {
  for (auto _ : state)
    benchmark::DoNotOptimize(core::threshold(phantom(), 0, 100));
  state.SetItemsProcessed(state.iterations() * 256 * 256 * 256);
}
BENCHMARK(Threshold256)->Unit(benchmark::kMillisecond);

void GrowRegion256(benchmark::State& state) {
  for (auto _ : state)
    benchmark::DoNotOptimize(core::grow_region(phantom(), {128, 128, 128}, 10));
}
BENCHMARK(GrowRegion256)->Unit(benchmark::kMillisecond);

void OpenLabels256(benchmark::State& state) {
  const auto labels = core::threshold(phantom(), 0, 100);
  for (auto _ : state)
    benchmark::DoNotOptimize(core::open_labels(labels, 1));
}
BENCHMARK(OpenLabels256)->Unit(benchmark::kMillisecond);

void KeepLargest256(benchmark::State& state) {
  const auto labels = core::threshold(phantom(), 0, 100);
  for (auto _ : state)
    benchmark::DoNotOptimize(core::keep_largest_component(labels));
}
BENCHMARK(KeepLargest256)->Unit(benchmark::kMillisecond);

}  // namespace
