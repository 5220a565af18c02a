// The suction–irrigation cannula in a laparoscopy session (simulator/session/suction_irrigation.h)
// on the left fallopian tube of the laparoscopy-gyn patient alone (as the sterilisation tests:
// the whole scene takes minutes): irrigating for 1 s onto the tube pushes it and fills the pool,
// suction draws the pool off, the report carries the volumes, and the session replays.

#include "simulator/session/suction_irrigation.h"

#include <gtest/gtest.h>

#include <fstream>

#include "core/json_eigen.h"
#include "core/json_schema/json_schema_validator.h"
#include "core/mesh/surface_mesh.h"
#include "simulator/session/instrument_input.h"
#include "simulator/session/session_runner.h"
#include "templates/template_catalog.h"
#include "tests/simulator/left_tube_patient.h"
#include "tests/support/test_paths.h"

namespace viscera::sim {
namespace {

using testing::left_tube_patient;

/// The centre of the highest surface triangle of the tube's body at rest, m.
core::Vec3 top_of_tube() {
  const World world(left_tube_patient());
  const auto rest = world.state().range(world.state().rest_positions, 0);
  core::Vec3 top = core::Vec3::Constant(-1e9);
  for (const core::Triangle& t : world.models()[0]->surface) {
    const core::Vec3 centre =
        (rest[static_cast<std::size_t>(t[0])] + rest[static_cast<std::size_t>(t[1])] +
         rest[static_cast<std::size_t>(t[2])]) /
        3.0;
    if (centre.z() > top.z()) top = centre;
  }
  return top;
}

/// Irrigates onto the tube from 3 cm above it for 1 s (when `irrigate`), goes to the pool
/// beside the tube 3 mm over its floor and opens the suction valve from 1.35 s to 1.75 s; ends
/// at 2 s.
nlohmann::json cannula_script(bool irrigate) {
  const core::BoundingBox box = core::bounds(left_tube_patient().objects[0].surface);
  const core::Vec3 centre = 0.5 * (box.min + box.max), extent = box.max - box.min;
  // Beside the tube across its length, 2 cm clear of it, just over the lowest knot.
  const int across = extent.x() < extent.y() ? 0 : 1;
  core::Vec3 pool = centre;
  pool[across] += 0.5 * extent[across] + 0.02;
  pool.z() = box.min.z() + 0.003;
  const core::Vec3 above = top_of_tube() + core::Vec3(0, 0, 0.03);
  const nlohmann::json down = core::Vec3(0, 0, -1);
  return {{"format", "viscera-script"},
          {"version", 2},
          {"waypoints",
           {{{"t", 0.0},
             {"tip", above},
             {"axis", down},
             {"tool", "suction"},
             {"irrigate", irrigate ? 1 : 0}},
            {{"t", 1.0}, {"tip", above}, {"irrigate", 0}},
            {{"t", 1.3}, {"tip", pool}},
            {{"t", 1.35}, {"tip", pool}, {"close", 1}},
            {{"t", 1.75}, {"tip", pool}, {"close", 0}},
            {{"t", 2.0}, {"tip", pool}}}}};
}

struct CannulaRun {
  SessionReport report;
  double landed = 0.0, in_flight = 0.0, pool_water = 0.0, pool_floor = 0.0;
  double max_impact = 0.0;                     ///< N, the largest total impact force of a step
  double fallen_in = 0.0;                      ///< m³ of drops that fell into the pool's surface
  double highest_wave = 0.0, displaced = 0.0;  ///< m, and the waves' ∫η dA at the end, m³
  long long bubbles_trapped = 0;
  std::size_t most_bubbles = 0;
};

CannulaRun run(const InstrumentInput& input, double duration, bool record) {
  HeadlessRunOptions options;
  options.duration = duration;
  options.instrument = &input;
  options.instrument_body = "tube-left";
  options.record_inputs = record;
  SessionRunner runner(left_tube_patient(), options);
  CannulaRun out;
  while (!runner.finished()) {
    const long long next = runner.world().steps() + 1;
    runner.step(input.state(next, static_cast<double>(next) * runner.world().time_step()));
    core::Vec3 total = core::Vec3::Zero();
    for (const fluid::JetImpact& impact : runner.irrigation()->last_impacts())
      total += impact.force;
    out.max_impact = std::max(out.max_impact, total.norm());
    for (const fluid::PoolLanding& landing : runner.irrigation()->last_landings())
      out.fallen_in += landing.volume;
    out.highest_wave = std::max(out.highest_wave, runner.irrigation()->waves().largest_elevation());
    out.most_bubbles = std::max(out.most_bubbles, runner.irrigation()->bubbles().bubbles().size());
  }
  out.displaced = runner.irrigation()->waves().displaced_volume();
  out.bubbles_trapped = runner.irrigation()->bubbles().trapped();
  const SuctionIrrigation& cannula = *runner.irrigation();
  out.landed = cannula.jet().landed_volume();
  out.in_flight = cannula.jet().in_flight_volume();
  out.pool_water = cannula.pool().contents().water;
  out.pool_floor = cannula.pool().floor().z();
  out.report = runner.finish();
  return out;
}

const CannulaRun& irrigated() {
  static const CannulaRun r = [] {
    const auto input = ScriptedTrajectory::from_json(cannula_script(true), "script", 30.0);
    return run(input, 2.0, true);
  }();
  return r;
}

TEST(SuctionIrrigation, irrigation_fills_the_pool_and_suction_draws_it_off_in_the_report) {
  const CannulaRun& r = irrigated();
  ASSERT_TRUE(r.report.laparoscopy.has_value());
  const LaparoscopySummary& l = *r.report.laparoscopy;
  // 1 s at 10 ml/s (one 0.01 ml drop per step while the valve is open).
  EXPECT_NEAR(l.irrigated_volume, 10e-6, 0.02e-6);
  EXPECT_EQ(r.in_flight, 0.0);  // every drop has come down by 2 s
  // 0.4 s of suction at 15 ml/s: 6 ml.
  EXPECT_NEAR(l.suctioned_volume, 6e-6, 0.02e-6);
  // Conservation: the pool holds what was irrigated less what was suctioned (no blood here).
  EXPECT_NEAR(l.pool_volume, l.irrigated_volume - l.suctioned_volume, 1e-15);
  EXPECT_NEAR(r.pool_water, l.pool_volume, 1e-18);
  EXPECT_EQ(l.pool_blood_fraction, 0.0);
  // The pool lies under the tube's lowest knot.
  EXPECT_NEAR(r.pool_floor, core::bounds(left_tube_patient().objects[0].surface).min.z(), 2e-3);
  // Drops the splashes threw into the pool raised waves that moved water but made none.
  EXPECT_GT(r.fallen_in, 0.0);
  EXPECT_GT(r.highest_wave, 1e-6);
  EXPECT_LT(std::abs(r.displaced), 1e-9 * r.fallen_in);
  // The fast ones trapped air: bubbles floated on the pool.
  EXPECT_GT(r.bubbles_trapped, 0);
  EXPECT_GT(r.most_bubbles, 0u);
  // The report in ml, valid against the schema.
  const nlohmann::json json = report_to_json(r.report);
  EXPECT_NEAR(json["laparoscopy"]["irrigated_ml"].get<double>(), 10.0, 0.02);
  EXPECT_NEAR(json["laparoscopy"]["suctioned_ml"].get<double>(), 6.0, 0.02);
  EXPECT_NEAR(json["laparoscopy"]["pool_ml"].get<double>(), 4.0, 0.04);
  EXPECT_EQ(json["laparoscopy"]["pool_blood_fraction"].get<double>(), 0.0);
  std::ifstream in(testing::source_dir() / "docs" / "session-report.schema.json");
  const core::JsonSchemaValidator schema(nlohmann::json::parse(in));
  std::string problems;
  for (const auto& v : schema.validate(json))
    problems += v.pointer + ": " + v.message + "\n";
  EXPECT_TRUE(problems.empty()) << problems;
  nlohmann::json broken = json;
  broken["laparoscopy"].erase("pool_ml");
  EXPECT_FALSE(schema.validate(broken).empty());
}

TEST(SuctionIrrigation, the_jet_pushes_the_tube_it_hits) {
  const CannulaRun& wet = irrigated();
  const auto input = ScriptedTrajectory::from_json(cannula_script(false), "script", 30.0);
  const CannulaRun dry = run(input, 2.0, false);
  // Eq. 4 for a drop that fell 3 cm after leaving at 0.8 m/s (|v|² ≈ 1.23 m²/s², ε = 0.2 and
  // µ = 0.3 keep little of it): about 6 mN, one drop a step.
  EXPECT_GT(wet.max_impact, 3e-3);
  EXPECT_LT(wet.max_impact, 2e-2);
  EXPECT_EQ(dry.max_impact, 0.0);
  EXPECT_EQ(dry.report.laparoscopy->irrigated_volume, 0.0);
  EXPECT_EQ(dry.report.laparoscopy->suctioned_volume, 0.0);  // an empty pool gives nothing
  // The drops' pushes moved the tissue: the two sessions' states differ.
  EXPECT_NE(wet.report.final_state_hash, dry.report.final_state_hash);
}

TEST(SuctionIrrigation, the_recorded_session_replays_bit_identically) {
  const CannulaRun& recorded = irrigated();
  bool irrigating = false;
  for (const auto& [step, state] : recorded.report.inputs)
    irrigating = irrigating || state.irrigating;
  EXPECT_TRUE(irrigating);  // the irrigation valve is in the record
  const RecordedInput input(recorded.report.inputs);
  const CannulaRun replayed = run(input, recorded.report.simulated_time, false);
  EXPECT_EQ(replayed.report.final_state_hash, recorded.report.final_state_hash);
  EXPECT_EQ(replayed.report.checkpoints, recorded.report.checkpoints);
  EXPECT_EQ(replayed.report.laparoscopy->pool_volume, recorded.report.laparoscopy->pool_volume);
}

TEST(SuctionIrrigation, the_sources_blood_joins_the_pool_and_suction_takes_it_in_proportion) {
  World world(left_tube_patient());
  SuctionIrrigation cannula(world);
  LaparoscopySummary summary;
  InstrumentState state;
  state.tool = LaparoscopicTool::Suction;
  state.axis = core::Vec3(0, 0, -1);
  state.tip = cannula.pool().floor() + core::Vec3(0.05, 0.05, 0.004);  // clear of the tube
  // 3 ml of blood let out so far by the session's sources, then 1 ml more; the total never
  // goes back (a later smaller count adds nothing).
  cannula.follow(state, world, 1e-3, 3e-6, summary);
  cannula.follow(state, world, 1e-3, 4e-6, summary);
  cannula.follow(state, world, 1e-3, 2e-6, summary);
  EXPECT_NEAR(cannula.pool().contents().blood, 4e-6, 1e-18);
  EXPECT_EQ(summary.pool_blood_fraction, 1.0);
  // 12 ml of water straight down into the pool: 16 ml, a quarter blood.
  state.irrigating = true;
  state.tip.z() += 0.01;
  for (int step = 0; step < 1200; ++step)
    cannula.follow(state, world, 1e-3, 4e-6, summary);
  state.irrigating = false;
  for (int step = 0; step < 200 && !cannula.jet().drops().empty(); ++step)
    cannula.follow(state, world, 1e-3, 4e-6, summary);
  ASSERT_TRUE(cannula.jet().drops().empty());
  EXPECT_NEAR(summary.pool_volume, 16e-6, 1e-15);
  EXPECT_NEAR(summary.pool_blood_fraction, 0.25, 1e-12);
  // Suction for 0.4 s, the tip 4 mm over the surface: 6 ml, a quarter of it blood.
  state.jaws_closed = true;
  for (int step = 0; step < 400; ++step) {
    state.tip = cannula.pool().surface_point(state.tip) + core::Vec3(0, 0, 0.004);
    cannula.follow(state, world, 1e-3, 4e-6, summary);
  }
  EXPECT_NEAR(summary.suctioned_volume, 6e-6, 1e-15);
  EXPECT_NEAR(cannula.pool().suctioned().blood, 1.5e-6, 1e-15);
  EXPECT_NEAR(summary.pool_blood_fraction, 0.25, 1e-12);
  EXPECT_NEAR(summary.pool_volume, 10e-6, 1e-15);
  // Out of reach, 2 cm over the surface, the valve draws nothing.
  state.tip.z() += 0.02;
  cannula.follow(state, world, 1e-3, 4e-6, summary);
  EXPECT_NEAR(summary.suctioned_volume, 6e-6, 1e-15);
}

}  // namespace
}  // namespace viscera::sim
