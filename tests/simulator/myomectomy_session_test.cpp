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
  for (const SessionReport* r : {&expert, &novice}) {
    EXPECT_NEAR(r->cutting->volume_after, r->cutting->volume_before,
                1e-9 * r->cutting->volume_before);
    EXPECT_GE(r->cutting->min_dihedral_after_degrees, 1.0);
    EXPECT_NE(r->end_reason, "perforation");
  }
}

}  // namespace
}  // namespace viscera::sim
