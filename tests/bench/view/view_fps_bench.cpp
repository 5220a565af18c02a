// Frames per second of the endoscopic view (issue 8 point 9: ≥ 30 fps at 1280 × 720 on Mesa
// llvmpipe): the hysteroscopy template with baked textures, the camera sweeping through the
// cavity, full lens pass (distortion, depth of field, field stop) and overlay, offscreen. The
// fourth argument is the lens pass's render scale in percent (the scene's resolution).
// Needs an X server: xvfb-run -a build/bin/viscera_view_bench.

#include <benchmark/benchmark.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>

#include "core/package/scenario_package.h"
#include "simulator/session/manual_control.h"
#include "simulator/session/session_runner.h"
#include "simulator/view/endoscopic_view.h"

namespace {

namespace fs = std::filesystem;

/// `viscera new` + `viscera bake` once, in the build tree.
const std::pair<fs::path, viscera::core::Scenario>& patient() {
  static const auto made = [] {
    const fs::path dir = fs::path(VISCERA_BINARY_DIR) / "bench" / "view-patient";
    const fs::path package = dir / "baked.vscene";
    if (!fs::exists(package / "manifest.json")) {
      fs::create_directories(dir);
      const std::string bin = std::string(VISCERA_BINARY_DIR) + "/bin/viscera";
      const std::string raw = (dir / "raw.vscene").string();
      if (std::system(
              (bin + " new --template hysteroscopy -o '" + raw + "' > /dev/null").c_str()) != 0 ||
          std::system(
              (bin + " bake '" + raw + "' -o '" + package.string() + "' > /dev/null").c_str()) != 0)
        std::abort();
    }
    return std::make_pair(package, viscera::core::read_package(package));
  }();
  return made;
}

void BM_EndoscopicViewFrame(benchmark::State& state) {
  const auto& [package, scenario] = patient();
  viscera::view::ViewOptions options;
  options.width = static_cast<int>(state.range(0));
  options.height = static_cast<int>(state.range(1));
  options.offscreen = true;
  options.lens_effects = state.range(2) != 0;
  options.render_scale = static_cast<double>(state.range(3)) / 100.0;
  viscera::view::EndoscopicView view(scenario, package, options);
  const viscera::sim::InstrumentState start = viscera::sim::starting_pose(scenario, 30.0);
  view.set_instrument(start, 30.0);
  view.render();  // shaders compiled, textures uploaded
  int frame = 0;
  for (auto _ : state) {
    viscera::sim::InstrumentState pose = start;
    pose.up = Eigen::AngleAxisd(0.05 * frame++, pose.axis) * pose.up;  // roll the optics
    view.set_instrument(pose, 30.0);
    view.render();
    view.window()->WaitForCompletion();
  }
  state.counters["fps"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_EndoscopicViewFrame)
    ->ArgNames({"width", "height", "lens", "scale%"})
    ->Args({1280, 720, 1, 50})   // the window's setting
    ->Args({1280, 720, 1, 100})  // snapshots and videos
    ->Args({1280, 720, 0, 100})
    ->Args({640, 360, 1, 100})
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()  // CPU of all threads: llvmpipe's rasteriser threads included
    ->UseRealTime();

/// A frame of a session in the window: the session's state into the view (every surface's
/// embedded positions and normals re-uploaded, the overlay's texts and bars), then the render
/// at the window's setting (1280 × 720, lens pass, scene at half resolution). The session
/// steps once per frame; its physics is not part of the view's cost but is timed with it.
void BM_EndoscopicViewSessionFrame(benchmark::State& state) {
  const auto& [package, scenario] = patient();
  viscera::view::ViewOptions options;
  options.offscreen = true;
  options.render_scale = 0.5;
  viscera::view::EndoscopicView view(scenario, package, options);
  const viscera::sim::InstrumentState start = viscera::sim::starting_pose(scenario, 30.0);
  const viscera::sim::RecordedInput resting({{0, start}});
  viscera::sim::HeadlessRunOptions run;
  run.instrument = &resting;
  run.duration = 1e6;
  viscera::sim::SessionRunner runner(scenario, run);
  view.update(runner);
  view.render();
  for (auto _ : state) {
    runner.step(start);
    view.update(runner);
    view.render();
    view.window()->WaitForCompletion();
  }
  state.counters["fps"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_EndoscopicViewSessionFrame)
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime();

/// Blood in the view (issue 18 §5: ≥ 30 fps at 1280 × 720 on llvmpipe with 10,000 particles):
/// the window's setting with 10,000 blood billboards in a 5 mm cloud ahead of the optics, every
/// one moved each frame and at stages spread over its life, and the lens pass's haze on.
void BM_EndoscopicViewBloodFrame(benchmark::State& state) {
  const auto& [package, scenario] = patient();
  viscera::view::ViewOptions options;
  options.offscreen = true;
  options.render_scale = 0.5;
  viscera::view::EndoscopicView view(scenario, package, options);
  viscera::sim::SessionSnapshot snapshot;
  snapshot.instrument = viscera::sim::starting_pose(scenario, 30.0);
  snapshot.optics_angle = 30.0;
  snapshot.haze_density = 30.0;  // 1/m: 0.6 % of blood at k = 5,000 /m
  const viscera::core::Vec3 ahead =
      snapshot.instrument.tip + 0.01 * viscera::sim::view_direction(snapshot.instrument, 30.0);
  const int count = static_cast<int>(state.range(0));
  std::vector<viscera::core::Vec3> base;
  for (int i = 0; i < count; ++i) {
    // A deterministic spread over a 5 mm ball (golden-angle spiral in radius and direction).
    const double t = (i + 0.5) / count, phi = 2.399963 * i, z = 1.0 - 2.0 * t;
    const double r = 0.005 * std::cbrt(std::fmod(0.618034 * i, 1.0));
    const double rho = std::sqrt(std::max(0.0, 1.0 - z * z));
    base.push_back(ahead + r * viscera::core::Vec3(rho * std::cos(phi), rho * std::sin(phi), z));
    snapshot.blood_stage.push_back(static_cast<float>(t));
  }
  snapshot.blood = base;
  view.update(snapshot);
  view.render();
  int frame = 0;
  for (auto _ : state) {
    const double shift = 1e-4 * std::sin(0.1 * frame++);
    for (std::size_t i = 0; i < base.size(); ++i)
      snapshot.blood[i] = base[i] + viscera::core::Vec3(shift, 0.0, 0.0);
    view.update(snapshot);
    view.render();
    view.window()->WaitForCompletion();
  }
  state.counters["fps"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_EndoscopicViewBloodFrame)
    ->ArgNames({"particles"})
    ->Arg(1000)
    ->Arg(10000)
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime();

}  // namespace
