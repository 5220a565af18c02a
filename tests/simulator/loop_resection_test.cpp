// The resection loop in a session (issue 17 §1, §4, §5): on the hysteroscopy template with a
// resectoscope, a pedal-down sweep that scoops the polyp's apex cuts it once the loop has left
// the tissue; the chip is free, the mesh stays sound, volume is kept and the run replays.

#include "simulator/session/loop_resection.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <numbers>

#include "core/json_schema/json_schema_validator.h"
#include "core/mesh/surface_embedding.h"
#include "simulator/dynamics/attachment_term.h"
#include "simulator/dynamics/fluid_drag.h"
#include "simulator/runtime/session_snapshot.h"
#include "simulator/session/instrument_input.h"
#include "simulator/session/session_runner.h"
#include "templates/template_catalog.h"
#include "tests/support/polyp_scoop.h"
#include "tests/support/test_paths.h"

namespace viscera::sim {
namespace {

using testing::frame_of;
using testing::kRadius;
using testing::polyp_frame;
using testing::PolypFrame;
using testing::resectoscope_patient;
using testing::scoop_script;

/// The scoop, then the loop back over the cut's centre with the coagulation pedal down from
/// `coagulate_from` s for 0.3 s.
nlohmann::json scoop_and_coagulate_script(const PolypFrame& f, double depth,
                                          double coagulate_from) {
  nlohmann::json script = scoop_script(f, depth);
  const core::Vec3 centre = f.apex + (kRadius - depth) * f.axis;
  const nlohmann::json tip = {centre.x(), centre.y(), centre.z()};
  auto& points = script["waypoints"];
  points.erase(points.size() - 1);  // the final rest
  points.push_back({{"t", coagulate_from - 0.1}, {"tip", tip}});
  points.push_back({{"t", coagulate_from}, {"tip", tip}, {"coagulate", 1}});
  points.push_back({{"t", coagulate_from + 0.3}, {"tip", tip}, {"coagulate", 0}});
  points.push_back({{"t", 1.5}, {"tip", tip}});
  return script;
}

struct ScoopRun {
  SessionReport report;
  std::vector<core::Vec3> polyp_at_release, polyp_at_end;
  int everted_at_end = -1;
};

ScoopRun run(const core::Scenario& scenario, const nlohmann::json& script) {
  const auto input = ScriptedTrajectory::from_json(script, "scoop", 30.0);
  HeadlessRunOptions options;
  options.duration = 1.5;
  options.instrument = &input;
  options.instrument_body = "uterus";
  SessionRunner runner(scenario, options);
  ScoopRun r;
  const int polyp = runner.world().body_index("polyp-1");
  while (!runner.finished()) {
    runner.step(input.state(runner.world().steps() + 1, runner.world().time()));
    const auto x = runner.world().state().range(runner.world().state().positions, polyp);
    if (std::abs(runner.world().time() - 0.73) < 5e-4)
      r.polyp_at_release.assign(x.begin(), x.end());
  }
  const auto x = runner.world().state().range(runner.world().state().positions, polyp);
  r.polyp_at_end.assign(x.begin(), x.end());
  r.everted_at_end = runner.world().everted_tets();
  r.report = runner.finish();
  return r;
}

TEST(LoopResection, a_sweep_across_the_polyp_apex_scoops_a_chip_that_then_moves_freely) {
  const core::Scenario scenario = resectoscope_patient();
  const PolypFrame frame = frame_of(scenario);
  ASSERT_GE(frame.body, 0);
  const ScoopRun r = run(scenario, scoop_script(frame, 2.0e-3));
  ASSERT_TRUE(r.report.cutting.has_value());
  const CuttingSummary& c = *r.report.cutting;
  EXPECT_EQ(c.sweeps, 1);
  EXPECT_EQ(c.released_in_tissue, 0);
  ASSERT_GE(c.cuts, 1);
  EXPECT_GT(c.tets_created, 0);
  EXPECT_GE(c.min_dihedral_after_degrees, 1.0);
  EXPECT_NEAR(c.volume_after, c.volume_before, 1e-9 * c.volume_before);
  const auto polyp = std::find_if(c.bodies.begin(), c.bodies.end(),
                                  [](const auto& b) { return b.body == "polyp-1"; });
  ASSERT_NE(polyp, c.bodies.end());
  EXPECT_GE(polyp->chips, 1);
  EXPECT_GT(polyp->resected_fraction(), 0.01);
  EXPECT_LT(polyp->resected_fraction(), 0.9);  // the apex, not the whole polyp
  // Sound afterwards: no inverted tet, finite energy, and the chip moved away from where it was
  // cut (it is free: gravity, the flow of the wall and contact move it).
  EXPECT_EQ(r.everted_at_end, 0);
  for (const auto& s : r.report.samples)
    EXPECT_TRUE(std::isfinite(s.total()));
  ASSERT_EQ(r.polyp_at_release.size(), r.polyp_at_end.size());
  double moved = 0.0;
  for (std::size_t i = 0; i < r.polyp_at_end.size(); ++i)
    moved = std::max(moved, (r.polyp_at_end[i] - r.polyp_at_release[i]).norm());
  EXPECT_GT(moved, 1e-4);
  const auto cut_event = std::find_if(r.report.events.begin(), r.report.events.end(),
                                      [](const auto& e) { return e.kind == "cut"; });
  EXPECT_NE(cut_event, r.report.events.end());
}

TEST(LoopResection, the_same_sweep_replays_to_the_same_state) {
  const core::Scenario scenario = resectoscope_patient();
  const auto script = scoop_script(frame_of(scenario), 2.0e-3);
  const ScoopRun a = run(scenario, script), b = run(scenario, script);
  EXPECT_EQ(a.report.final_state_hash, b.report.final_state_hash);
  EXPECT_EQ(a.report.checkpoints, b.report.checkpoints);
}

TEST(LoopResection, a_sweep_that_bleeds_replays_to_the_same_blood_and_fluid) {
  const core::Scenario scenario =
      templates::build_from_template("hysteroscopy", {{"pathology_artery_radius", "0.0003"}}, 1);
  core::Scenario resectoscope = scenario;
  resectoscope.session.instrument.kind = "resectoscope";
  const auto script = scoop_script(frame_of(resectoscope), 2.0e-3);
  const ScoopRun a = run(resectoscope, script), b = run(resectoscope, script);
  ASSERT_TRUE(a.report.bleeding.has_value() && b.report.bleeding.has_value());
  ASSERT_FALSE(a.report.bleeding->empty());
  EXPECT_EQ(a.report.final_state_hash, b.report.final_state_hash);
  ASSERT_EQ(a.report.bleeding->size(), b.report.bleeding->size());
  for (std::size_t i = 0; i < a.report.bleeding->size(); ++i) {
    EXPECT_EQ((*a.report.bleeding)[i].bled, (*b.report.bleeding)[i].bled);  // bit for bit
    EXPECT_EQ((*a.report.bleeding)[i].intravasated, (*b.report.bleeding)[i].intravasated);
  }
  EXPECT_EQ(a.report.fluid->bled, b.report.fluid->bled);
  EXPECT_EQ(a.report.final_cavity_pressure, b.report.final_cavity_pressure);
  // The flow that carries the blood replays too: the same particles, field and clouding.
  ASSERT_TRUE(a.report.cavity_flow.has_value() && b.report.cavity_flow.has_value());
  const CavityFlowSummary &fa = *a.report.cavity_flow, &fb = *b.report.cavity_flow;
  EXPECT_GT(fa.blood_released, 0.0);
  EXPECT_EQ(fa.blood_in_cavity, fb.blood_in_cavity);
  EXPECT_EQ(fa.blood_drained, fb.blood_drained);
  EXPECT_EQ(fa.particles, fb.particles);
  EXPECT_EQ(fa.lowest_transmission, fb.lowest_transmission);
  EXPECT_EQ(fa.view_obscured_time, fb.view_obscured_time);
}

TEST(LoopResection, a_scoop_through_the_polyps_feeding_artery_bleeds_and_the_balance_holds) {
  // The template's feeding artery (r 0.3 mm) up the polyp's axis from its base: the scoop 2 mm
  // below the apex opens it (issue 18 §3). Blood enters the cavity through the opened artery
  // and the cut surface, and the distension balance keeps every volume.
  core::Scenario scenario =
      templates::build_from_template("hysteroscopy", {{"pathology_artery_radius", "0.0003"}}, 1);
  scenario.session.instrument.kind = "resectoscope";
  const PolypFrame frame = frame_of(scenario);
  const ScoopRun r = run(scenario, scoop_script(frame, 2.0e-3));
  ASSERT_GE(r.report.cutting->cuts, 1);
  ASSERT_TRUE(r.report.bleeding.has_value());
  const auto& sources = *r.report.bleeding;
  const auto vessel =
      std::find_if(sources.begin(), sources.end(), [](const auto& s) { return !s.capillary; });
  ASSERT_NE(vessel, sources.end());
  EXPECT_EQ(vessel->vessel_tree, "polyp-1-artery");
  EXPECT_DOUBLE_EQ(vessel->radius, 0.0003);
  EXPECT_EQ(vessel->stop, fluid::BleedingStop::Bleeding);  // nothing stopped it
  EXPECT_GT(vessel->bled, 0.0);
  EXPECT_TRUE(
      std::any_of(sources.begin(), sources.end(), [](const auto& s) { return s.capillary; }));
  // The artery bled at its Poiseuille rate against the cavity's pressure: no more than the
  // rate into an empty cavity over the time since the cut.
  const double since_cut = r.report.simulated_time - vessel->opened_at;
  EXPECT_LT(vessel->bled, vessel->conductance * vessel->pressure * since_cut * (1 + 1e-9));
  EXPECT_GT(vessel->bled, 0.1 * vessel->conductance * vessel->pressure * since_cut);
  const auto opened = std::find_if(r.report.events.begin(), r.report.events.end(),
                                   [](const auto& e) { return e.kind == "vessel-opened"; });
  EXPECT_NE(opened, r.report.events.end());

  ASSERT_TRUE(r.report.fluid.has_value());
  const FluidTotals& f = *r.report.fluid;
  double bled = 0.0;
  for (const auto& s : sources)
    bled += s.bled;
  EXPECT_NEAR(f.bled, bled, 1e-12 * bled);
  // Every drop that bled went into the cavity's flow, and the flow accounts for all of it.
  ASSERT_TRUE(r.report.cavity_flow.has_value());
  const CavityFlowSummary& flow = *r.report.cavity_flow;
  EXPECT_GT(flow.flow_steps, 0);
  EXPECT_NEAR(flow.blood_released, bled, 1e-12 * bled);
  EXPECT_NEAR(flow.blood_in_cavity + flow.blood_drained + flow.blood_lost, flow.blood_released,
              1e-9 * bled);
  EXPECT_GT(flow.blood_in_cavity, 0.0);
  // The report's bleeding and fluid blocks follow the published schema.
  std::ifstream schema_file(viscera::testing::source_dir() / "docs" / "session-report.schema.json");
  const core::JsonSchemaValidator schema(nlohmann::json::parse(schema_file));
  const nlohmann::json json = report_to_json(r.report);
  for (const auto& violation : schema.validate(json))
    ADD_FAILURE() << violation.pointer << ": " << violation.message;
  EXPECT_GT(json["bleeding"]["blood_loss"].get<double>(), 0.0);
  EXPECT_GT(json["fluid_series"]["bled"].back().get<double>(), 0.0);

  const double compliance = DistensionChannels{}.cavity_compliance;
  const double retained = compliance * r.report.final_cavity_pressure;
  EXPECT_NEAR(f.used + f.bled - f.drained - f.absorbed - f.intravasated, retained,
              1e-9 * (f.used + f.bled));
}

TEST(LoopResection, the_coagulation_pedal_over_the_cut_seals_the_artery_and_stops_its_pulse) {
  core::Scenario scenario =
      templates::build_from_template("hysteroscopy", {{"pathology_artery_radius", "0.0003"}}, 1);
  scenario.session.instrument.kind = "resectoscope";
  // The polyp's artery pulses (a gentle 2 mN wave): coagulating it must stop the wave there.
  const auto tree = std::find_if(scenario.vessel_trees.begin(), scenario.vessel_trees.end(),
                                 [](const auto& t) { return t.id == "polyp-1-artery"; });
  ASSERT_NE(tree, scenario.vessel_trees.end());
  scenario.active_deformations.push_back(
      {"polyp-pulse", tree->host_object, core::PulseSpec{tree->id, 70.0, 5.0, 0.002}});
  const PolypFrame frame = frame_of(scenario);
  const ScoopRun open = run(scenario, scoop_script(frame, 2.0e-3));
  const ScoopRun sealed = run(scenario, scoop_and_coagulate_script(frame, 2.0e-3, 1.0));
  const auto artery = [](const ScoopRun& r) {
    for (const auto& s : *r.report.bleeding)
      if (!s.capillary) return s;
    throw std::runtime_error("no artery was opened");
  };
  EXPECT_EQ(artery(open).stop, fluid::BleedingStop::Bleeding);
  const fluid::BleedingSource a = artery(sealed);
  EXPECT_EQ(a.stop, fluid::BleedingStop::Coagulated);
  EXPECT_GE(a.stopped_at, 1.0);
  EXPECT_LE(a.stopped_at, 1.3);
  // It bled the same until the pedal and nothing after: less than the open artery's whole run.
  EXPECT_LT(a.bled, artery(open).bled);
  EXPECT_GT(a.bled, 0.0);
  const auto event = std::find_if(sealed.report.events.begin(), sealed.report.events.end(),
                                  [](const auto& e) { return e.kind == "coagulated"; });
  EXPECT_NE(event, sealed.report.events.end());
  const auto stopped_pulse = [](const ScoopRun& r) {
    return std::find_if(r.report.events.begin(), r.report.events.end(),
                        [](const auto& e) { return e.kind == "pulse-stopped"; });
  };
  ASSERT_NE(stopped_pulse(sealed), sealed.report.events.end());
  EXPECT_EQ(stopped_pulse(sealed)->time, a.stopped_at);
  EXPECT_EQ(stopped_pulse(open), open.report.events.end());
  const nlohmann::json json = report_to_json(sealed.report);
  EXPECT_GE(json["bleeding"]["controlled"].get<int>(), 1);
  EXPECT_TRUE(json["bleeding"]["mean_time_to_control"].is_number());
}

TEST(LoopResection, a_pedal_released_inside_the_polyp_cuts_nothing) {
  const core::Scenario scenario = resectoscope_patient();
  const PolypFrame frame = frame_of(scenario);
  // Released half-way across: the loop is still in the tissue.
  const ScoopRun r = run(scenario, scoop_script(frame, 2.0e-3, 0.5));
  ASSERT_TRUE(r.report.cutting.has_value());
  EXPECT_EQ(r.report.cutting->cuts, 0);
  EXPECT_EQ(r.report.cutting->released_in_tissue, 1);
  EXPECT_EQ(r.report.cutting->tets_created, 0);
}

TEST(LoopResection, a_diagnostic_hysteroscope_has_no_loop) {
  core::Scenario scenario = resectoscope_patient();
  scenario.session.instrument.kind = "hysteroscope";
  const ScoopRun r = run(scenario, scoop_script(frame_of(scenario), 2.0e-3));
  EXPECT_FALSE(r.report.cutting.has_value());
}

TEST(LoopResection, the_loop_hangs_towards_the_optics_view_across_the_shaft) {
  InstrumentState s;
  s.tip = core::Vec3(0.01, 0.0, 0.0);
  s.axis = core::Vec3::UnitX();
  s.up = core::Vec3::UnitZ();
  const cutting::LoopPose pose = loop_pose(s);
  EXPECT_TRUE(pose.rotation.isUnitary(1e-12));
  EXPECT_NEAR(pose.rotation.determinant(), 1.0, 1e-12);
  const auto points = cutting::loop_points(standard_resection_loop(), pose);
  // The arc's middle point lies one radius from the tip on the up side, in the plane across
  // the shaft.
  const core::Vec3 middle = points[points.size() / 2];
  EXPECT_NEAR((middle - (s.tip + kRadius * s.up)).norm(), 0.0, 1e-12);
  for (const auto& p : points)
    EXPECT_NEAR((p - s.tip).dot(s.axis), 0.0, 1e-12);
}

TEST(LoopResection, the_cut_polyp_shows_its_inside_on_its_visible_surface) {
  // Issue 17 §2: the polyp's visible surface is cut with its tets; the faces the cut opened
  // are part of it, each vertex follows a tet of the cut body, and the view's snapshot carries
  // the surface without copying it.
  const core::Scenario scenario = resectoscope_patient();
  const auto input =
      ScriptedTrajectory::from_json(scoop_script(frame_of(scenario), 2.0e-3), "scoop", 30.0);
  HeadlessRunOptions options;
  options.duration = 1.0;
  options.instrument = &input;
  options.instrument_body = "uterus";
  SessionRunner runner(scenario, options);
  const int polyp = runner.world().body_index("polyp-1");
  ASSERT_NE(runner.visible_surfaces(), nullptr);
  EXPECT_EQ(runner.visible_surfaces()->cut_surface(polyp), nullptr);
  while (!runner.finished())
    runner.step(input.state(runner.world().steps() + 1, runner.world().time()));
  const auto& cut = runner.visible_surfaces()->cut_surface(polyp);
  ASSERT_NE(cut, nullptr);
  const core::TetMesh& body = runner.world().models()[static_cast<std::size_t>(polyp)]->mesh;
  EXPECT_EQ(cut->tets, body.tets);
  ASSERT_EQ(cut->embedding.tet.size(), cut->mesh.vertices.size());
  const core::SceneObject& object = *scenario.find_object("polyp-1");
  EXPECT_GT(cut->mesh.triangles.size(), object.surface.triangles.size());
  // The cut faces: vertices flagged, at their material points, and embedded where they are.
  const auto& flag = cut->mesh.vertex_attributes.at("cut_face");
  const auto rest = core::embedded_positions(cut->embedding, cut->tets, body.nodes);
  std::size_t opened = 0;
  for (const core::Triangle& t : cut->mesh.triangles)
    opened += flag[static_cast<std::size_t>(t[0])] == 1.0 &&
              flag[static_cast<std::size_t>(t[1])] == 1.0 &&
              flag[static_cast<std::size_t>(t[2])] == 1.0;
  EXPECT_GT(opened, 0u);
  for (std::size_t v = 0; v < cut->mesh.vertices.size(); ++v) {
    ASSERT_LT(cut->embedding.tet[v], static_cast<int>(body.tets.size()));
    if (flag[v] == 1.0) {
      EXPECT_LT((rest[v] - cut->mesh.vertices[v]).norm(), 1e-9) << v;
    }
  }
  // The flow carries the chips: the fluid's drag holds every chip node (chip_drift.h).
  const FluidDrag* drag = nullptr;
  for (const auto& term : runner.world().terms())
    if (const auto* d = dynamic_cast<const FluidDrag*>(term.get())) drag = d;
  ASSERT_NE(drag, nullptr);
  std::size_t chip_nodes = 0;
  for (const Chip& chip : runner.resection()->chips())
    chip_nodes += chip.nodes.size();
  EXPECT_GT(chip_nodes, 0u);
  EXPECT_EQ(drag->drag().size(), chip_nodes);
  for (const NodeDrag& d : drag->drag())
    EXPECT_GT(d.coefficient, 0.0);
  SessionSnapshot snapshot;
  capture_snapshot(runner, snapshot);
  EXPECT_EQ(snapshot.bodies[static_cast<std::size_t>(polyp)].cut_surface, cut);
  EXPECT_EQ(
      snapshot.bodies[static_cast<std::size_t>(runner.world().body_index("uterus"))].cut_surface,
      nullptr);
}

/// A scoop of the polyp's apex cut by a LoopResection on a bare world (no session), with pieces
/// below `debris_volume` m³ shed as debris into `shreds` (no sink when the bound is 0).
struct BareScoop {
  CuttingSummary summary;
  std::vector<std::pair<core::Vec3, double>> shreds;
  std::vector<Chip> chips;
  int polyp_tets_after = 0;
  std::size_t polyp_nodes_after = 0;
  std::vector<core::Vec3> shed_nodes_at_cut, shed_nodes_later;
  std::shared_ptr<const CutVisibleSurface> surface;  ///< the polyp's, at the end
  std::vector<core::Tetrahedron> polyp_tets;         ///< at the end
  std::vector<SessionEvent> events;
};

BareScoop bare_scoop(double debris_volume) {
  const core::Scenario scenario = resectoscope_patient();
  World world(scenario);
  world.settle();
  const int polyp = world.body_index("polyp-1");
  const auto input =
      ScriptedTrajectory::from_json(scoop_script(polyp_frame(world), 2.0e-3), "scoop", 30.0);
  LoopResection resection(world, {polyp}, standard_resection_loop());
  VisibleSurfaces visible(scenario, world);
  resection.cut_visible_surfaces(&visible);
  BareScoop r;
  if (debris_volume > 0.0)
    resection.shed_debris_below(debris_volume, [&](const core::Vec3& centre, double radius) {
      r.shreds.emplace_back(centre, radius);
    });
  resection.begin(world, r.summary);
  std::vector<SessionEvent> events;
  std::vector<int> shed_nodes;
  for (int step = 1; step <= 1200; ++step) {
    world.step();
    const int cuts = r.summary.cuts;
    resection.follow(input.state(step, world.time()), world, world.time(), r.summary, events);
    if (r.summary.cuts == cuts || r.shreds.empty()) continue;
    // The shed nodes: those of the cut mesh that no tet holds any more.
    const core::TetMesh& mesh = world.models()[static_cast<std::size_t>(polyp)]->mesh;
    std::vector<std::uint8_t> in_tet(mesh.nodes.size(), 0);
    for (const auto& t : mesh.tets)
      for (const int v : t)
        in_tet[static_cast<std::size_t>(v)] = 1;
    const auto x = world.state().range(world.state().positions, polyp);
    for (std::size_t v = 0; v < mesh.nodes.size(); ++v)
      if (!in_tet[v]) {
        shed_nodes.push_back(static_cast<int>(v));
        r.shed_nodes_at_cut.push_back(x[v]);
      }
  }
  const auto x = world.state().range(world.state().positions, polyp);
  for (const int v : shed_nodes)
    r.shed_nodes_later.push_back(x[static_cast<std::size_t>(v)]);
  const core::TetMesh& mesh_after = world.models()[static_cast<std::size_t>(polyp)]->mesh;
  r.polyp_tets_after = static_cast<int>(mesh_after.tets.size());
  r.polyp_nodes_after = mesh_after.nodes.size();
  r.chips = resection.chips();
  r.surface = visible.cut_surface(polyp);
  r.events = events;
  r.polyp_tets = mesh_after.tets;
  return r;
}

TEST(LoopResection, pieces_below_the_debris_bound_leave_the_body_as_debris_shreds) {
  // Issue 17 §3: with every piece below the bound (1 m³), the scoop's chip is shed as debris.
  // The same cut without a bound keeps it as a chip: same resected volume, same pieces.
  const BareScoop chip = bare_scoop(0.0), shed = bare_scoop(1.0);
  ASSERT_EQ(chip.summary.cuts, 1);
  ASSERT_EQ(shed.summary.cuts, 1);
  const BodyResection& kept = chip.summary.bodies[0];
  const BodyResection& gone = shed.summary.bodies[0];
  ASSERT_GE(kept.chips, 1);
  EXPECT_EQ(kept.debris, 0);
  EXPECT_TRUE(chip.shreds.empty());
  EXPECT_EQ(gone.chips, 0);
  EXPECT_EQ(gone.debris, kept.chips);
  EXPECT_TRUE(shed.chips.empty());
  EXPECT_NEAR(gone.resected_volume, kept.resected_volume, 1e-12 * kept.resected_volume);
  // One shred per chip, the radius of the sphere of its volume: the radii's cubes add up to it.
  ASSERT_EQ(static_cast<int>(shed.shreds.size()), kept.chips);
  double volume = 0.0;
  for (const auto& [centre, radius] : shed.shreds) {
    EXPECT_TRUE(centre.allFinite());
    volume += 4.0 / 3.0 * std::numbers::pi * radius * radius * radius;
  }
  EXPECT_NEAR(volume, kept.resected_volume, 1e-9 * kept.resected_volume);
  const auto cut_event = std::find_if(shed.events.begin(), shed.events.end(),
                                      [](const SessionEvent& e) { return e.kind == "cut"; });
  ASSERT_NE(cut_event, shed.events.end());
  EXPECT_NE(cut_event->message.find("shred(s) of debris"), std::string::npos) << cut_event->message;
  // The chip's tets left the body; its nodes stay (every index holds) and no longer move.
  EXPECT_LT(shed.polyp_tets_after, chip.polyp_tets_after);
  EXPECT_EQ(shed.polyp_nodes_after, chip.polyp_nodes_after);
  ASSERT_FALSE(shed.shed_nodes_at_cut.empty());
  EXPECT_EQ(shed.shed_nodes_later, shed.shed_nodes_at_cut);
  // The visible surface lost the chip's triangles and follows the kept tets.
  ASSERT_NE(chip.surface, nullptr);
  ASSERT_NE(shed.surface, nullptr);
  EXPECT_EQ(shed.surface->tets, shed.polyp_tets);
  EXPECT_LT(shed.surface->mesh.triangles.size(), chip.surface->mesh.triangles.size());
  ASSERT_EQ(shed.surface->embedding.tet.size(), shed.surface->mesh.vertices.size());
  for (const int t : shed.surface->embedding.tet) {
    EXPECT_GE(t, 0);
    EXPECT_LT(t, static_cast<int>(shed.polyp_tets.size()));
  }
  for (const auto& [name, values] : shed.surface->mesh.vertex_attributes)
    EXPECT_EQ(values.size(), shed.surface->mesh.vertices.size()) << name;
}

}  // namespace
}  // namespace viscera::sim
