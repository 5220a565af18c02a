#include "core/materials/shipped_materials.h"

#include <gtest/gtest.h>

#include <set>

#include "core/error.h"
#include "core/materials/cubic_stress_fit.h"

namespace viscera::core {
namespace {

TEST(ShippedMaterials, every_tissue_the_gynaecology_and_urology_scenes_need_is_there) {
  for (const char* id : {"myometrium", "endometrium", "myoma", "ovary", "fallopian-tube",
                         "ligament", "artery", "vein", "bowel", "liver", "bladder", "urethra"}) {
    EXPECT_NE(find_shipped_material(id), nullptr) << id;
  }
  EXPECT_EQ(shipped_material("myometrium").id, "myometrium");
  EXPECT_THROW(shipped_material("spleen"), UsageError);
}

TEST(ShippedMaterials, every_number_has_a_source_that_says_measured_or_estimate) {
  for (const auto& shipped : shipped_materials()) {
    std::set<std::string> quantities;
    for (const auto& [quantity, source] : shipped.sources) {
      quantities.insert(quantity);
      EXPECT_TRUE(source.rfind("measured: ", 0) == 0 || source.rfind("estimate: ", 0) == 0)
          << shipped.material.id << " " << quantity << ": " << source;
    }
    for (const char* q :
         {"density", "small_strain_modulus", "stiffening", "plastic_yield", "poisson_ratio"}) {
      EXPECT_TRUE(quantities.count(q)) << shipped.material.id << " lacks " << q;
    }
    EXPECT_TRUE(quantities.count("tensile_strength") || quantities.count("tearing_strain"))
        << shipped.material.id;
    EXPECT_FALSE(shipped.material.source.empty());
  }
}

TEST(ShippedMaterials, curves_stiffen_and_pass_through_their_anchors) {
  for (const auto& shipped : shipped_materials()) {
    const Material& m = shipped.material;
    ASSERT_TRUE(m.stress_strain) << m.id;
    const auto& c = m.stress_strain->cubic;
    ASSERT_EQ(c.size(), 4u);
    const std::array<double, 4> cubic = {c[0], c[1], c[2], c[3]};
    EXPECT_GT(c[1], 0.0) << m.id;
    EXPECT_GE(c[3], 0.0) << m.id;
    for (std::size_t i = 0; i < m.stress_strain->strain.size(); ++i) {
      EXPECT_NEAR(cubic_stress(cubic, m.stress_strain->strain[i]), m.stress_strain->stress[i],
                  1e-6 * (1.0 + m.stress_strain->stress[i]))
          << m.id << " point " << i;
    }
    EXPECT_GT(m.tearing_threshold, m.plastic_yield) << m.id;
    EXPECT_GT(m.distance_stiffness, 0.0) << m.id;
    EXPECT_GT(m.volume_stiffness, 0.0) << m.id;
    EXPECT_GT(m.distance_damping, 0.0) << m.id;
    EXPECT_GT(m.density, 900.0) << m.id;
    EXPECT_LT(m.density, 1200.0) << m.id;
  }
}

TEST(ShippedMaterials, published_anchors_are_reproduced) {
  // Myometrium: tangent 0.9 MPa at 69 kPa (Pearsall and Roberts 1978), tearing where the curve
  // reaches 1.0 MPa.
  const Material myometrium = shipped_material("myometrium");
  const auto& c = myometrium.stress_strain->cubic;
  const std::array<double, 4> cubic = {c[0], c[1], c[2], c[3]};
  const double at = myometrium.stress_strain->strain[1];
  EXPECT_NEAR(cubic_stress(cubic, at), 6.9e4, 1.0);
  EXPECT_NEAR(cubic_tangent_modulus(cubic, at), 9.0e5, 1.0);
  EXPECT_NEAR(cubic_stress(cubic, myometrium.tearing_threshold), 1.0e6, 1.0);
  // Bowel: 0.9 MPa at 140 % strain (Egorov et al. 2002).
  const Material bowel = shipped_material("bowel");
  EXPECT_NEAR(bowel.tearing_threshold, 1.4, 1e-9);
  // A myoma is stiffer than the myometrium around it, the endometrium softer.
  EXPECT_GT(shipped_material("myoma").distance_stiffness, myometrium.distance_stiffness);
  EXPECT_LT(shipped_material("endometrium").distance_stiffness, myometrium.distance_stiffness);
}

TEST(ShippedMaterials, catalogue_errors_name_the_json_pointer) {
  const std::string head =
      R"({"format": "viscera-materials", "version": 1, "working_strain": {"value": 0.3, "source": "x"},
          "damping_time": {"value": 1e-4, "source": "x"}, "materials": [)";
  try {
    parse_material_catalogue(
        head + R"({"id": "a", "name": "A", "density": {"value": -1, "source": "s"}}]})",
        "cat.json");
    FAIL() << "expected an error";
  } catch (const ValidationError& e) {
    EXPECT_EQ(e.location().file, "cat.json");
    EXPECT_EQ(e.location().json_pointer, "/materials/0/density/value");
  }
  EXPECT_THROW(parse_material_catalogue("{", "cat.json"), InputError);
  EXPECT_THROW(parse_material_catalogue(R"({"format": "other"})", "cat.json"), ValidationError);
}

}  // namespace
}  // namespace viscera::core
