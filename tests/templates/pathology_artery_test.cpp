// The hysteroscopy template's pathology arteries (issue 18 §3: bleeding needs the patient's own
// vessels where the loop cuts): with a radius set, every polyp and every myoma that grows into
// the cavity hosts one artery from the centre of its base up its axis; intramural myomas and
// adhesions host none, and by default there are none at all.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>

#include "templates/template_catalog.h"

namespace viscera::templates {
namespace {

TEST(PathologyArtery, each_polyp_and_cavity_myoma_hosts_one_up_its_axis) {
  const core::Scenario s = build_from_template("hysteroscopy",
                                               {{"pathology_artery_radius", "0.0004"},
                                                {"polyps", "2"},
                                                {"submucosal_myomas", "1"},
                                                {"pedunculated_myomas", "1"},
                                                {"intramural_myomas", "1"},
                                                {"adhesions", "1"},
                                                {"vessel_terminals", "0"}},
                                               3);
  std::map<std::string, const core::Landmark*> landmarks;
  for (const auto& mark : s.landmarks)
    landmarks[mark.id] = &mark;
  int arteries = 0;
  for (const auto& tree : s.vessel_trees) {
    ++arteries;
    ASSERT_EQ(tree.id, tree.host_object + "-artery");
    ASSERT_EQ(tree.segments.size(), 1u);
    EXPECT_EQ(tree.kind, "arterial");
    const core::VesselSegment& artery = tree.segments.front();
    EXPECT_DOUBLE_EQ(artery.radius, 0.0004);
    const core::Vec3 base = landmarks.at(tree.host_object + "-base")->position;
    const core::Vec3 apex = landmarks.at(tree.host_object)->position;
    EXPECT_NEAR((artery.proximal - base).norm(), 0.0, 1e-12);
    EXPECT_NEAR((artery.distal - (base + 0.9 * (apex - base))).norm(), 0.0, 1e-12);
    const auto host = std::find_if(s.pathologies.begin(), s.pathologies.end(),
                                   [&](const auto& p) { return p.id == tree.host_object; });
    ASSERT_NE(host, s.pathologies.end()) << tree.host_object;
    EXPECT_TRUE(host->kind == "polyp" || host->kind == "myoma-submucosal" ||
                host->kind == "myoma-pedunculated")
        << host->kind;
  }
  EXPECT_EQ(arteries, 4);

  const core::Scenario plain =
      build_from_template("hysteroscopy", {{"polyps", "2"}, {"vessel_terminals", "0"}}, 3);
  EXPECT_TRUE(plain.vessel_trees.empty());
}

}  // namespace
}  // namespace viscera::templates
