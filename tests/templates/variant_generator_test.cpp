#include "templates/generator/variant_generator.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "templates/generator/diversity_summary.h"
#include "templates/generator/patient_seed.h"
#include "templates/variability/parameter_distribution.h"

namespace viscera::templates {
namespace {

TEST(PatientSeed, is_the_leading_sha256_bytes_of_template_seed_k_and_attempt) {
  // python3: int.from_bytes(hashlib.sha256(b"viscera-generate/1/hysteroscopy/1/0/0")
  //                        .digest()[:8], "big")
  EXPECT_EQ(patient_seed("hysteroscopy", 1, 0, 0), 341402977488870248ULL);
  const auto base = patient_seed("hysteroscopy", 1, 3, 0);
  EXPECT_EQ(patient_seed("hysteroscopy", 1, 3, 0), base);
  EXPECT_NE(patient_seed("hysteroscopy", 1, 4, 0), base);
  EXPECT_NE(patient_seed("hysteroscopy", 1, 3, 1), base);
  EXPECT_NE(patient_seed("hysteroscopy", 2, 3, 0), base);
  EXPECT_NE(patient_seed("ball", 1, 3, 0), base);
}

std::vector<core::VariabilityRule> ball_rules() {
  return {uniform_rule("radius", 0.02, 0.04), fixed_rule("cell_size", 0.01)};
}

TEST(VariantGenerator, patient_k_is_the_same_whenever_it_is_drawn_and_differs_from_others) {
  const VariantGenerator generator(find_template("ball"), ball_rules(), 7);
  const GeneratedPatient a = generator.generate(2), b = generator.generate(2);
  const GeneratedPatient c = generator.generate(3);
  EXPECT_TRUE(a.scenario == b.scenario);
  EXPECT_EQ(a.parameters, b.parameters);
  EXPECT_NE(a.parameters.at("radius"), c.parameters.at("radius"));
  EXPECT_GE(a.parameters.at("radius"), 0.02);
  EXPECT_LT(a.parameters.at("radius"), 0.04);
  EXPECT_DOUBLE_EQ(a.parameters.at("cell_size"), 0.01);
  EXPECT_TRUE(a.validation.valid()) << a.validation.first_failure();
  EXPECT_EQ(a.validation.checks.back().name, "simulation");
  // The perturbation moved the ball, and it stayed within its bound.
  const auto& sim = a.validation.checks.back().measures;
  EXPECT_GE(sim.at("max_displacement").get<double>(), 1e-4);
  EXPECT_EQ(sim.at("steps"), 1000);
  EXPECT_EQ(a.scenario.provenance.seed, a.build_seed);
  EXPECT_EQ(a.scenario.variability, ball_rules());
  const nlohmann::json record = patient_record(a, "patient-0002.vscene");
  EXPECT_EQ(record.at("index"), 2);
  EXPECT_EQ(record.at("attempts"), 1);
  EXPECT_EQ(record.at("organ"), "ball");
}

TEST(VariantGenerator, counts_and_reports_invalid_draws_and_gives_up_after_the_limit) {
  GenerationOptions options;
  options.max_attempts = 2;
  options.validation.min_dihedral_degrees = 75.0;  // no tet mesh passes
  const VariantGenerator generator(find_template("ball"), ball_rules(), 7, options);
  try {
    generator.generate(0);
    FAIL() << "expected a ValidationError";
  } catch (const core::ValidationError& e) {
    EXPECT_NE(std::string(e.what()).find("all 2 draws (tets 2)"), std::string::npos) << e.what();
  }
}

TEST(VariantGenerator, refuses_rules_for_unknown_parameters) {
  EXPECT_THROW(VariantGenerator(find_template("ball"), {uniform_rule("nope", 0, 1)}, 1),
               core::UsageError);
}

TEST(PackageName, pads_to_four_digits_or_the_batch_width) {
  EXPECT_EQ(patient_package_name(7, 20), "patient-0007.vscene");
  EXPECT_EQ(patient_package_name(12345, 20000), "patient-12345.vscene");
}

TEST(SimulationCheck, an_unbounded_motion_and_a_non_finite_body_fail) {
  const VariantGenerator generator(find_template("ball"), ball_rules(), 7);
  const core::Scenario ball = generator.generate(0).scenario;
  SimulationBounds tight;
  tight.max_displacement_fraction = 1e-4;  // ~10 µm for this ball: below the perturbation
  const ValidationCheck moved = simulate_one_second(ball, tight);
  EXPECT_FALSE(moved.passed);
  EXPECT_NE(moved.detail.find("from rest"), std::string::npos) << moved.detail;
  SimulationBounds wild;
  wild.perturbation = 0.05;  // tangles the ball's tets: the integrator diverges
  const ValidationCheck exploded = simulate_one_second(ball, wild);
  EXPECT_FALSE(exploded.passed);
  EXPECT_NE(exploded.detail.find("unstable"), std::string::npos) << exploded.detail;
  core::Scenario broken = ball;
  broken.objects[0].body.nodes.back().x() = std::nan("");
  EXPECT_FALSE(simulate_one_second(broken).passed);
}

TEST(DiversitySummary, histograms_count_every_patient_in_its_bin) {
  nlohmann::json records = nlohmann::json::array();
  for (const double r : {0.011, 0.012, 0.049, 0.2})
    records.push_back({{"parameters", {{"radius", r}, {"cell_size", 0.01}}}});
  const nlohmann::json h =
      parameter_histograms(find_template("ball"), ball_rules(), records).at("radius");
  EXPECT_EQ(h.at("count"), 4);
  const auto edges = h.at("bin_edges").get<std::vector<double>>();
  ASSERT_EQ(edges.size(), 11u);
  const auto counts = h.at("counts").get<std::vector<int>>();
  int total = 0;
  for (const int c : counts)
    total += c;
  EXPECT_EQ(total, 4);
  EXPECT_EQ(counts.back(), 1);  // the maximum falls in the last bin
  EXPECT_NEAR(h.at("mean").get<double>(), (0.011 + 0.012 + 0.049 + 0.2) / 4, 1e-15);
  EXPECT_DOUBLE_EQ(h.at("min").get<double>(), 0.011);
  // A fixed parameter has no histogram.
  EXPECT_FALSE(
      parameter_histograms(find_template("ball"), ball_rules(), records).contains("cell_size"));
}

}  // namespace
}  // namespace viscera::templates
