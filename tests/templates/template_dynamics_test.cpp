// Every shipped template runs under the implicit core without sub-steps and never gains energy
// without input; a hysteroscopy polyp is attached to the wall: the tool pushes it, and its base
// follows a wall that is moved.
#include <gtest/gtest.h>

#include "core/random.h"
#include "simulator/world/world.h"
#include "templates/template_catalog.h"

namespace viscera::templates {
namespace {

using core::Vec3;

TEST(TemplateDynamics, every_template_steps_implicitly_at_its_step_and_never_gains_energy) {
  for (const auto& entry : template_catalog()) {
    const core::Scenario scenario = build_from_template(entry->name(), {}, 3);
    sim::World world(scenario, sim::IntegratorKind::BackwardEuler);
    if (world.bodies().empty()) continue;  // lattice and agent templates: no World body
    SCOPED_TRACE(entry->name());
    EXPECT_EQ(world.substeps(), 1);
    // A 0.2 mm random jiggle of every free node excites every mode.
    core::Rng rng(11);
    auto& state = world.state();
    for (std::size_t n = 0; n < state.node_count(); ++n)
      if (state.inverse_masses[n] > 0.0)
        state.positions[n] +=
            2e-4 * Vec3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
    double previous = world.energies().total();
    for (int s = 0; s < 100; ++s) {
      world.step();
      const double energy = world.energies().total();
      ASSERT_LE(energy, previous + 1e-9 * std::abs(previous) + 1e-15) << "step " << s + 1;
      previous = energy;
    }
  }
}

/// The hysteroscopy template with one polyp and nothing else in the cavity.
core::Scenario one_polyp() {
  return build_from_template(
      "hysteroscopy", {{"polyps", "1"}, {"submucosal_myomas", "0"}, {"polyp_length", "0.01"}}, 4);
}

int polyp_index(const sim::World& world, const core::Scenario& scenario) {
  for (const auto& object : scenario.objects)
    if (object.role == core::ObjectRole::Pathology && object.id.find("polyp") != std::string::npos)
      return world.body_index(object.id);
  return -1;
}

TEST(TemplateDynamics, the_tool_pushes_a_polyp_it_touches_instead_of_passing_through) {
  const core::Scenario scenario = one_polyp();
  sim::World world(scenario);
  const int polyp = polyp_index(world, scenario);
  ASSERT_GE(polyp, 0);
  const int wall = world.body_index("uterus");
  ASSERT_GE(wall, 0);
  // The tool comes in along the polyp's axis (its base's centre → its centroid) onto its apex.
  const sim::BodyView& body = world.bodies()[static_cast<std::size_t>(polyp)];
  Vec3 base = Vec3::Zero();
  int count = 0;
  for (const auto& connection : scenario.connections)
    if (connection.object_b == body.name())
      for (const auto& pair : connection.node_pairs)
        base += body.rest_positions()[static_cast<std::size_t>(pair[1])], ++count;
  ASSERT_GT(count, 0);
  base /= count;
  const Vec3 axis = (body.rest_centre_of_mass() - base).normalized();
  Vec3 far = base;
  for (const auto& p : body.rest_positions())
    if ((p - base).dot(axis) > (far - base).dot(axis)) far = p;
  world.attach_instrument(wall, 300.0, far + 0.004 * axis);
  for (int s = 0; s <= 300; ++s) {
    world.set_instrument_tip(far + (0.004 - 0.00002 * s) * axis);  // ends 2 mm inside
    world.step();
  }
  EXPECT_TRUE(world.instrument_in_contact());
  EXPECT_EQ(world.instrument_touched_body(), polyp);
  EXPECT_GT(world.instrument_force().norm(), 0.0);
  EXPECT_GT(world.bodies()[static_cast<std::size_t>(polyp)].max_displacement(), 2e-4);
}

TEST(TemplateDynamics, a_polyp_follows_its_wall_when_the_wall_is_moved) {
  const core::Scenario scenario = one_polyp();
  sim::World world(scenario);
  const int polyp = polyp_index(world, scenario);
  const int wall = world.body_index("uterus");
  ASSERT_GE(polyp, 0);
  // A prescribed displacement of the whole wall: 2 mm along x, ramped over 0.1 s, its nodes
  // driven (inverse mass 0) like motility would drive them.
  auto& state = world.state();
  const auto range = state.body(wall);
  for (int i = 0; i < range.count; ++i)
    state.inverse_masses[static_cast<std::size_t>(range.first + i)] = 0.0;
  const Vec3 shift(0.002, 0.0, 0.0);
  const Vec3 start = world.bodies()[static_cast<std::size_t>(polyp)].centre_of_mass();
  for (int s = 1; s <= 400; ++s) {
    const double ramp = std::min(1.0, s / 100.0);
    for (int i = 0; i < range.count; ++i) {
      const auto g = static_cast<std::size_t>(range.first + i);
      state.positions[g] = state.rest_positions[g] + ramp * shift;
    }
    world.step();
  }
  const Vec3 moved = world.bodies()[static_cast<std::size_t>(polyp)].centre_of_mass() - start;
  EXPECT_NEAR(moved.x(), 0.002, 0.1 * 0.002);
  EXPECT_NEAR(moved.y(), 0.0, 0.1 * 0.002);
  EXPECT_NEAR(moved.z(), 0.0, 0.1 * 0.002);
}

}  // namespace
}  // namespace viscera::templates
