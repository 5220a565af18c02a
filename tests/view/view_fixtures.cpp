#include "tests/view/view_fixtures.h"

#include <gtest/gtest.h>
#include <vtkImageData.h>

#include <cmath>

#include "core/package/scenario_package.h"
#include "tests/support/command_runner.h"
#include "tests/support/test_paths.h"

namespace viscera::testing {

namespace {

double luminance(const unsigned char* p) {
  return 0.299 * p[0] + 0.587 * p[1] + 0.114 * p[2];
}

template <typename F>
void for_pixels(vtkImageData* frame, double field, F&& visit) {
  int dims[3];
  frame->GetDimensions(dims);
  const int channels = frame->GetNumberOfScalarComponents();
  const auto* pixels = static_cast<const unsigned char*>(frame->GetScalarPointer());
  const double cx = 0.5 * dims[0], cy = 0.5 * dims[1], radius = field * 0.5 * dims[1];
  for (int y = 0; y < dims[1]; ++y) {
    for (int x = 0; x < dims[0]; ++x) {
      if (field > 0.0 && std::hypot(x + 0.5 - cx, y + 0.5 - cy) > radius) continue;
      visit(pixels + (static_cast<std::size_t>(y) * dims[0] + x) * channels, x, y);
    }
  }
}

}  // namespace

const Patient& hysteroscopy_patient() {
  static const Patient patient = [] {
    Patient p;
    const auto dir = std::filesystem::path(std::getenv("VISCERA_TEST_TMP") != nullptr
                                               ? std::getenv("VISCERA_TEST_TMP")
                                               : std::filesystem::temp_directory_path().string()) /
                     "hysteroscopy-patient";
    p.package = dir / "patient.vscene";
    if (!std::filesystem::exists(p.package / "manifest.json")) {
      std::filesystem::create_directories(dir);
      const auto raw = dir / "raw.vscene";
      auto result = run_program(
          "viscera", "new --template hysteroscopy --seed 7 -o " + shell_quote(raw.string()), dir);
      if (result.exit_code != 0) ADD_FAILURE() << "viscera new failed: " << result.err;
      result = run_program(
          "viscera", "bake " + shell_quote(raw.string()) + " -o " + shell_quote(p.package.string()),
          dir);
      if (result.exit_code != 0) ADD_FAILURE() << "viscera bake failed: " << result.err;
    }
    p.scenario = core::read_package(p.package);
    return p;
  }();
  return patient;
}

FrameStatistics frame_statistics(vtkImageData* frame, double field) {
  FrameStatistics stats;
  double sum = 0.0, sum2 = 0.0, rgb[3] = {0.0, 0.0, 0.0};
  long long count = 0, lit = 0;
  for_pixels(frame, field, [&](const unsigned char* p, int, int) {
    const double l = luminance(p);
    sum += l;
    sum2 += l * l;
    ++count;
    if (l > 8.0) {
      ++lit;
      for (int c = 0; c < 3; ++c)
        rgb[c] += p[c];
    }
  });
  if (count == 0) return stats;
  stats.lit_fraction = static_cast<double>(lit) / static_cast<double>(count);
  stats.mean_luminance = sum / static_cast<double>(count);
  stats.luminance_stddev = std::sqrt(std::max(
      0.0, sum2 / static_cast<double>(count) - stats.mean_luminance * stats.mean_luminance));
  const double total = rgb[0] + rgb[1] + rgb[2];
  if (total > 0.0)
    for (int c = 0; c < 3; ++c)
      stats.chromaticity[static_cast<std::size_t>(c)] = rgb[c] / total;
  return stats;
}

double mean_abs_difference(vtkImageData* a, vtkImageData* b, double field) {
  const int channels = a->GetNumberOfScalarComponents();
  const auto* base = static_cast<const unsigned char*>(a->GetScalarPointer());
  const auto* other = static_cast<const unsigned char*>(b->GetScalarPointer());
  double sum = 0.0;
  long long count = 0;
  for_pixels(a, field, [&](const unsigned char* p, int, int) {
    const std::ptrdiff_t offset = p - base;
    for (int c = 0; c < 3; ++c)
      sum += std::abs(static_cast<int>(p[c]) - static_cast<int>(other[offset + c]));
    count += 3;
  });
  (void)channels;
  return count > 0 ? sum / static_cast<double>(count) : 0.0;
}

double corner_luminance(vtkImageData* frame) {
  int dims[3];
  frame->GetDimensions(dims);
  double sum = 0.0;
  long long count = 0;
  for_pixels(frame, 0.0, [&](const unsigned char* p, int x, int y) {
    const bool corner_x = x < 12 || x >= dims[0] - 12, corner_y = y < 12 || y >= dims[1] - 12;
    if (corner_x && corner_y) {
      sum += luminance(p);
      ++count;
    }
  });
  return count > 0 ? sum / static_cast<double>(count) : 0.0;
}

}  // namespace viscera::testing
