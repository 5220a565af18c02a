// The settled start of an explicit (KisMo) world: the left uterine artery and vein of the
// laparoscopy-gyn patient, the artery with its authored pulse. The settle brings both to their
// passive sag, the quiet vein falls asleep at once and stays where it settled, and the pulsing
// artery never sleeps between beats.

#include <gtest/gtest.h>

#include <algorithm>

#include "simulator/dynamics/explicit_verlet.h"
#include "simulator/world/world.h"
#include "templates/template_catalog.h"

namespace viscera::sim {
namespace {

const core::Scenario& artery_and_vein() {
  static const core::Scenario s = [] {
    core::Scenario p = templates::build_from_template("laparoscopy-gyn", {}, 1);
    const auto kept = [](const std::string& id) {
      return id == "artery-uterine-left" || id == "vein-uterine-left";
    };
    std::erase_if(p.objects, [&](const auto& o) { return !kept(o.id); });
    std::erase_if(p.vessel_trees, [&](const auto& t) { return !kept(t.host_object); });
    std::erase_if(p.active_deformations, [&](const auto& d) { return !kept(d.target_object); });
    p.connections.clear();
    p.session.steps.clear();
    p.session.tasks.clear();
    return p;
  }();
  return s;
}

/// The farthest a node of `body` gets from where it was, over `steps` steps of the world.
double largest_travel(World& world, int body, int steps) {
  const auto range = world.state().bodies().at(static_cast<std::size_t>(body));
  const std::vector<core::Vec3> before = world.state().positions;
  double travel = 0.0;
  for (int s = 0; s < steps; ++s) {
    world.step();
    for (int i = range.first; i < range.first + range.count; ++i) {
      const auto n = static_cast<std::size_t>(i);
      travel = std::max(travel, (world.state().positions[n] - before[n]).norm());
    }
  }
  return travel;
}

const ExplicitVerlet& verlet(const World& world) {
  return dynamic_cast<const ExplicitVerlet&>(world.integrator());
}

TEST(ExplicitSettle,
     the_vessels_start_at_their_sag_the_vein_sleeps_and_the_pulsing_artery_does_not) {
  World world(artery_and_vein());
  ASSERT_EQ(world.integrator().name(), "explicit-verlet");
  world.set_sleep_threshold(1e-7);
  const int artery = world.body_index("artery-uterine-left");
  const int vein = world.body_index("vein-uterine-left");
  ASSERT_GE(artery, 0);
  ASSERT_GE(vein, 0);

  const World::Settling settling = world.settle();
  EXPECT_TRUE(settling.at_rest);
  EXPECT_GT(settling.steps, 0);
  EXPECT_EQ(world.time(), 0.0);
  EXPECT_FALSE(world.asleep());  // the pulse drives the artery

  // The vein hangs by a measurable amount and, settled, moves less than a micrometre in its
  // first 0.3 s, after which it sleeps; from its authored shape it swings by far more.
  double vein_sag = 0.0;
  const auto vein_range = world.state().bodies().at(static_cast<std::size_t>(vein));
  for (int i = vein_range.first; i < vein_range.first + vein_range.count; ++i) {
    const auto n = static_cast<std::size_t>(i);
    vein_sag =
        std::max(vein_sag, (world.state().positions[n] - world.state().rest_positions[n]).norm());
  }
  EXPECT_GT(vein_sag, 1e-4);
  EXPECT_LT(largest_travel(world, vein, 300), 1e-6);
  EXPECT_EQ(verlet(world).islands_asleep(), 1);

  // Over the next two beats (72 /min) the artery keeps pulsing: its knots travel tens of
  // micrometres between steps 300 and 2,000, and its island never falls asleep.
  EXPECT_GT(largest_travel(world, artery, 1700), 1e-5);
  EXPECT_EQ(verlet(world).islands_asleep(), 1);

  World authored(artery_and_vein());
  authored.set_sleep_threshold(1e-7);
  EXPECT_GT(largest_travel(authored, vein, 300), 0.3 * vein_sag);
}

}  // namespace
}  // namespace viscera::sim
