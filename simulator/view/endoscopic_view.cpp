#include "simulator/view/endoscopic_view.h"

#include <vtkCamera.h>
#include <vtkCameraPass.h>
#include <vtkImageData.h>
#include <vtkLight.h>
#include <vtkRenderStepsPass.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkWindowToImageFilter.h>

#include <algorithm>
#include <cmath>

#include "simulator/view/endoscope_lens_pass.h"
#include "simulator/view/image_files.h"
#include "simulator/view/particle_billboards.h"
#include "simulator/view/pool_surface.h"
#include "simulator/view/port_instrument.h"
#include "simulator/view/scene_surfaces.h"
#include "simulator/view/smoke_billboards.h"
#include "simulator/view/x_display.h"

namespace viscera::view {

namespace {
constexpr double kNearPlane = 0.0005;              // m: the optics see from half a millimetre
constexpr double kFarPlane = 0.3;                  // m
constexpr double kEndoscopeLightFalloff = 0.03;    // m
constexpr double kLaparoscopeLightFalloff = 0.08;  // m
}  // namespace

EndoscopicView::EndoscopicView(const core::Scenario& scenario, const std::filesystem::path& package,
                               const ViewOptions& options)
    : scenario_(scenario), options_(options) {
  require_x_display();  // VTK would end the process without one
  surfaces_ = std::make_unique<SceneSurfaces>(scenario, package);
  overlay_ = std::make_unique<SessionOverlay>(options.bindings);

  window_ = vtkSmartPointer<vtkRenderWindow>::New();
  window_->SetSize(options.width, options.height);
  window_->SetOffScreenRendering(options.offscreen ? 1 : 0);
  window_->SetWindowName("Viscera - endoscopic view");
  window_->SetNumberOfLayers(2);
  window_->SetMultiSamples(0);

  scene_ = vtkSmartPointer<vtkRenderer>::New();
  scene_->SetLayer(0);
  scene_->SetBackground(0.0, 0.0, 0.0);
  scene_->AutomaticLightCreationOff();
  scene_->LightFollowCameraOff();
  scene_->TwoSidedLightingOn();
  surfaces_->add_to(scene_);
  blood_ = std::make_unique<ParticleBillboards>(scene_, kBloodLook);
  bubbles_ = std::make_unique<ParticleBillboards>(scene_, kBubbleLook);
  debris_ = std::make_unique<ParticleBillboards>(scene_, kDebrisLook);
  drops_ = std::make_unique<ParticleBillboards>(scene_, kDropLook);
  pool_ = std::make_unique<PoolSurface>(scene_);
  left_tool_ = std::make_unique<PortInstrument>(scene_);
  right_tool_ = std::make_unique<PortInstrument>(scene_);
  smoke_ = std::make_unique<SmokeBillboards>(scene_);

  // The head light: a spot at the tip along the optics, dimming with distance.
  light_ = vtkSmartPointer<vtkLight>::New();
  light_->SetLightTypeToSceneLight();
  light_->PositionalOn();
  light_->SetIntensity(options.light_intensity);
  light_->SetColor(1.0, 0.97, 0.92);
  light_->SetConeAngle(scenario.session.instrument.field_of_view / 2.0 + 20.0);
  const double falloff = options.light_falloff > 0.0 ? options.light_falloff
                         : scenario.session.instrument.kind == "laparoscope"
                             ? kLaparoscopeLightFalloff
                             : kEndoscopeLightFalloff;
  light_->SetAttenuationValues(1.0, 0.0, 1.0 / (falloff * falloff));
  scene_->AddLight(light_);

  if (options.lens_effects) {
    vtkNew<vtkRenderStepsPass> steps;
    vtkNew<vtkCameraPass> camera;
    camera->SetDelegatePass(steps);
    lens_ = vtkSmartPointer<EndoscopeLensPass>::New();
    lens_->SetDelegatePass(camera);
    lens_->distortion = options.distortion;
    lens_->focus_distance = scenario.session.instrument.focus_distance;
    lens_->render_scale = options.render_scale;
    scene_->SetPass(lens_);
  }

  hud_ = vtkSmartPointer<vtkRenderer>::New();
  hud_->SetLayer(1);
  hud_->InteractiveOff();
  overlay_->add_to(hud_);

  window_->AddRenderer(scene_);
  window_->AddRenderer(hud_);
  set_instrument(sim::InstrumentState{}, scenario.session.instrument.optics_angle);
}

EndoscopicView::~EndoscopicView() {
  if (window_) window_->Finalize();
}

void EndoscopicView::set_instrument(const sim::InstrumentState& state, double optics_angle) {
  sim::InstrumentState pose = state;
  sim::orthonormalise(pose);
  const core::Vec3 direction = sim::view_direction(pose, optics_angle);
  // The image's up: the instrument's up, made orthogonal to the line of sight.
  core::Vec3 up = pose.up - pose.up.dot(direction) * direction;
  if (up.norm() < 1e-9) up = pose.axis - pose.axis.dot(direction) * direction;
  up.normalize();
  const core::InstrumentSpec& optics = scenario_.session.instrument;
  const core::Vec3 focus = pose.tip + optics.focus_distance * direction;
  vtkCamera* camera = scene_->GetActiveCamera();
  camera->SetPosition(pose.tip.data());
  camera->SetFocalPoint(focus.data());
  camera->SetViewUp(up.data());
  camera->SetViewAngle(optics.field_of_view);
  camera->SetClippingRange(kNearPlane, kFarPlane);
  light_->SetPosition(pose.tip.data());
  light_->SetFocalPoint(focus.data());
}

void EndoscopicView::update(const sim::SessionRunner& runner) {
  sim::capture_snapshot(runner, captured_);
  update(captured_);
}

void EndoscopicView::update(const sim::SessionSnapshot& snapshot) {
  surfaces_->update(snapshot.bodies);
  blood_->update(snapshot.blood, snapshot.blood_stage);
  bubbles_->update(snapshot.bubbles, snapshot.bubble_size);
  debris_->update(snapshot.debris, snapshot.debris_size);
  drops_->update(snapshot.irrigation_drops, snapshot.irrigation_drop_age);
  pool_->update(snapshot.pool_centre, snapshot.pool_up, snapshot.pool_radius,
                snapshot.pool_blood_fraction, snapshot.pool_waves);
  if (lens_) {
    lens_->haze_density = snapshot.haze_density;
    lens_->lens_fog = snapshot.lens_fog;
  }
  left_tool_->update(snapshot.instrument.second);
  // The working port's tool is in view while the laparoscope is held apart; otherwise it runs
  // along the optics, out of their view.
  right_tool_->update(sim::port_tool(snapshot.instrument, snapshot.instrument.camera.held));
  set_instrument(sim::camera_pose(snapshot.instrument), snapshot.optics_angle);
  {
    // The smoke faces the camera just placed.
    vtkCamera* camera = scene_->GetActiveCamera();
    core::Vec3 up, forward;
    camera->GetViewUp(up.data());
    camera->GetDirectionOfProjection(forward.data());
    smoke_->update(snapshot.smoke, forward.cross(up).normalized(), up.normalized());
  }
  OverlayState state;
  state.elapsed = snapshot.time;
  state.time_limit = snapshot.time_limit;
  state.force = snapshot.instrument_force;
  state.force_warning = snapshot.force_warning;
  state.tip = snapshot.instrument.tip;
  state.optics_angle = snapshot.optics_angle;
  state.inflow = snapshot.instrument.inflow;
  state.outflow = snapshot.instrument.outflow;
  state.surface_seen = snapshot.surface_seen;
  state.step = snapshot.step;
  state.ended = snapshot.ended;
  if (snapshot.tools) {
    state.tool = std::string(sim::tool_name(snapshot.instrument.tool));
    state.jaws_closed = snapshot.instrument.jaws_closed;
    state.irrigating = snapshot.instrument.irrigating;
    state.lens_fog = snapshot.lens_fog;
    state.pool_ml = snapshot.pool_volume * 1e6;
    state.pool_blood_fraction = snapshot.pool_blood_fraction;
    if (snapshot.instrument.second.inserted) {
      state.left_tool = std::string(sim::tool_name(snapshot.instrument.second.tool));
      state.left_jaws_closed = snapshot.instrument.second.jaws_closed;
    }
  }
  overlay_->update(state);
}

void EndoscopicView::set_render_scale(double scale) {
  options_.render_scale = std::clamp(scale, 0.25, 1.0);
  if (lens_) lens_->render_scale = options_.render_scale;
}

double EndoscopicView::haze_density() const {
  return lens_ ? lens_->haze_density : 0.0;
}

double EndoscopicView::lens_fog() const {
  return lens_ ? lens_->lens_fog : 0.0;
}

double EndoscopicView::render_scale() const {
  return options_.render_scale;
}

void EndoscopicView::render() {
  window_->Render();
}

vtkSmartPointer<vtkImageData> EndoscopicView::capture() {
  render();
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window_);
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  grab->Update();
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->DeepCopy(grab->GetOutput());
  return image;
}

void EndoscopicView::write_png(const std::filesystem::path& path) {
  write_file_atomically(path, encode_png(capture()));
}

}  // namespace viscera::view
