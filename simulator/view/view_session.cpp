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

#include <chrono>
#include <cmath>
#include <optional>
#include <system_error>

#include "core/error.h"

namespace viscera::view {

namespace {

/// Keys and mouse to ManualControl commands; VTK's own bindings (wireframe, quit on 'q', …)
/// are switched off by overriding every handler.
class ManualStyle : public vtkInteractorStyle {
 public:
  static ManualStyle* New();
  vtkTypeMacro(ManualStyle, vtkInteractorStyle) sim::ManualControl* manual = nullptr;
  bool abort_requested = false;

  void OnKeyPress() override {
    const auto command = sim::ManualControl::command_for_key(Interactor->GetKeySym());
    if (!command) return;
    if (*command == sim::ManualCommand::Abort) abort_requested = true;
    if (manual != nullptr) manual->press(*command);
  }
  void OnKeyRelease() override {
    const auto command = sim::ManualControl::command_for_key(Interactor->GetKeySym());
    if (command && manual != nullptr) manual->release(*command);
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
    manual->drag(now[0] - last_[0], now[1] - last_[1]);
    last_[0] = now[0];
    last_[1] = now[1];
  }
  void OnMouseWheelForward() override {
    if (manual != nullptr) manual->wheel(1);
  }
  void OnMouseWheelBackward() override {
    if (manual != nullptr) manual->wheel(-1);
  }
  void OnRightButtonDown() override {}
  void OnMiddleButtonDown() override {}

 private:
  bool dragging_ = false;
  int last_[2] = {0, 0};
};
vtkStandardNewMacro(ManualStyle);

/// The input of physics step `next` for a session without a live control.
sim::InstrumentState scripted_state(const sim::HeadlessRunOptions& options,
                                    const sim::SessionRunner& runner) {
  const long long next = runner.world().steps() + 1;
  const double time = static_cast<double>(next) * runner.world().time_step();
  return options.instrument != nullptr ? options.instrument->state(next, time)
                                       : sim::InstrumentState{};
}

/// Everything the window's timer needs.
struct WindowLoop {
  const sim::HeadlessRunOptions* options;
  sim::SessionRunner* runner;
  EndoscopicView* view;
  sim::LiveInput* live;
  ManualStyle* style;
  vtkRenderWindowInteractor* interactor;
  std::chrono::steady_clock::time_point start;

  void tick() {
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const double dt = runner->world().time_step();
    // At most a quarter second of simulation per frame, so a slow machine slows down the
    // session instead of freezing the window.
    const long long budget = std::llround(0.25 / dt);
    for (long long n = 0;
         n < budget && !runner->finished() && runner->world().time() + 0.5 * dt < wall; ++n) {
      if (style->abort_requested) {
        runner->end("abort", "the trainee ended the session");
        break;
      }
      if (live != nullptr) {
        runner->step(live->next(dt));
        live->after_step(*runner);
      } else {
        runner->step(scripted_state(*options, *runner));
      }
    }
    view->update(*runner);
    view->render();
    if (runner->finished()) interactor->TerminateApp();
  }
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
  std::optional<sim::LiveInstrument> live_instrument;
  if (live != nullptr) run.instrument = &live_instrument.emplace(*live);
  sim::SessionRunner runner(scenario, run);

  vtkNew<vtkRenderWindowInteractor> interactor;
  interactor->SetRenderWindow(view.window());
  vtkNew<ManualStyle> style;
  style->manual = options.instrument == nullptr ? manual : nullptr;
  interactor->SetInteractorStyle(style);
  interactor->Initialize();

  WindowLoop loop{&run, &runner, &view, live, style, interactor, std::chrono::steady_clock::now()};
  vtkNew<vtkCallbackCommand> timer;
  timer->SetCallback(on_timer);
  timer->SetClientData(&loop);
  interactor->AddObserver(vtkCommand::TimerEvent, timer);
  view.update(runner);
  view.render();
  interactor->CreateRepeatingTimer(
      static_cast<unsigned long>(std::max(1.0, std::round(1000.0 / frame_rate))));
  loop.start = std::chrono::steady_clock::now();
  interactor->Start();
  if (!runner.finished()) runner.end("abort", "the window was closed");
  interactor->RemoveObserver(timer);
  return runner.finish();
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
