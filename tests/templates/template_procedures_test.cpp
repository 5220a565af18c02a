// Every template but the ball embeds its procedure (seed 000 §11), and every task that names a
// landmark finds it in the scenario the template builds, in a plausible place.

#include <gtest/gtest.h>

#include <limits>

#include "core/scenario/procedure.h"
#include "templates/template_catalog.h"

namespace viscera::templates {
namespace {

const core::Landmark* landmark(const core::Scenario& s, const std::string& id) {
  for (const auto& l : s.landmarks) {
    if (l.id == id) return &l;
  }
  return nullptr;
}

double distance_to_surface_vertices(const core::Scenario& s, const std::string& object,
                                    const core::Vec3& p) {
  double best = std::numeric_limits<double>::infinity();
  for (const auto& o : s.objects) {
    if (o.id != object) continue;
    for (const auto& v : o.surface.vertices)
      best = std::min(best, (v - p).norm());
  }
  return best;
}

/// The procedure is embedded whole and every landmark its tasks name exists.
void expect_procedure(const core::Scenario& s, const std::string& name) {
  const core::ProcedureDefinition& p = core::procedure_definition(name);
  EXPECT_EQ(s.session.procedure_definition, name);
  EXPECT_EQ(s.session.steps, p.steps);
  EXPECT_EQ(s.session.instrument.kind, p.instrument.kind);
  EXPECT_EQ(s.session.duration_limit, p.duration_limit);
  for (const core::TaskSpec* task : core::all_tasks(s.session)) {
    if (!task->parameters.contains("landmark")) continue;
    const std::string id = task->parameters["landmark"].get<std::string>();
    EXPECT_NE(landmark(s, id), nullptr) << name << ": task " << task->id << " names " << id;
  }
}

TEST(TemplateProcedures, hysteroscopy_embeds_the_diagnostic_procedure_with_its_landmarks) {
  const core::Scenario s =
      build_from_template("hysteroscopy", {{"vessel_terminals", "0"}, {"edge_length", "0.008"}}, 1);
  expect_procedure(s, "diagnostic-hysteroscopy");
  const auto* outer = landmark(s, "cervix-external-os");
  const auto* inner = landmark(s, "cervix-internal-os");
  ASSERT_TRUE(outer != nullptr && inner != nullptr);
  // The external os's normal points out of the body (away from the internal os), which the
  // withdraw task measures against; the canal between them is about its 25 mm long.
  EXPECT_LT(outer->normal.dot(inner->position - outer->position), 0.0);
  EXPECT_NEAR((inner->position - outer->position).norm(), 0.025, 0.004);
  // The inspect task's region exists on the uterus surface and holds the cavity wall only.
  const auto& uterus = s.objects.front();
  ASSERT_EQ(uterus.id, "uterus");
  const auto& cavity = uterus.surface.vertex_attributes.at("cavity");
  std::size_t in_cavity = 0;
  for (const double v : cavity)
    in_cavity += v == 1.0;
  EXPECT_GT(in_cavity, 0u);
  EXPECT_LT(in_cavity, cavity.size() / 2);
}

TEST(TemplateProcedures, urethra_embeds_the_insertion_with_its_endoscope) {
  const core::Scenario s = build_from_template("urethra", {}, 1);
  expect_procedure(s, "urethral-endoscope-insertion");
  // The lattice's endoscope, not the procedure's default shaft.
  EXPECT_DOUBLE_EQ(s.session.instrument.shaft_diameter,
                   2.0 * s.urethra_lattices[0].endoscope_radius);
  const auto* meatus = landmark(s, "urethral-meatus");
  const auto* entrance = landmark(s, "bladder-entrance");
  ASSERT_TRUE(meatus != nullptr && entrance != nullptr);
  EXPECT_LT(meatus->normal.dot(entrance->position - meatus->position), 0.0);
}

TEST(TemplateProcedures, laparoscopy_marks_both_tubes_on_their_surface) {
  const core::Scenario s = build_from_template("laparoscopy-gyn", {}, 1);
  expect_procedure(s, "laparoscopic-tubal-sterilisation");
  for (const std::string side : {"left", "right"}) {
    const auto* tube = landmark(s, "fallopian-tube-" + side);
    ASSERT_NE(tube, nullptr);
    EXPECT_EQ(tube->object, "tube-" + side);
    // On the tube's surface (within a triangle edge of a vertex), on the patient's side.
    EXPECT_LT(distance_to_surface_vertices(s, "tube-" + side, tube->position), 0.004);
    EXPECT_EQ(tube->position.x() > 0.0, side == "left");
  }
}

TEST(TemplateProcedures, agent_tissue_embeds_its_lab_and_the_ball_none) {
  expect_procedure(build_from_template("agent-tissue", {}, 1), "agent-tissue-lab");
  const core::Scenario ball = build_from_template("ball", {}, 1);
  EXPECT_TRUE(ball.session.steps.empty());
  EXPECT_TRUE(ball.session.procedure_definition.empty());
}

}  // namespace
}  // namespace viscera::templates
