// The laparoscopic tubal sterilisation (issue 19 §3, §6) on the left fallopian tube of the
// laparoscopy-gyn template's patient, alone (the other 20 objects take no part in it and would
// make every run minutes long): the shipped expert and novice scripts, the grasper pulling and
// tearing (a hard pull cracks the tube apart), clips closing the tube, bipolar coagulation stopping
// ooze, the scissors dividing it, and a replay.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>

#include "core/json_schema/json_schema_validator.h"
#include "core/json_text.h"
#include "simulator/session/headless_session.h"
#include "simulator/session/instrument_input.h"
#include "templates/template_catalog.h"
#include "tests/simulator/left_tube_patient.h"
#include "tests/support/test_paths.h"

namespace viscera::sim {
namespace {

using testing::left_tube_patient;

nlohmann::json script_json(const std::string& who) {
  const std::string file =
      (testing::source_dir() / ("data/scripts/laparoscopy-sterilisation-" + who + ".json"))
          .string();
  return resolve_script_landmarks(core::read_json_file(file), left_tube_patient().landmarks, file);
}

SessionReport run_json(const nlohmann::json& json, bool record = false) {
  const auto input = ScriptedTrajectory::from_json(json, "script", 30.0);
  HeadlessRunOptions options;
  options.duration = input.duration();
  options.instrument = &input;
  options.instrument_body = "tube-left";
  options.record_inputs = record;
  return run_headless(left_tube_patient(), options);
}

const TaskResult& task(const SessionReport& r, const std::string& id) {
  return *std::find_if(r.tasks.begin(), r.tasks.end(), [&](const auto& t) { return t.id == id; });
}

/// The session's events, one per line, for failure messages.
std::string events_text(const SessionReport& r) {
  std::string text;
  for (const auto& e : r.events)
    text += std::to_string(e.time) + " " + e.kind + ": " + e.message + "\n";
  return text;
}

int events(const SessionReport& r, const std::string& kind) {
  return static_cast<int>(std::count_if(r.events.begin(), r.events.end(),
                                        [&](const auto& e) { return e.kind == kind; }));
}

double blood_loss(const SessionReport& r) {
  double bled = 0.0;
  for (const auto& s : r.bleeding.value_or(std::vector<fluid::BleedingSource>{}))
    bled += s.bled;
  return bled;
}

int secure_clips(const SessionReport& r) {
  return static_cast<int>(std::count_if(r.laparoscopy->clips.begin(), r.laparoscopy->clips.end(),
                                        [](const auto& c) { return c.secure(); }));
}

const SessionReport& expert() {
  static const SessionReport r = run_json(script_json("expert"), true);
  return r;
}

const SessionReport& novice() {
  static const SessionReport r = run_json(script_json("novice"));
  return r;
}

TEST(Sterilisation, the_expert_completes_every_task_with_none_unavailable) {
  const SessionReport& r = expert();
  for (const auto& t : r.tasks) {
    if (t.id == "view-right-tube") continue;  // the right tube is not in this scene
    EXPECT_EQ(t.status, "completed") << t.id << ": " << t.note;
  }
  ASSERT_TRUE(r.laparoscopy.has_value());
  const LaparoscopySummary& l = *r.laparoscopy;
  // The right hand grasps and pulls the isthmus; the left hand's grasper, through the second
  // port, holds the tube beside it from the first bite to the cut.
  EXPECT_EQ(l.grasps, 2);
  EXPECT_EQ(events(r, "tool-inserted"), 1) << events_text(r);
  EXPECT_GT(l.path_per_hand.at("left"), 0.03);  // in 3 cm along its shaft to the tube
  EXPECT_GT(l.path_per_hand.at("right"), l.path_per_hand.at("left"));
  EXPECT_EQ(secure_clips(r), 2);
  // Each clip squeezed its knots to the crushed walls' gap, from the tube's width.
  for (const ClipPlacement& c : l.clips) {
    EXPECT_GT(c.gap_placed, 0.003);
    EXPECT_LT(c.gap, 0.5 * c.gap_placed);
  }
  ASSERT_EQ(l.cuts.size(), 1u);
  EXPECT_TRUE(l.cuts[0].separated());
  EXPECT_TRUE(l.cuts[0].between_clips);
  EXPECT_GE(l.coagulated_of("tube-left")->length, 0.008);
}

TEST(Sterilisation, the_grasped_tube_follows_the_grasper) {
  // The expert pulls the held isthmus 5 mm towards the camera (−y) at 6.3–7.2 s.
  const SessionReport& r = expert();
  ASSERT_TRUE(r.laparoscopy.has_value());
  EXPECT_GT(r.laparoscopy->max_grasp_force, 0.0);
  EXPECT_EQ(r.laparoscopy->knots_torn_out, 0);
  EXPECT_EQ(events(r, "tissue-tear"), 0) << events_text(r);
  EXPECT_EQ(events(r, "tissue-torn-apart"), 0);
}

TEST(Sterilisation, a_hard_pull_tears_the_tube) {
  nlohmann::json script = script_json("expert");
  auto& w = script["waypoints"];
  // Pull 4 cm instead of 5 mm while the grasper holds.
  for (auto& point : w) {
    const double t = point["t"].get<double>();
    if (t > 7.0 && t < 7.5) point["tip"][1] = point["tip"][1].get<double>() - 0.035;
  }
  w.erase(std::remove_if(w.begin(), w.end(), [](const auto& p) { return p["t"] > 8.0; }), w.end());
  const SessionReport r = run_json(script);
  EXPECT_GT(events(r, "tissue-tear") + r.laparoscopy->knots_torn_out, 0);
  // Issue 17 §4 (seed 001 §4.1): the torn links crack the tube apart, knots duplicated, and
  // the session goes on sound.
  EXPECT_GT(events(r, "tissue-torn-apart"), 0) << events_text(r);
  for (const auto& sample : r.samples)
    EXPECT_TRUE(std::isfinite(sample.total()));
  EXPECT_EQ(r.end_reason, "duration");
}

TEST(Sterilisation, coagulated_tissue_does_not_ooze_when_cut_but_raw_tissue_does) {
  // The expert cuts through the coagulated isthmus; the novice cuts beside it, through raw tube.
  ASSERT_TRUE(expert().bleeding.has_value());
  ASSERT_TRUE(novice().bleeding.has_value());
  EXPECT_GT(blood_loss(novice()), 0.0);
  EXPECT_LT(blood_loss(expert()), 0.1 * blood_loss(novice()));
}

TEST(Sterilisation, expert_and_novice_separate_on_every_metric) {
  const SessionReport& e = expert();
  const SessionReport& n = novice();
  EXPECT_GT(secure_clips(e), secure_clips(n));
  EXPECT_GT(e.laparoscopy->coagulated_of("tube-left")->length,
            n.laparoscopy->coagulated_of("tube-left")->length);
  EXPECT_LT(blood_loss(e), blood_loss(n));
  double expert_path = 0.0, novice_path = 0.0;
  for (const auto& [tool, m] : e.laparoscopy->path_per_tool)
    expert_path += m;
  for (const auto& [tool, m] : n.laparoscopy->path_per_tool)
    novice_path += m;
  EXPECT_LT(expert_path, novice_path);
  // Per hand: the novice's left hand wanders (a grasp beside the tube, a jerk) and so does
  // his right.
  for (const char* hand : {"right", "left"})
    EXPECT_LT(e.laparoscopy->path_per_hand.at(hand), n.laparoscopy->path_per_hand.at(hand)) << hand;
  EXPECT_LT(e.simulated_time, n.simulated_time);
  // Three bipolar bites raise more smoke than one (thorough coagulation costs smoke; suction
  // clears it). The expert's assistant keeps the laparoscope 5.7 cm off the bites, clear of the
  // column, and its lens stays clear; the novice's, pushed in to 2.5 cm, steams at his one bite.
  EXPECT_GT(e.laparoscopy->smoke_time, n.laparoscopy->smoke_time);
  EXPECT_GT(n.laparoscopy->smoke_time, 0.0);
  EXPECT_LT(e.laparoscopy->peak_lens_fog, 0.05);
  EXPECT_GT(n.laparoscopy->peak_lens_fog, 0.1);
  // The expert draws the smoke column off with the suction cannula; the novice leaves it.
  EXPECT_GT(e.laparoscopy->smoke_puffs_suctioned, 10);
  EXPECT_EQ(n.laparoscopy->smoke_puffs_suctioned, 0);
  EXPECT_EQ(task(n, "cut-tube").status, "not-completed");
  EXPECT_EQ(task(n, "clip-distal").status, "not-completed");
}

TEST(Sterilisation, the_report_with_its_laparoscopy_block_validates_against_the_schema) {
  std::ifstream in(testing::source_dir() / "docs" / "session-report.schema.json");
  const core::JsonSchemaValidator schema(nlohmann::json::parse(in));
  const nlohmann::json report = report_to_json(expert());
  ASSERT_TRUE(report["laparoscopy"].is_object());
  EXPECT_EQ(report["laparoscopy"]["clips_secure"], 2);
  std::string problems;
  for (const auto& v : schema.validate(report))
    problems += v.pointer + ": " + v.message + "\n";
  EXPECT_TRUE(problems.empty()) << problems;
  // A clip without its angle is caught.
  nlohmann::json broken = report;
  broken["laparoscopy"]["clips"][0].erase("across_degrees");
  EXPECT_FALSE(schema.validate(broken).empty());
}

TEST(Sterilisation, the_recorded_session_replays_bit_identically) {
  const SessionReport& recorded = expert();
  const RecordedInput input(recorded.inputs);
  HeadlessRunOptions options;
  options.duration = recorded.simulated_time;
  options.instrument = &input;
  options.instrument_body = "tube-left";
  const SessionReport replayed = run_headless(left_tube_patient(), options);
  EXPECT_EQ(replayed.final_state_hash, recorded.final_state_hash);
  EXPECT_EQ(replayed.checkpoints, recorded.checkpoints);
}

}  // namespace
}  // namespace viscera::sim
