#pragma once
/// The endoscopic view of a session (seed 000 §7, seed 002 §4–§6): the scene seen from the
/// optics' tip (the instrument's, or the laparoscope's when held apart) through angled optics (0°,
/// 12°, 30°), lit by a head light at the tip, through the lens pass (barrel distortion, depth of
/// field, round field stop), with the force bars and the session-info panel on top. A VTK render
/// window, on screen or offscreen (X only: offscreen still needs an X server, e.g. Xvfb). Headless
/// sessions never construct one.

#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>

#include <filesystem>
#include <memory>
#include <string>

#include "core/scenario/scenario.h"
#include "simulator/runtime/session_snapshot.h"
#include "simulator/session/instrument_state.h"
#include "simulator/session/session_runner.h"
#include "simulator/view/session_overlay.h"

class vtkImageData;
class vtkLight;

namespace viscera::view {

class ParticleBillboards;
class PoolSurface;
class PortInstrument;
class SmokeBillboards;
class EndoscopeLensPass;
class SceneSurfaces;

/// How the view is set up.
struct ViewOptions {
  int width = 1280, height = 720;  ///< pixels
  bool offscreen = false;          ///< render without showing a window
  bool lens_effects = true;        ///< barrel distortion, depth of field, field stop
  double distortion = 0.2;         ///< barrel coefficient k (EndoscopeLensPass)
  /// With lens effects: the scene is rendered at this fraction of the size and resampled by
  /// the lens pass (EndoscopeLensPass::render_scale; 0.5 keeps a window at ≥ 30 fps on a
  /// software renderer, 1 for snapshots and videos).
  double render_scale = 1.0;
  /// In a window: lower render_scale (down to 0.25) while the view draws fewer than
  /// `target_fps` frames a second, and raise it back (up to the render_scale given) when there
  /// is room — dynamic resolution, so a loaded machine keeps the frame rate, not the detail.
  bool adaptive_resolution = false;
  double target_fps = 30.0;
  std::string bindings;          ///< key bindings shown in the window ("" : none)
  double light_intensity = 1.4;  ///< head light
  /// m at which the head light has dimmed to half; 0: the instrument's — 3 cm for a
  /// hysteroscope or cystoscope, which work a centimetre or two from the wall, and 8 cm for a
  /// laparoscope, whose xenon light through a 10 mm scope lights the pelvis from 5–10 cm.
  double light_falloff = 0.0;
};

/// The endoscopic image of one scenario.
class EndoscopicView {
 public:
  /// Builds the scene from the package's surfaces and textures. Throws core::InputError when a
  /// texture cannot be read.
  EndoscopicView(const core::Scenario& scenario, const std::filesystem::path& package,
                 const ViewOptions& options);
  ~EndoscopicView();
  EndoscopicView(const EndoscopicView&) = delete;
  EndoscopicView& operator=(const EndoscopicView&) = delete;

  /// Puts the camera at the tip looking along the optics (view_direction(state, angle)), with
  /// `state.up` as the image's up; focus and field of view from the scenario's instrument.
  void set_instrument(const sim::InstrumentState& state, double optics_angle);
  /// Surfaces, camera and overlay from a running session (captures a snapshot of it).
  void update(const sim::SessionRunner& runner);
  /// The same from a snapshot, as the render thread of a threaded session sees it.
  void update(const sim::SessionSnapshot& snapshot);
  void render();

  /// RGB pixels of the current frame (renders first).
  vtkSmartPointer<vtkImageData> capture();
  /// Writes the current frame as PNG through a temporary sibling; throws core::OutputError.
  void write_png(const std::filesystem::path& path);

  vtkRenderWindow* window() const { return window_; }
  const ViewOptions& options() const { return options_; }
  /// The lens pass's scene resolution as a fraction of the view (0.25–1); no effect without
  /// lens effects.
  void set_render_scale(double scale);
  double render_scale() const;
  vtkRenderer* scene_renderer() const { return scene_; }
  SessionOverlay& overlay() { return *overlay_; }
  const SceneSurfaces& surfaces() const { return *surfaces_; }
  const ParticleBillboards& blood() const { return *blood_; }
  const ParticleBillboards& bubbles() const { return *bubbles_; }
  const ParticleBillboards& debris() const { return *debris_; }
  const ParticleBillboards& irrigation_drops() const { return *drops_; }
  const PoolSurface& pool() const { return *pool_; }
  /// The second port's tool as drawn.
  const PortInstrument& left_tool() const { return *left_tool_; }
  /// The working port's tool as drawn: only while the laparoscope is held apart
  /// (sim::LaparoscopeCamera); otherwise it runs along the optics, out of view.
  const PortInstrument& right_tool() const { return *right_tool_; }
  const SmokeBillboards& smoke() const { return *smoke_; }
  /// The steam on the lens in the lens pass, 0…1 (0 without lens effects).
  double lens_fog() const;
  /// The blood haze's extinction in the lens pass, 1/m (0 without lens effects).
  double haze_density() const;

 private:
  const core::Scenario& scenario_;
  ViewOptions options_;
  vtkSmartPointer<vtkRenderWindow> window_;
  vtkSmartPointer<vtkRenderer> scene_, hud_;
  vtkSmartPointer<vtkLight> light_;
  vtkSmartPointer<EndoscopeLensPass> lens_;
  std::unique_ptr<SceneSurfaces> surfaces_;
  std::unique_ptr<SessionOverlay> overlay_;
  std::unique_ptr<ParticleBillboards> blood_, bubbles_, debris_, drops_;
  std::unique_ptr<PoolSurface> pool_;
  std::unique_ptr<PortInstrument> left_tool_, right_tool_;
  std::unique_ptr<SmokeBillboards> smoke_;
  sim::SessionSnapshot captured_;  ///< reused by update(runner)
};

}  // namespace viscera::view
