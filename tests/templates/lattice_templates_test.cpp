#include <gtest/gtest.h>

#include <cmath>

#include "templates/template_catalog.h"
#include "templates/validation/patient_validation.h"

namespace viscera::templates {
namespace {

TEST(UrethraTemplate, sections_sit_on_the_parabola_normal_to_it_with_the_bladder_entrance_fixed) {
  const core::Scenario s = build_from_template("urethra", {}, 1);
  ASSERT_EQ(s.objects.size(), 1u);
  ASSERT_EQ(s.urethra_lattices.size(), 1u);
  const auto& spec = s.urethra_lattices[0];
  const auto& body = s.objects[0].body;
  const int n = spec.points_per_section, w = spec.sections;
  EXPECT_EQ(n, 9);
  EXPECT_EQ(w, 26);
  ASSERT_EQ(body.nodes.size(), static_cast<std::size_t>(n * w));
  for (int j = 0; j < w; ++j) {
    core::Vec3 centre = core::Vec3::Zero();
    for (int i = 0; i < n; ++i)
      centre += body.nodes[static_cast<std::size_t>(j * n + i)];
    centre /= n;
    const double z = j * spec.length / (w - 1);
    EXPECT_NEAR(centre.z(), z, 1e-12);
    EXPECT_NEAR(centre.y(), spec.curvature * z * z, 1e-12);  // y = a z², seed 002 §3.1
    const core::Vec3 tangent = core::Vec3(0.0, 2.0 * spec.curvature * z, 1.0).normalized();
    for (int i = 0; i < n; ++i) {
      const core::Vec3 r = body.nodes[static_cast<std::size_t>(j * n + i)] - centre;
      EXPECT_NEAR(r.norm(), spec.radius, 1e-12);
      EXPECT_NEAR(r.dot(tangent), 0.0, 1e-12);
      EXPECT_EQ(body.fixed[static_cast<std::size_t>(j * n + i)], j == w - 1 ? 1 : 0);
    }
  }
  EXPECT_TRUE(validate_patient_geometry(s).valid());
}

TEST(AgentTissueTemplate, lays_out_cells_with_inclusions_and_a_stable_step) {
  const core::Scenario s =
      build_from_template("agent-tissue", {{"inclusions", "1"}, {"inclusion_radius", "0.004"}}, 3);
  ASSERT_EQ(s.cell_tissues.size(), 1u);
  const auto& spec = s.cell_tissues[0];
  const auto& body = s.objects[0].body;
  ASSERT_EQ(body.nodes.size(), 40u * 30u);
  ASSERT_EQ(spec.cell_types.size(), body.nodes.size());
  // One disc of radius 4 mm on a 1 mm grid: about π·4² ≈ 50 cells, fewer where it leaves the
  // sheet; all in one connected disc of inclusion cells.
  int inclusion = 0;
  core::Vec3 centre = core::Vec3::Zero();
  for (std::size_t c = 0; c < body.nodes.size(); ++c) {
    if (spec.cell_types[c] == 1) {
      ++inclusion;
      centre += body.nodes[c];
    }
  }
  ASSERT_GT(inclusion, 10);
  EXPECT_LE(inclusion, 53);
  centre /= inclusion;
  for (std::size_t c = 0; c < body.nodes.size(); ++c) {
    if (spec.cell_types[c] == 1) {
      EXPECT_LE((body.nodes[c] - centre).norm(), 2 * 0.004 + 1e-9);
    }
  }
  // Explicit stability: ω h < 1 for the stiffest cell.
  for (const auto& t : spec.types) {
    const double omega = std::sqrt((4.0 * t.connection_stiffness + t.home_stiffness) / t.mass);
    EXPECT_LE(omega * s.session.time_step, 1.0 + 1e-12);
  }
  EXPECT_EQ(spec.max_neighbours, 4);
}

}  // namespace
}  // namespace viscera::templates

#include "templates/laparoscopy/laparoscopy_gyn_template.h"

namespace viscera::templates {
namespace {

TEST(LaparoscopyGynTemplate, has_seed_001s_21_objects_with_knot_counts_near_its_table) {
  const core::Scenario s = build_from_template("laparoscopy-gyn", {}, 1);
  EXPECT_EQ(s.objects.size(), 21u);
  const nlohmann::json counts = laparoscopy_gyn_counts(s);
  for (const auto& [group, c] : counts.items()) {
    EXPECT_EQ(c.at("objects"), c.at("seed_objects")) << group;
    const double knots = c.at("knots").get<double>(), seed = c.at("seed_knots").get<double>();
    EXPECT_NEAR(knots, seed, 0.06 * seed) << group;
    // Each quad between the layers gets a diagonal spring (the prisms' tets), so our nets
    // carry about 5 springs per knot where KisMo's carried 4.
    EXPECT_NEAR(c.at("springs").get<double>() / knots, 4.9, 0.4) << group;
  }
  EXPECT_EQ(counts.at("total").at("knots"), 2784);
  EXPECT_TRUE(validate_patient_geometry(s).valid()) << validate_patient_geometry(s).first_failure();
  EXPECT_EQ(find_template("laparoscopy-gyn").reference_counts(), counts);
}

}  // namespace
}  // namespace viscera::templates
