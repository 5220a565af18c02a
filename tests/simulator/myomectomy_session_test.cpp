// Operative hysteroscopy, the myoma (issue 17 §5): the hysteroscopy-myomectomy template's
// patient and the shipped expert and novice scripts placed at the myoma's landmarks. The expert
// shaves the myoma in layers of strips, each cut by a sweep from behind the myoma towards the
// optics (seed 000 §5); the novice cuts the top, lets go of the pedal with the loop still in the
// myoma and leaves its sides.

#include <gtest/gtest.h>

#include <cmath>

#include "simulator/dynamics/hydrometra_sweep.h"
#include "templates/template_catalog.h"
#include "tests/support/operative_session.h"

namespace viscera::sim {
namespace {

/// The patient `viscera new --template hysteroscopy-myomectomy --seed 1` writes.
const core::Scenario& patient() {
  static const core::Scenario s = [] {
    core::Scenario built = templates::build_from_template("hysteroscopy-myomectomy", {}, 1);
    add_hydrometra_states(built);
    return built;
  }();
  return s;
}

SessionReport run_script(const std::string& who) {
  return testing::run_operative_script(patient(), "hysteroscopy-myomectomy-" + who + ".json");
}

const BodyResection& myoma_of(const SessionReport& r) {
  return testing::resection_of(r, "myoma-1");
}

using testing::task_status;

TEST(MyomectomySession, the_template_gives_a_resectoscope_and_a_sessile_myoma_on_a_corpus_face) {
  const core::Scenario& s = patient();
  EXPECT_EQ(s.session.instrument.kind, "resectoscope");
  EXPECT_EQ(s.session.procedure_definition, "hysteroscopic-myomectomy");
  ASSERT_FALSE(s.pathologies.empty());
  for (const auto& p : s.pathologies)
    EXPECT_EQ(p.kind, "myoma-submucosal") << p.id;
  const auto base = std::find_if(s.landmarks.begin(), s.landmarks.end(),
                                 [](const auto& l) { return l.id == "myoma-1-base"; });
  ASSERT_NE(base, s.landmarks.end());
  // On the anterior or posterior wall of the corpus, where the sheath lies beside it.
  EXPECT_GT(std::abs(base->normal.y()), 0.6);
  EXPECT_LT(std::abs(base->normal.x()), 0.5);
  // Every seed the variants draw keeps to it.
  for (std::uint64_t seed = 2; seed <= 6; ++seed) {
    const core::Scenario other =
        templates::build_from_template("hysteroscopy-myomectomy", {}, seed);
    for (const auto& mark : other.landmarks) {
      if (!mark.id.ends_with("-base")) continue;
      EXPECT_GT(std::abs(mark.normal.y()), 0.6) << "seed " << seed << ' ' << mark.id;
    }
  }
}

TEST(MyomectomySession, the_expert_shaves_the_myoma_in_layers_and_the_novice_leaves_more_of_it) {
  const SessionReport expert = run_script("expert"), novice = run_script("novice");
  ASSERT_TRUE(expert.cutting && novice.cutting);
  // Stepwise shaving: many cuts, each taking a strip off as a chip.
  EXPECT_GE(expert.cutting->cuts, 6);
  EXPECT_GE(myoma_of(expert).chips, 6);
  EXPECT_GE(myoma_of(expert).resected_fraction(), 0.85);
  EXPECT_EQ(task_status(expert, "resect-myoma-1"), "completed");
  EXPECT_GE(novice.cutting->released_in_tissue, 1);
  EXPECT_GT(myoma_of(expert).resected_fraction(), myoma_of(novice).resected_fraction() + 0.2);
  EXPECT_EQ(task_status(novice, "resect-myoma-1"), "not-completed");
  EXPECT_GT(expert.score, novice.score);
  // Shaving down to the myoma's bed takes a thin layer of the wall under it, never much of the
  // wall's thickness (seed 000 §2.1); the novice, who leaves the myoma's sides, does not reach it.
  const CuttingSummary& shaved = *expert.cutting;
  ASSERT_TRUE(shaved.deepest_wall_cut && shaved.healthy_wall_removed);
  EXPECT_LT(*shaved.deepest_wall_cut, 0.25 * *shaved.wall_thickness_at_deepest_cut);
  EXPECT_GT(*shaved.healthy_wall_removed, 0.0);
  EXPECT_LT(*shaved.healthy_wall_removed, 0.25 * myoma_of(expert).initial_volume);
  EXPECT_LE(novice.cutting->healthy_wall_removed.value_or(0.0), *shaved.healthy_wall_removed);
  for (const SessionReport* r : {&expert, &novice}) {
    EXPECT_NEAR(r->cutting->volume_after, r->cutting->volume_before,
                1e-9 * r->cutting->volume_before);
    EXPECT_GE(r->cutting->min_dihedral_after_degrees, 1.0);
    EXPECT_NE(r->end_reason, "perforation");
  }
}

TEST(MyomectomySession, strips_through_the_myomas_feeding_artery_bleed_cloud_the_view_and_count) {
  // Issue 18's session: the same patient with an artery of 0.4 mm radius up the myoma's axis
  // (`--set pathology_artery_radius=0.0004`). The expert's strips open it; the arterial
  // pressure (85 mmHg) exceeds the cavity's, so it bleeds while the cavity is distended.
  core::Scenario bleeding = templates::build_from_template(
      "hysteroscopy-myomectomy", {{"pathology_artery_radius", "0.0004"}}, 1);
  add_hydrometra_states(bleeding);
  const SessionReport r =
      testing::run_operative_script(bleeding, "hysteroscopy-myomectomy-expert.json");
  ASSERT_TRUE(r.bleeding.has_value() && r.fluid.has_value() && r.cavity_flow.has_value());
  int artery_openings = 0;
  double bled = 0.0;
  for (const auto& source : *r.bleeding) {
    bled += source.bled;
    if (source.capillary) continue;
    EXPECT_EQ(source.vessel_tree, "myoma-1-artery");
    EXPECT_GT(source.bled, 0.0);
    ++artery_openings;
  }
  // Each layer's strips meet the artery again: more than one episode from it.
  EXPECT_GE(artery_openings, 2);
  EXPECT_GT(bled, 1e-6);  // m³: over a millilitre
  EXPECT_NEAR(r.fluid->bled, bled, 1e-12 * bled);
  // The blood enters the flow and clouds the optics for a while.
  EXPECT_NEAR(r.cavity_flow->blood_released, bled, 1e-9 * bled);
  EXPECT_LT(r.cavity_flow->lowest_transmission, 0.5);
  EXPECT_GT(r.cavity_flow->view_obscured_time, 1.0);
  // The deficit the pump shows (used − drained) is followed over the session.
  ASSERT_GE(r.fluid_series.size(), 10u);
  EXPECT_GT(r.fluid->used, 0.0);
  // Without the artery the same script bleeds only capillary ooze, held back by the pressure.
  const SessionReport dry = run_script("expert");
  ASSERT_TRUE(dry.fluid.has_value());
  EXPECT_LT(dry.fluid->bled, 0.01 * bled);
}

}  // namespace
}  // namespace viscera::sim
