// The Teschner terms of the core honour each wall layer's material: a two-layer bar in tension
// strains in the inverse ratio of its layers' stiffnesses.
#include "simulator/dynamics/teschner_terms.h"

#include <gtest/gtest.h>

#include "core/error.h"
#include "simulator/world/world.h"
#include "tests/simulator/sim_fixtures.h"

namespace viscera::sim {
namespace {

/// A constant force `force` (N) on each of `nodes`: E = −Σ F·(x − X).
class ConstantPull : public ForceTerm {
 public:
  ConstantPull(std::vector<int> nodes, Vec3 force, std::vector<Vec3> rest)
      : nodes_(std::move(nodes)), force_(force), rest_(std::move(rest)) {}
  std::string name() const override { return "pull"; }
  double energy(std::span<const Vec3> x) const override {
    double e = 0.0;
    for (const int n : nodes_)
      e -= force_.dot(x[n] - rest_[static_cast<std::size_t>(n)]);
    return e;
  }
  double add_forces(std::span<const Vec3> x, std::span<const Vec3>,
                    std::span<Vec3> f) const override {
    for (const int n : nodes_)
      f[n] += force_;
    return energy(x);
  }
  void declare_blocks(BlockPattern&) const override {}
  void add_stiffness(std::span<const Vec3>, double, bool, BlockSparseMatrix&) const override {}

 private:
  std::vector<int> nodes_;
  Vec3 force_;
  std::vector<Vec3> rest_;
};

TEST(TeschnerTerms, a_two_layer_bar_in_tension_strains_as_its_two_materials_predict) {
  // 8 × 2 × 2 cm bar along x, clamped at x = 0; label 1 (x < 4 cm) soft, label 2 three times
  // stiffer; pulled along x at x = 8 cm. In series each layer carries the same force, so the
  // strains are in the inverse ratio of the stiffnesses.
  core::Scenario scenario;
  scenario.materials["soft"] = viscera::testing::soft_test_material(200.0);
  // Elastic layers: the soft one strains past the default 0.3 plastic yield under this pull,
  // and plastic flow (its own tests) would lengthen it for good.
  scenario.materials["soft"].plastic_yield = 0.0;
  core::Material stiff = scenario.materials["soft"];
  stiff.id = "stiff";
  stiff.distance_stiffness *= 3.0;
  stiff.volume_stiffness *= 3.0;
  scenario.materials["stiff"] = stiff;
  core::SceneObject bar = viscera::testing::held_block("bar", 8, 2, 2, 0.01);
  for (std::size_t n = 0; n < bar.body.nodes.size(); ++n)
    bar.body.fixed[n] = bar.body.nodes[n].x() < 1e-9 ? 1 : 0;
  for (const auto& t : bar.body.tets) {
    double x = 0.0;
    for (const int n : t)
      x += bar.body.nodes[static_cast<std::size_t>(n)].x() / 4.0;
    bar.body.tet_labels.push_back(x < 0.04 ? 1 : 2);
  }
  bar.layer_materials = {{1, "soft"}, {2, "stiff"}};
  scenario.objects.push_back(bar);
  scenario.session.gravity = Vec3::Zero();
  World world(scenario);
  ASSERT_EQ(world.models()[0]->materials.size(), 3u);  // the object's material and two layers
  std::vector<int> end;
  for (std::size_t n = 0; n < bar.body.nodes.size(); ++n)
    if (bar.body.nodes[n].x() > 0.08 - 1e-9) end.push_back(static_cast<int>(n));
  world.add_term(
      std::make_unique<ConstantPull>(end, Vec3(0.05, 0.0, 0.0), world.state().rest_positions));
  for (int s = 0; s < 3000; ++s)
    world.step();
  ASSERT_LT(world.energies().kinetic, 1e-6);  // settled (the pull stores about 1 mJ)
  // Mean x displacement of the cross-sections at 1, 3, 5 and 7 cm: strain within each layer,
  // away from the clamp, the interface and the loaded end.
  const auto section = [&](double x0) {
    double sum = 0.0;
    int count = 0;
    const auto x = world.bodies()[0].positions();
    for (std::size_t n = 0; n < x.size(); ++n)
      if (std::abs(bar.body.nodes[n].x() - x0) < 1e-9) sum += x[n].x() - x0, ++count;
    return sum / count;
  };
  const double soft_strain = (section(0.03) - section(0.01)) / 0.02;
  const double stiff_strain = (section(0.07) - section(0.05)) / 0.02;
  ASSERT_GT(stiff_strain, 1e-5);
  EXPECT_NEAR(soft_strain / stiff_strain, 3.0, 0.05 * 3.0);
}

TEST(TeschnerTerms, an_unknown_layer_material_is_refused_naming_the_object) {
  core::Scenario scenario;
  scenario.materials["soft"] = viscera::testing::soft_test_material();
  core::SceneObject bar = viscera::testing::held_block("bar", 2, 2, 2, 0.01);
  bar.body.tet_labels.assign(bar.body.tets.size(), 1);
  bar.layer_materials = {{1, "missing"}};
  scenario.objects.push_back(bar);
  try {
    World world(scenario);
    FAIL() << "a missing layer material was accepted";
  } catch (const core::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("missing"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("bar"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace viscera::sim
