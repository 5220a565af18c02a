// The endoscopic view rendered offscreen (under Xvfb) on a real hysteroscopy package: the
// textured organ is in the picture, angled optics look elsewhere, the lens pass distorts and
// stops the field, and the overlay warns about force as seed 002 §5.2 says.

#include "simulator/view/endoscopic_view.h"

#include <gtest/gtest.h>
#include <vtkCamera.h>
#include <vtkImageData.h>
#include <vtkPointData.h>

#include <cmath>
#include <fstream>
#include <numbers>

#include "core/package/scenario_package.h"
#include "simulator/session/manual_control.h"
#include "simulator/view/particle_billboards.h"
#include "simulator/view/pool_surface.h"
#include "simulator/view/port_instrument.h"
#include "simulator/view/scene_surfaces.h"
#include "simulator/view/smoke_billboards.h"
#include "tests/support/command_runner.h"
#include "tests/support/test_paths.h"
#include "tests/view/view_fixtures.h"

namespace viscera {
namespace {

using testing::frame_statistics;
using testing::FrameStatistics;

view::ViewOptions offscreen(bool lens) {
  view::ViewOptions options;
  options.width = 640;
  options.height = 360;
  options.offscreen = true;
  options.lens_effects = lens;
  return options;
}

TEST(EndoscopicView, shows_the_textured_organ_from_the_starting_pose) {
  const auto& patient = testing::hysteroscopy_patient();
  view::EndoscopicView view(patient.scenario, patient.package, offscreen(false));
  const double angle = patient.scenario.session.instrument.optics_angle;
  view.set_instrument(sim::starting_pose(patient.scenario, angle), angle);
  const auto frame = view.capture();
  int dims[3];
  frame->GetDimensions(dims);
  EXPECT_EQ(dims[0], 640);
  EXPECT_EQ(dims[1], 360);
  const FrameStatistics stats = frame_statistics(frame, 0.9);
  // Lit tissue fills the field (not a blank frame), with the texture's detail in it.
  EXPECT_GT(stats.lit_fraction, 0.8);
  EXPECT_GT(stats.mean_luminance, 25.0);
  EXPECT_GT(stats.luminance_stddev, 4.0);
  // Its hue is the texture's: the chromaticity (r, g, b)/(r+g+b) of the frame is close to
  // that of the organ's albedo map (the head light is white, so shading only scales it).
  vtkImageData* albedo = nullptr;
  for (const auto& object : patient.scenario.objects)
    if (albedo == nullptr) albedo = view.surfaces().texture_of(object.id);
  ASSERT_NE(albedo, nullptr) << "the hysteroscopy package carries an albedo texture";
  const auto texture = view::mean_colour(albedo);
  const double texture_sum = texture[0] + texture[1] + texture[2];
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(stats.chromaticity[static_cast<std::size_t>(c)],
                texture[static_cast<std::size_t>(c)] / texture_sum, 0.06)
        << "channel " << c;
  }
}

TEST(EndoscopicView, angled_optics_look_elsewhere_from_the_same_pose) {
  const auto& patient = testing::hysteroscopy_patient();
  view::EndoscopicView view(patient.scenario, patient.package, offscreen(false));
  const sim::InstrumentState pose = sim::starting_pose(patient.scenario, 0.0);
  view.set_instrument(pose, 0.0);
  const auto straight = view.capture();
  view.set_instrument(pose, 12.0);
  const auto twelve = view.capture();
  view.set_instrument(pose, 30.0);
  const auto thirty = view.capture();
  const double d12 = testing::mean_abs_difference(straight, twelve);
  const double d30 = testing::mean_abs_difference(straight, thirty);
  EXPECT_GT(d12, 2.0);
  EXPECT_GT(d30, d12) << "a steeper angle moves the picture further";
  // The same optics from the same pose give the same picture.
  view.set_instrument(pose, 0.0);
  EXPECT_LT(testing::mean_abs_difference(straight, view.capture()), 0.01);
}

TEST(EndoscopicView, lens_pass_stops_the_field_and_distorts_the_image) {
  const auto& patient = testing::hysteroscopy_patient();
  const double angle = patient.scenario.session.instrument.optics_angle;
  const sim::InstrumentState pose = sim::starting_pose(patient.scenario, angle);
  view::EndoscopicView plain(patient.scenario, patient.package, offscreen(false));
  plain.set_instrument(pose, angle);
  const auto pinhole = plain.capture();
  view::EndoscopicView lens(patient.scenario, patient.package, offscreen(true));
  lens.set_instrument(pose, angle);
  const auto optics = lens.capture();
  // Outside the round field (the corners) the endoscope shows black; inside, tissue.
  EXPECT_LT(testing::corner_luminance(optics), 1.0);
  EXPECT_GT(testing::corner_luminance(pinhole), 5.0);
  const FrameStatistics inside = frame_statistics(optics, 0.9);
  EXPECT_GT(inside.lit_fraction, 0.8);
  // Distortion and blur change the picture inside the field too.
  EXPECT_GT(testing::mean_abs_difference(pinhole, optics, 0.9), 2.0);
}

TEST(EndoscopicView, without_distortion_the_lens_shows_the_pinhole_picture_in_the_field) {
  const auto& patient = testing::hysteroscopy_patient();
  const double angle = patient.scenario.session.instrument.optics_angle;
  const sim::InstrumentState pose = sim::starting_pose(patient.scenario, angle);
  view::EndoscopicView plain(patient.scenario, patient.package, offscreen(false));
  plain.set_instrument(pose, angle);
  const auto pinhole = plain.capture();
  view::ViewOptions options = offscreen(true);
  options.distortion = 0.0;  // only the depth of field and the field stop remain
  view::EndoscopicView lens(patient.scenario, patient.package, options);
  lens.set_instrument(pose, angle);
  const double same = testing::mean_abs_difference(pinhole, lens.capture(), 0.9);
  // Mapped 1:1, the field differs from the pinhole image by the blur alone; a scene sampled
  // with the wrong scale or aspect would differ like a different picture (as k = 0.2 does).
  options.distortion = 0.2;
  view::EndoscopicView distorted(patient.scenario, patient.package, options);
  distorted.set_instrument(pose, angle);
  const double moved = testing::mean_abs_difference(pinhole, distorted.capture(), 0.9);
  EXPECT_LT(same, 0.5 * moved);
}

TEST(EndoscopicView, half_resolution_scene_under_the_lens_keeps_the_picture) {
  const auto& patient = testing::hysteroscopy_patient();
  const double angle = patient.scenario.session.instrument.optics_angle;
  const sim::InstrumentState pose = sim::starting_pose(patient.scenario, angle);
  view::EndoscopicView full(patient.scenario, patient.package, offscreen(true));
  full.set_instrument(pose, angle);
  const auto sharp = full.capture();
  view::ViewOptions options = offscreen(true);
  options.render_scale = 0.5;
  view::EndoscopicView half(patient.scenario, patient.package, options);
  half.set_instrument(pose, angle);
  const auto soft = half.capture();
  int dims[3];
  soft->GetDimensions(dims);
  EXPECT_EQ(dims[0], 640) << "the output keeps the view's size";
  EXPECT_EQ(dims[1], 360);
  // The same field, organ and brightness; only fine detail differs.
  const FrameStatistics a = frame_statistics(sharp, 0.9), b = frame_statistics(soft, 0.9);
  EXPECT_GT(b.lit_fraction, 0.8);
  EXPECT_NEAR(b.mean_luminance, a.mean_luminance, 0.05 * a.mean_luminance);
  EXPECT_LT(testing::corner_luminance(soft), 1.0);
  const double difference = testing::mean_abs_difference(sharp, soft, 0.9);
  EXPECT_GT(difference, 0.0) << "a quarter of the pixels cannot give the identical image";
  EXPECT_LT(difference, 6.0);
  // Rendering the same pose twice gives the same bytes (no state carried between frames).
  EXPECT_EQ(testing::mean_abs_difference(soft, half.capture()), 0.0);
  // A quarter-resolution scene is composited at half resolution and stretched onto the view:
  // the same picture again, softer, at the view's size, black outside the field.
  half.set_render_scale(0.25);
  const auto quarter = half.capture();
  quarter->GetDimensions(dims);
  EXPECT_EQ(dims[0], 640);
  EXPECT_EQ(dims[1], 360);
  const FrameStatistics c = frame_statistics(quarter, 0.9);
  EXPECT_GT(c.lit_fraction, 0.8);
  EXPECT_NEAR(c.mean_luminance, a.mean_luminance, 0.08 * a.mean_luminance);
  EXPECT_LT(testing::corner_luminance(quarter), 1.0);
  const double coarser = testing::mean_abs_difference(sharp, quarter, 0.9);
  EXPECT_GT(coarser, difference);
  EXPECT_LT(coarser, 9.0);
}

/// The view's input at the patient's starting pose, through its angled optics.
sim::SessionSnapshot starting_snapshot(const core::Scenario& scenario) {
  sim::SessionSnapshot snapshot;
  snapshot.optics_angle = scenario.session.instrument.optics_angle;
  snapshot.instrument = sim::starting_pose(scenario, snapshot.optics_angle);
  return snapshot;
}

/// The hysteroscopy patient through the lens pass from its starting pose: the view, its input,
/// and the clear picture with its statistics, for tests that put something in front of it.
struct ClearStartingView {
  const testing::Patient& patient = testing::hysteroscopy_patient();
  view::EndoscopicView view{patient.scenario, patient.package, offscreen(true)};
  sim::SessionSnapshot snapshot = starting_snapshot(patient.scenario);
  vtkSmartPointer<vtkImageData> clear;
  FrameStatistics before;

  ClearStartingView() {
    view.update(snapshot);
    clear = view.capture();
    before = frame_statistics(clear, 0.9);
  }
  /// Shows the snapshot again (with what a test put in front taken out): the clear picture.
  void expect_the_clear_picture_again() {
    view.update(snapshot);
    EXPECT_LT(testing::mean_abs_difference(clear, view.capture(), 0.9), 0.5);
  }
  /// The point `distance` m ahead of the lens along the optics' line of sight.
  core::Vec3 ahead(double distance) const {
    return snapshot.instrument.tip +
           distance * sim::view_direction(snapshot.instrument, snapshot.optics_angle);
  }
};

TEST(EndoscopicView, blood_in_the_flow_shows_as_billboards_and_clouds_the_lens) {
  // Issue 18 §5: a cloud of fresh blood particles in front of the optics, then the haze of
  // blood mixed into the fluid. Both turn the picture towards red and darken it.
  ClearStartingView start;
  auto& [patient, view, snapshot, clear, before] = start;
  // 2,000 fresh drops in a 4 mm ball 8 mm ahead of the lens.
  const core::Vec3 ahead = start.ahead(0.008);
  std::uint64_t state = 12345;
  const auto uniform = [&state] {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<double>(state >> 11) / 9007199254740992.0 * 2.0 - 1.0;
  };
  while (snapshot.blood.size() < 2000) {
    const core::Vec3 offset(uniform(), uniform(), uniform());
    if (offset.norm() > 1.0) continue;
    snapshot.blood.push_back(ahead + 0.002 * offset);
    snapshot.blood_stage.push_back(0.1f);
  }
  view.update(snapshot);
  EXPECT_EQ(view.blood().size(), 2000u);
  const FrameStatistics drops = frame_statistics(view.capture(), 0.9);
  EXPECT_GT(drops.chromaticity[0], before.chromaticity[0] + 0.03);
  EXPECT_GT(testing::mean_abs_difference(clear, view.capture(), 0.9), 2.0);

  // The haze alone: 200 /m (e.g. 4 % blood at the k = 5,000 /m) over the cavity.
  snapshot.blood.clear();
  snapshot.blood_stage.clear();
  snapshot.haze_density = 200.0;
  view.update(snapshot);
  EXPECT_DOUBLE_EQ(view.haze_density(), 200.0);
  const FrameStatistics haze = frame_statistics(view.capture(), 0.9);
  EXPECT_GT(haze.chromaticity[0], before.chromaticity[0] + 0.03);
  EXPECT_LT(haze.mean_luminance, before.mean_luminance);
  // Clear fluid again: the picture comes back exactly.
  snapshot.haze_density = 0.0;
  start.expect_the_clear_picture_again();
}

TEST(EndoscopicView, coagulation_smoke_veils_the_picture_and_a_steamed_lens_blurs_it) {
  // Issue 19 §4: a column of smoke puffs rising in front of the optics greys the picture and
  // flattens its contrast; a steamed lens blurs and veils it; both go when they are gone.
  ClearStartingView start;
  auto& [patient, view, snapshot, clear, before] = start;
  sim::SurgicalSmoke smoke;
  const core::Vec3 ahead = start.ahead(0.012);
  const core::Vec3 up = snapshot.instrument.up;
  for (int k = 1; k <= 2000; ++k)  // 2 s of coagulation, 1 ms steps
    smoke.step(0.001 * k, 0.001, ahead - 0.01 * up, up, snapshot.instrument.tip - 0.1 * up);
  snapshot.smoke = smoke.billboards();
  ASSERT_GT(snapshot.smoke.size(), 30u);
  view.update(snapshot);
  EXPECT_EQ(view.smoke().size(), snapshot.smoke.size());
  const FrameStatistics smoky = frame_statistics(view.capture(), 0.9);
  EXPECT_GT(testing::mean_abs_difference(clear, view.capture(), 0.9), 2.0);
  // Towards grey: the red of the tissue loses its share.
  EXPECT_LT(smoky.chromaticity[0], before.chromaticity[0] - 0.01);

  snapshot.smoke.clear();
  snapshot.lens_fog = 0.8;
  view.update(snapshot);
  EXPECT_DOUBLE_EQ(view.lens_fog(), 0.8);
  const FrameStatistics fogged = frame_statistics(view.capture(), 0.9);
  EXPECT_LT(fogged.luminance_stddev, before.luminance_stddev);
  EXPECT_LT(fogged.chromaticity[0], before.chromaticity[0] - 0.01);
  snapshot.lens_fog = 0.0;
  start.expect_the_clear_picture_again();
}

TEST(EndoscopicView, air_bubbles_and_irrigation_drops_show_as_pale_particles) {
  // Seed 000 §7 (bubbles) and issue 19 §3 (the jet): pale sprites in front of the optics lift
  // the blue share of the reddish picture; without them it comes back exactly.
  ClearStartingView start;
  auto& [patient, view, snapshot, clear, before] = start;
  const core::Vec3 ahead = start.ahead(0.008);
  const core::Vec3 side = snapshot.instrument.up.cross(snapshot.instrument.axis).normalized();
  for (int a = -10; a <= 10; ++a)
    for (int b = -10; b <= 10; ++b) {
      const core::Vec3 at = ahead + 0.0002 * (a * side + b * snapshot.instrument.up);
      ((a + b) % 2 == 0 ? snapshot.bubbles : snapshot.irrigation_drops).push_back(at);
      ((a + b) % 2 == 0 ? snapshot.bubble_size : snapshot.irrigation_drop_age).push_back(0.5f);
    }
  view.update(snapshot);
  EXPECT_EQ(view.bubbles().size(), snapshot.bubbles.size());
  EXPECT_EQ(view.irrigation_drops().size(), snapshot.irrigation_drops.size());
  const FrameStatistics pale = frame_statistics(view.capture(), 0.9);
  EXPECT_GT(testing::mean_abs_difference(clear, view.capture(), 0.9), 1.0);
  EXPECT_GT(pale.chromaticity[2], before.chromaticity[2] + 0.01);
  snapshot.bubbles.clear();
  snapshot.bubble_size.clear();
  snapshot.irrigation_drops.clear();
  snapshot.irrigation_drop_age.clear();
  start.expect_the_clear_picture_again();
}

TEST(EndoscopicView, coagulated_tissue_darkens_towards_brown_where_its_nodes_are) {
  // Issue 19 §3: the bipolar forceps' coagulated knots change the tissue's colour. Every body
  // at rest with its nodes coagulated: the picture darkens and loses red to the brown tint;
  // with no node coagulated it comes back exactly.
  ClearStartingView start;
  auto& [patient, view, snapshot, clear, before] = start;
  for (const core::SceneObject& object : patient.scenario.objects) {
    if (object.body.nodes.empty()) continue;
    sim::BodyPositions body;
    body.name = object.id;
    body.positions = object.body.nodes;
    body.coagulated.assign(object.body.nodes.size(), 1.0f);
    snapshot.bodies.push_back(std::move(body));
  }
  ASSERT_FALSE(snapshot.bodies.empty());
  view.update(snapshot);
  const FrameStatistics burnt = frame_statistics(view.capture(), 0.9);
  EXPECT_LT(burnt.mean_luminance, 0.8 * before.mean_luminance);
  EXPECT_GT(testing::mean_abs_difference(clear, view.capture(), 0.9), 5.0);
  for (sim::BodyPositions& body : snapshot.bodies)
    body.coagulated.clear();
  start.expect_the_clear_picture_again();
}

TEST(EndoscopicView, the_pool_shows_as_a_translucent_surface_tinted_by_its_blood) {
  // Issue 19 §3: a pool across the line of sight veils the tissue; a bloody pool reddens the
  // picture more than a clear one; without a pool the picture comes back exactly.
  ClearStartingView start;
  auto& [patient, view, snapshot, clear, before] = start;
  snapshot.pool_centre = start.ahead(0.006);
  snapshot.pool_up = (snapshot.instrument.tip - snapshot.pool_centre).normalized();
  snapshot.pool_radius = 0.03;
  snapshot.pool_blood_fraction = 0.0;
  view.update(snapshot);
  EXPECT_TRUE(view.pool().visible());
  const FrameStatistics water = frame_statistics(view.capture(), 0.9);
  EXPECT_GT(testing::mean_abs_difference(clear, view.capture(), 0.9), 5.0);
  // Waves (fluid::PoolWaves' elevations at the mesh's vertices) lift and lower the surface by
  // what they say and move its highlight; a flat field draws the flat pool.
  const auto flat = view.capture();
  constexpr int kRings = sim::SessionSnapshot::kPoolRings,
                kSides = sim::SessionSnapshot::kPoolSides;
  snapshot.pool_waves.assign(1 + kRings * kSides, 0.0f);
  for (int k = 1; k <= kRings; ++k)
    for (int side = 0; side < kSides; ++side)
      snapshot.pool_waves[static_cast<std::size_t>(1 + (k - 1) * kSides + side)] =
          static_cast<float>(0.002 * std::sin(std::numbers::pi * k / 2.0) *
                             std::cos(6.0 * std::numbers::pi * side / kSides));
  view.update(snapshot);
  EXPECT_NEAR(view.pool().relief(), 0.004, 1e-6);
  EXPECT_GT(testing::mean_abs_difference(flat, view.capture(), 0.9), 0.5);
  std::fill(snapshot.pool_waves.begin(), snapshot.pool_waves.end(), 0.0f);
  view.update(snapshot);
  EXPECT_EQ(view.pool().relief(), 0.0);
  EXPECT_LT(testing::mean_abs_difference(flat, view.capture(), 0.9), 0.01);
  snapshot.pool_waves.clear();
  snapshot.pool_blood_fraction = 1.0;
  view.update(snapshot);
  const FrameStatistics blood = frame_statistics(view.capture(), 0.9);
  EXPECT_GT(blood.chromaticity[0], water.chromaticity[0] + 0.05);
  snapshot.pool_radius = 0.0;
  view.update(snapshot);
  EXPECT_FALSE(view.pool().visible());
  EXPECT_LT(testing::mean_abs_difference(clear, view.capture(), 0.9), 0.5);
}

TEST(EndoscopicView, the_second_ports_tool_shows_in_front_of_the_optics) {
  // Issue 19 §3: the left hand's grasper, in from the side, its jaws 15 mm ahead of the lens,
  // darkens part of the picture as steel does; taken out, the picture comes back exactly.
  ClearStartingView start;
  auto& [patient, view, snapshot, clear, before] = start;
  const core::Vec3 view_line = sim::view_direction(snapshot.instrument, snapshot.optics_angle);
  sim::SecondPort& left = snapshot.instrument.second;
  left.inserted = true;
  left.tool = sim::LaparoscopicTool::Grasper;
  left.tip = start.ahead(0.015);
  left.axis = (view_line + view_line.unitOrthogonal()).normalized();
  left.up = view_line.cross(left.axis).normalized();
  view.update(snapshot);
  EXPECT_TRUE(view.left_tool().visible());
  const auto open = view.capture();
  EXPECT_GT(testing::mean_abs_difference(clear, open, 0.9), 2.0);
  left.jaws_closed = true;  // the jaws close: a different picture
  view.update(snapshot);
  EXPECT_GT(testing::mean_abs_difference(open, view.capture(), 0.9), 0.05);
  left = sim::SecondPort{};
  view.update(snapshot);
  EXPECT_FALSE(view.left_tool().visible());
  start.expect_the_clear_picture_again();
}

TEST(EndoscopicView, a_laparoscope_held_apart_shows_the_working_ports_tool_from_where_it_is) {
  // Issue 19 §3: with the laparoscope held apart the camera stays where it is held, and the
  // working port's tool, brought 15 mm ahead of the lens from the side, is drawn as steel; given
  // back, the optics are at the tool's tip again.
  ClearStartingView start;
  auto& [patient, view, snapshot, clear, before] = start;
  sim::InstrumentState& state = snapshot.instrument;
  const sim::InstrumentState optics = state;
  state.camera = {true, optics.tip, optics.axis, optics.up};
  view.update(snapshot);
  EXPECT_TRUE(view.right_tool().visible());  // its jaws reach the lens: the tip is at it
  const core::Vec3 view_line = sim::view_direction(optics, snapshot.optics_angle);
  state.tool = sim::LaparoscopicTool::Grasper;
  state.tip = start.ahead(0.015);
  state.axis = (view_line - view_line.unitOrthogonal()).normalized();
  state.up = view_line.cross(state.axis).normalized();
  view.update(snapshot);
  core::Vec3 eye;
  view.scene_renderer()->GetActiveCamera()->GetPosition(eye.data());
  EXPECT_LT((eye - optics.tip).norm(), 1e-12);  // the camera did not follow the tool
  EXPECT_TRUE(view.right_tool().visible());
  EXPECT_GT(testing::mean_abs_difference(clear, view.capture(), 0.9), 2.0);
  // The camera drawn back 5 mm along its shaft sees the scene from further away.
  state.tip = optics.tip;
  state.axis = optics.axis;
  state.up = optics.up;
  state.camera.tip = optics.tip - 0.005 * optics.axis;
  view.update(snapshot);
  view.scene_renderer()->GetActiveCamera()->GetPosition(eye.data());
  EXPECT_LT((eye - state.camera.tip).norm(), 1e-12);
  // Given back: the optics are the tool's again and the tool runs along them, out of view.
  state = optics;
  view.update(snapshot);
  EXPECT_FALSE(view.right_tool().visible());
  start.expect_the_clear_picture_again();
}

TEST(SessionOverlay, force_bars_fill_and_warn_as_the_force_nears_the_limit) {
  EXPECT_EQ(view::force_alert(0.5, 1.0), "");
  EXPECT_EQ(view::force_alert(0.9, 1.0), "approaching");
  EXPECT_EQ(view::force_alert(1.2, 1.0), "excessive");
  EXPECT_EQ(view::force_alert(5.0, 0.0), "") << "no warning level, no warning";
  view::SessionOverlay overlay("");
  view::OverlayState state;
  state.force = core::Vec3(0.3, 0.0, -0.4);
  state.force_warning = 1.0;
  state.elapsed = 12.5;
  state.tip = core::Vec3(0.001, 0.002, 0.003);
  overlay.update(state);
  EXPECT_NEAR(overlay.bar_fill()[0], 0.3 / 1.5, 1e-12);
  EXPECT_NEAR(overlay.bar_fill()[2], 0.4 / 1.5, 1e-12);
  EXPECT_NEAR(overlay.bar_fill()[3], 0.5 / 1.5, 1e-12);
  EXPECT_EQ(overlay.warning_text(), "");
  EXPECT_NE(overlay.info_text().find("12.5 s"), std::string::npos) << overlay.info_text();
  EXPECT_NE(overlay.info_text().find("+1.0   +2.0   +3.0 mm"), std::string::npos)
      << overlay.info_text();
  state.force = core::Vec3(0.0, 0.0, 1.3);
  overlay.update(state);
  EXPECT_NE(overlay.warning_text().find("EXCESSIVE"), std::string::npos);
}

TEST(SessionOverlay, lays_its_numbers_out_ten_times_a_second_and_its_tool_lines_at_once) {
  view::SessionOverlay overlay("");
  view::OverlayState state;
  state.elapsed = 1.0;
  state.force = core::Vec3(0.0, 0.0, 0.25);
  overlay.update(state);
  EXPECT_NE(overlay.info_text().find("0.25 N"), std::string::npos) << overlay.info_text();
  state.elapsed = 1.05;  // within 0.1 s of session time: the numbers stay, the bars move
  state.force = core::Vec3(0.0, 0.0, 0.5);
  overlay.update(state);
  EXPECT_NE(overlay.info_text().find("0.25 N"), std::string::npos) << overlay.info_text();
  EXPECT_DOUBLE_EQ(overlay.bar_fill()[3], 0.25);
  state.tool = "grasper";  // a tool line changes: laid out at once
  overlay.update(state);
  EXPECT_NE(overlay.info_text().find("0.50 N"), std::string::npos) << overlay.info_text();
  state.elapsed = 1.1;
  state.force = core::Vec3(0.0, 0.0, 0.75);
  overlay.update(state);
  EXPECT_NE(overlay.info_text().find("0.50 N"), std::string::npos) << overlay.info_text();
  state.elapsed = 1.151;
  overlay.update(state);
  EXPECT_NE(overlay.info_text().find("0.75 N"), std::string::npos) << overlay.info_text();
}

TEST(SessionOverlay, shows_the_suction_irrigation_cannulas_valves_and_the_pool) {
  view::SessionOverlay overlay("");
  view::OverlayState state;
  state.tool = "suction";
  state.irrigating = true;
  state.pool_ml = 12.4;
  state.pool_blood_fraction = 0.05;
  overlay.update(state);
  EXPECT_NE(overlay.info_text().find("suction off, irrigation on"), std::string::npos)
      << overlay.info_text();
  EXPECT_NE(overlay.info_text().find("pool 12 ml (5 % blood)"), std::string::npos)
      << overlay.info_text();
  state.tool = "grasper";
  state.jaws_closed = true;
  state.pool_ml = 0.0;
  overlay.update(state);
  EXPECT_NE(overlay.info_text().find("grasper, jaws closed"), std::string::npos);
  EXPECT_EQ(overlay.info_text().find("pool"), std::string::npos);
  EXPECT_EQ(overlay.info_text().find("Left"), std::string::npos);
  state.left_tool = "bipolar";  // the second port's tool
  overlay.update(state);
  EXPECT_NE(overlay.info_text().find("Left    bipolar, jaws open"), std::string::npos)
      << overlay.info_text();
}

}  // namespace
}  // namespace viscera
