#include "simulator/view/view_session.h"

#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkImageData.h>
#include <vtkInteractorStyle.h>
#include <vtkObjectFactory.h>
#include <vtkOggTheoraWriter.h>
#include <vtkRenderWindow.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkWindowToImageFilter.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <mutex>
#include <optional>
#include <system_error>

#include "core/error.h"
#include "simulator/runtime/realtime_loop.h"

namespace viscera::view {

namespace {

/// Keys and mouse to ManualControl commands; VTK's own bindings (wireframe, quit on 'q', …)
/// are switched off by overriding every handler. The physics thread reads the same control, so
/// every call holds `mutex`.
class ManualStyle : public vtkInteractorStyle {
 public:
  static ManualStyle* New();
  vtkTypeMacro(ManualStyle, vtkInteractorStyle) sim::ManualControl* manual = nullptr;
  std::mutex* mutex = nullptr;
  std::atomic<bool> abort_requested{false};

  void OnKeyPress() override {
    const auto command = sim::ManualControl::command_for_key(Interactor->GetKeySym());
    if (!command) return;
    if (*command == sim::ManualCommand::Abort) abort_requested = true;
    if (manual != nullptr) {
      const std::lock_guard<std::mutex> lock(*mutex);
      manual->press(*command);
    }
  }
  void OnKeyRelease() override {
    const auto command = sim::ManualControl::command_for_key(Interactor->GetKeySym());
    if (command && manual != nullptr) {
      const std::lock_guard<std::mutex> lock(*mutex);
      manual->release(*command);
    }
  }
  void OnChar() override {}
  void OnLeftButtonDown() override {
    dragging_ = true;
    Interactor->GetEventPosition(last_);
  }
  void OnLeftButtonUp() override { dragging_ = false; }
  void OnMouseMove() override {
    if (!dragging_ || manual == nullptr) return;
    int now[2];
    Interactor->GetEventPosition(now);
    {
      const std::lock_guard<std::mutex> lock(*mutex);
      manual->drag(now[0] - last_[0], now[1] - last_[1]);
    }
    last_[0] = now[0];
    last_[1] = now[1];
  }
  void OnMouseWheelForward() override { wheel(1); }
  void OnMouseWheelBackward() override { wheel(-1); }
  void OnRightButtonDown() override {}
  void OnMiddleButtonDown() override {}

 private:
  void wheel(int clicks) {
    if (manual == nullptr) return;
    const std::lock_guard<std::mutex> lock(*mutex);
    manual->wheel(clicks);
  }
  bool dragging_ = false;
  int last_[2] = {0, 0};
};
vtkStandardNewMacro(ManualStyle);

/// A live input whose state the window's thread also touches (the keyboard's ManualControl):
/// the physics thread holds `mutex` while it reads it.
class GuardedInput final : public sim::LiveInput {
 public:
  GuardedInput(sim::LiveInput& input, std::mutex& mutex) : input_(input), mutex_(mutex) {}
  sim::InstrumentState next(double dt) override {
    const std::lock_guard<std::mutex> lock(mutex_);
    return input_.next(dt);
  }
  const sim::InstrumentState& current() const override { return input_.current(); }
  void after_step(const sim::SessionRunner& runner) override { input_.after_step(runner); }
  std::string describe() const override { return input_.describe(); }
  void start_realtime(const sim::SessionRunner& runner) override { input_.start_realtime(runner); }
  void stop_realtime() override { input_.stop_realtime(); }
  void add_stats(sim::RealtimeStats& stats) const override { input_.add_stats(stats); }

 private:
  sim::LiveInput& input_;
  std::mutex& mutex_;
};

/// The input of physics step `next` for a session without a live control.
sim::InstrumentState scripted_state(const sim::HeadlessRunOptions& options,
                                    const sim::SessionRunner& runner) {
  const long long next = runner.world().steps() + 1;
  const double time = static_cast<double>(next) * runner.world().time_step();
  return options.instrument != nullptr ? options.instrument->state(next, time)
                                       : sim::InstrumentState{};
}

/// The window's thread: draws the newest snapshot of the physics thread at display rate.
struct WindowLoop {
  sim::RealtimeLoop* loop;
  EndoscopicView* view;
  ManualStyle* style;
  vtkRenderWindowInteractor* interactor;
  long long frames = 0;
  double lowest_scale = 1.0;  ///< smallest render scale the adaptive resolution used
  long long frames_then = 0;
  std::chrono::steady_clock::time_point then = std::chrono::steady_clock::now();

  void tick() {
    if (style->abort_requested) loop->request_end("abort", "the trainee ended the session");
    if (const sim::SessionSnapshot* snapshot = loop->latest()) view->update(*snapshot);
    view->render();
    ++frames;
    adapt_resolution();
    if (loop->finished()) interactor->TerminateApp();
  }

  /// Every 0.3 s: below the target frame rate, render the scene under the lens pass
  /// smaller; well above it, larger again (never above the scale the view was given).
  void adapt_resolution() {
    const ViewOptions& options = view->options();
    if (!options.adaptive_resolution || !options.lens_effects) return;
    const auto now = std::chrono::steady_clock::now();
    const double elapsed = std::chrono::duration<double>(now - then).count();
    if (elapsed < 0.3) return;
    const double fps = static_cast<double>(frames - frames_then) / elapsed;
    const double scale = view->render_scale();
    if (fps < options.target_fps * 1.05 && scale > kLowestScale)
      view->set_render_scale(std::max(kLowestScale, 0.75 * scale));
    else if (fps > options.target_fps * 1.6 && scale < ceiling)
      view->set_render_scale(std::min(ceiling, 1.1 * scale));
    lowest_scale = std::min(lowest_scale, view->render_scale());
    frames_then = frames;
    then = now;
  }
  static constexpr double kLowestScale = 0.25;
  double ceiling = 1.0;  ///< the render scale the view was given
};

void on_timer(vtkObject*, unsigned long, void* client, void*) {
  static_cast<WindowLoop*>(client)->tick();
}

}  // namespace

sim::SessionReport run_in_window(const core::Scenario& scenario,
                                 const sim::HeadlessRunOptions& options, EndoscopicView& view,
                                 sim::ManualControl* manual, sim::LiveInput* live,
                                 double frame_rate) {
  sim::HeadlessRunOptions run = options;
  std::optional<sim::KeyboardInput> keyboard;
  if (run.instrument != nullptr) {
    live = nullptr;  // a script or a recording drives the instrument
  } else if (live == nullptr && manual != nullptr) {
    live = &keyboard.emplace(*manual);
  }
  std::mutex input_mutex;
  std::optional<GuardedInput> guarded;
  std::optional<sim::LiveInstrument> live_instrument;
  if (live != nullptr) {
    guarded.emplace(*live, input_mutex);
    run.instrument = &live_instrument.emplace(*live);
  }
  sim::SessionRunner runner(scenario, run);

  vtkNew<vtkRenderWindowInteractor> interactor;
  interactor->SetRenderWindow(view.window());
  vtkNew<ManualStyle> style;
  style->manual = options.instrument == nullptr ? manual : nullptr;
  style->mutex = &input_mutex;
  interactor->SetInteractorStyle(style);
  interactor->Initialize();

  sim::RealtimeLoop loop(runner, guarded ? &*guarded : nullptr,
                         guarded ? nullptr : options.instrument);
  WindowLoop window{&loop, &view, style, interactor};
  window.ceiling = view.render_scale();
  window.lowest_scale = view.render_scale();
  vtkNew<vtkCallbackCommand> timer;
  timer->SetCallback(on_timer);
  timer->SetClientData(&window);
  interactor->AddObserver(vtkCommand::TimerEvent, timer);
  view.update(runner);
  view.render();
  interactor->CreateRepeatingTimer(
      static_cast<unsigned long>(std::max(1.0, std::floor(1000.0 / frame_rate))));
  const auto began = std::chrono::steady_clock::now();
  loop.start();
  interactor->Start();
  const double shown =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
  interactor->RemoveObserver(timer);
  if (!loop.finished()) loop.request_end("abort", "the window was closed");
  loop.join();  // rethrows a SimulationError of the physics thread

  sim::SessionReport report = runner.finish();
  sim::RealtimeStats stats;
  stats.wall_time = loop.wall_time();
  stats.physics_steps = loop.counters().physics_steps.load();
  stats.late_steps = loop.counters().late_steps.load();
  stats.max_lag = loop.max_lag();
  stats.frames = window.frames;
  stats.view_fps = shown > 0.0 ? static_cast<double>(window.frames) / shown : 0.0;
  stats.render_scale = view.render_scale();
  stats.lowest_render_scale = window.lowest_scale;
  if (guarded) guarded->add_stats(stats);
  if (stats.device && stats.wall_time > 0.0)
    stats.feedback_rate = static_cast<double>(stats.device_feedback) / stats.wall_time;
  report.realtime = stats;
  return report;
}

sim::SessionReport run_with_snapshot(const core::Scenario& scenario,
                                     const sim::HeadlessRunOptions& options, EndoscopicView& view,
                                     const std::filesystem::path& png, double at) {
  sim::SessionRunner runner(scenario, options);
  const double dt = runner.world().time_step();
  bool taken = false;
  while (!runner.finished()) {
    runner.step(scripted_state(options, runner));
    if (at >= 0.0 && !taken && runner.world().time() + 0.5 * dt >= at) {
      view.update(runner);
      view.write_png(png);
      taken = true;
    }
  }
  sim::SessionReport report = runner.finish();
  if (!taken) {
    view.update(runner);
    view.write_png(png);
  }
  return report;
}

sim::SessionReport run_to_video(const core::Scenario& scenario,
                                const sim::HeadlessRunOptions& options, EndoscopicView& view,
                                const std::filesystem::path& ogv, int fps, long long& frames) {
  if (fps <= 0) throw core::UsageError("the video frame rate must be positive");
  sim::SessionRunner runner(scenario, options);
  const double dt = runner.world().time_step();
  const long long every = std::max<long long>(1, std::llround(1.0 / (fps * dt)));

  std::error_code error;
  if (ogv.has_parent_path()) std::filesystem::create_directories(ogv.parent_path(), error);
  const std::filesystem::path partial = ogv.string() + ".partial";
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(view.window());
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  vtkNew<vtkOggTheoraWriter> writer;
  writer->SetInputConnection(grab->GetOutputPort());
  writer->SetFileName(partial.string().c_str());
  writer->SetRate(fps);
  writer->SetQuality(2);
  frames = 0;
  const auto frame = [&] {
    view.update(runner);
    view.render();
    grab->Modified();
    if (frames == 0) writer->Start();
    writer->Write();
    ++frames;
  };
  frame();
  while (!runner.finished()) {
    runner.step(scripted_state(options, runner));
    if (runner.world().steps() % every == 0) frame();
  }
  sim::SessionReport report = runner.finish();
  writer->End();
  if (writer->GetError() != 0 || !std::filesystem::exists(partial)) {
    std::filesystem::remove(partial, error);
    throw core::OutputError("the video encoder failed", {ogv.string(), "", ""});
  }
  std::filesystem::rename(partial, ogv, error);
  if (error)
    throw core::OutputError("cannot move the finished video into place", {ogv.string(), "", ""});
  return report;
}

}  // namespace viscera::view
