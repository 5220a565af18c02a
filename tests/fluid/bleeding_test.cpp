// Bleeding from opened vessels (simulator/fluid/opened_vessels.h, bleeding_sources.h): a cut
// through a vessel of known radius bleeds at the Poiseuille rate the model states and stops when
// the cavity pressure passes the vessel pressure (issue 18 tests); the tree's geometry decides
// which vessels open, and coagulation, a clip between the root and the cut (not one beyond it)
// and clotting of capillary ooze stop the sources they should and no others.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "core/error.h"
#include "simulator/fluid/bleeding_sources.h"
#include "simulator/fluid/distension_balance.h"
#include "simulator/fluid/opened_vessels.h"

using namespace viscera;
using namespace viscera::sim;
using namespace viscera::sim::fluid;

namespace {

/// An arterial tree along z: a root (r 0.5 mm, 20 mm) that forks at z = 20 mm into two branches
/// of r 0.3 mm, one towards +x and one towards −x, each 20 mm long.
core::VesselTree forked_artery() {
  core::VesselTree tree;
  tree.id = "uterine";
  tree.kind = "arterial";
  tree.segments.push_back({0, -1, {0, 0, 0}, {0, 0, 0.02}, 0.5e-3, 0.0});
  tree.segments.push_back({1, 0, {0, 0, 0.02}, {0.01, 0, 0.0373}, 0.3e-3, 0.0});
  tree.segments.push_back({2, 0, {0, 0, 0.02}, {-0.01, 0, 0.0373}, 0.3e-3, 0.0});
  return tree;
}

/// A square cut surface in the plane z = `z`, 60 mm wide, as two triangles over four nodes.
struct CutPlane {
  std::vector<core::Vec3> nodes;
  std::vector<core::Triangle> triangles;
};

CutPlane cut_plane(double z, double half = 0.03) {
  return {{{-half, -half, z}, {half, -half, z}, {half, half, z}, {-half, half, z}},
          {{0, 1, 2}, {0, 2, 3}}};
}

double resistance(double length, double radius) {
  return 8.0 * 3.5e-3 * length / (std::numbers::pi * std::pow(radius, 4));
}

core::FluidSpec saline(double pump_pressure) {
  core::FluidSpec fluid;
  fluid.enabled = true;
  fluid.inflow_pressure = pump_pressure;
  fluid.outflow_pressure = 0.0;
  fluid.overload_volume = 1.0e-3;
  return fluid;
}

}  // namespace

TEST(OpenedVessels, a_cut_across_both_branches_opens_each_with_its_poiseuille_conductance) {
  const core::VesselTree tree = forked_artery();
  const CutPlane cut = cut_plane(0.03);  // 10 mm up the branches, past the fork
  const std::vector<OpenedVessel> opened = find_opened_vessels(tree, cut.nodes, cut.triangles);
  ASSERT_EQ(opened.size(), 2u);
  for (int b = 0; b < 2; ++b) {
    const OpenedVessel& v = opened[static_cast<std::size_t>(b)];
    EXPECT_EQ(v.segment, b + 1);
    EXPECT_EQ(v.path, (std::vector<int>{0, b + 1}));
    EXPECT_EQ(v.level, 1);  // one fork between the root and the branch
    EXPECT_DOUBLE_EQ(v.radius, 0.3e-3);
    EXPECT_NEAR(v.site.z(), 0.03, 1e-12);
    // Feed (one more root) + root + the branch up to the cut, which lies at 10/17.3 of it.
    const double branch = (tree.segments[1].distal - tree.segments[1].proximal).norm();
    const double along = 0.01 / 0.0173;
    const double expected =
        1.0 / (2.0 * resistance(0.02, 0.5e-3) + resistance(along * branch, 0.3e-3));
    EXPECT_NEAR(v.conductance / expected, 1.0, 1e-6);
    EXPECT_DOUBLE_EQ(v.pressure, 11300.0);
  }
}

TEST(OpenedVessels, a_cut_below_the_fork_opens_the_root_only_and_a_cut_that_misses_opens_none) {
  const core::VesselTree tree = forked_artery();
  const CutPlane low = cut_plane(0.005);
  const auto opened = find_opened_vessels(tree, low.nodes, low.triangles);
  ASSERT_EQ(opened.size(), 1u);
  EXPECT_EQ(opened[0].segment, 0);
  EXPECT_EQ(opened[0].level, 0);
  EXPECT_NEAR(opened[0].conductance, 1.0 / resistance(0.025, 0.5e-3), 1e-6 * opened[0].conductance);

  const CutPlane beside = cut_plane(0.03, 0.004);  // 8 mm wide: the branches pass outside it
  EXPECT_TRUE(find_opened_vessels(tree, beside.nodes, beside.triangles).empty());

  core::VesselTree venous = tree;
  venous.kind = "venous";
  EXPECT_DOUBLE_EQ(find_opened_vessels(venous, low.nodes, low.triangles)[0].pressure, 1300.0);
}

TEST(OpenedVessels, a_tree_whose_parents_loop_is_refused_naming_it) {
  core::VesselTree tree = forked_artery();
  tree.segments[0].parent = 2;
  const CutPlane cut = cut_plane(0.03);
  try {
    find_opened_vessels(tree, cut.nodes, cut.triangles);
    FAIL() << "a cyclic tree was accepted";
  } catch (const core::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("uterine"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("cycle"), std::string::npos) << e.what();
  }
}

TEST(Bleeding,
     a_cut_vessel_bleeds_at_its_stated_rate_and_stops_once_the_cavity_passes_its_pressure) {
  const core::VesselTree tree = forked_artery();
  const CutPlane cut = cut_plane(0.005);
  BleedingSources sources;
  ASSERT_EQ(sources.add_cut(0, std::span(&tree, 1), cut.nodes, cut.triangles, 0.0), 1);
  ASSERT_EQ(sources.sources().size(), 2u);  // the root and the cut surface's ooze
  const double g = sources.sources()[0].conductance;

  // Valves shut, cavity empty: the first millisecond bleeds G · P_artery · dt (the cavity fills
  // far more slowly than that: C / G is seconds).
  DistensionBalance cavity(saline(13332.0));
  const double compliance = cavity.channels().cavity_compliance;
  ASSERT_GT(compliance / g, 1.0);
  cavity.set_openings(sources.openings(0.0));
  cavity.step(0.0, 0.0, 1e-3);
  sources.record_step(cavity.last_step_volumes());
  const double expected = g * 11300.0 * 1e-3;
  EXPECT_NEAR(sources.sources()[0].bled / expected, 1.0, 1e-3 + 1e-3 * 1e-3 * g / compliance);
  EXPECT_GT(sources.sources()[1].bled, 0.0);  // the capillary bed oozes too

  // Open the pump at 100 mmHg, above the artery's 85: the cavity passes the vessel pressure,
  // the vessel stops bleeding and takes fluid instead (intravasation).
  double t = 1e-3;
  for (int s = 0; s < 600; ++s, t += 0.05) {
    cavity.set_openings(sources.openings(t));
    cavity.step(1.0, 0.0, 0.05);
    sources.record_step(cavity.last_step_volumes());
  }
  ASSERT_GT(cavity.pressure(), 11300.0);
  const double bled = sources.sources()[0].bled;
  const double taken = sources.sources()[0].intravasated;
  EXPECT_GT(taken, 0.0);
  cavity.set_openings(sources.openings(t));
  cavity.step(1.0, 0.0, 1.0);
  sources.record_step(cavity.last_step_volumes());
  EXPECT_EQ(sources.sources()[0].bled, bled);  // no more blood in
  EXPECT_NEAR(sources.sources()[0].intravasated - taken, g * (cavity.pressure() - 11300.0) * 1.0,
              0.01 * g * (cavity.pressure() - 11300.0));
  EXPECT_EQ(sources.sources()[0].stop, BleedingStop::Bleeding);  // only held back by pressure
}

TEST(Bleeding, coagulation_near_a_site_and_a_clip_upstream_stop_only_their_sources) {
  const core::VesselTree tree = forked_artery();
  const CutPlane cut = cut_plane(0.03);
  BleedingSources sources;
  ASSERT_EQ(sources.add_cut(3, std::span(&tree, 1), cut.nodes, cut.triangles, 2.0), 2);
  ASSERT_EQ(sources.sources().size(), 3u);
  EXPECT_EQ(sources.sources()[2].body, 3);
  EXPECT_TRUE(sources.sources()[2].capillary);
  EXPECT_NEAR(sources.sources()[2].area, 0.06 * 0.06 / 2.0, 1e-12);  // both sides given

  std::vector<core::Vec3> sites;
  for (const BleedingSource& s : sources.sources())
    sites.push_back(site_position(s, cut.nodes));
  EXPECT_NEAR((sites[0] - core::Vec3(0.01 * 10 / 17.3, 0, 0.03)).norm(), 0.0, 1e-5);

  // The electrode touches the +x branch's site only.
  EXPECT_EQ(sources.coagulate(sites[0] + core::Vec3(0, 0.001, 0), 0.002, sites, 5.0), 1);
  EXPECT_EQ(sources.sources()[0].stop, BleedingStop::Coagulated);
  EXPECT_EQ(sources.sources()[0].stopped_at, 5.0);
  EXPECT_EQ(sources.sources()[1].stop, BleedingStop::Bleeding);

  // A clip on the +x branch (downstream of nothing still bleeding) stops nothing; one on the
  // root stops the −x branch, which it feeds.
  EXPECT_EQ(sources.clip("uterine", 1, 6.0), 0);
  EXPECT_EQ(sources.clip("other-tree", 0, 6.0), 0);
  EXPECT_EQ(sources.clip("uterine", 0, 6.0), 1);
  EXPECT_EQ(sources.sources()[1].stop, BleedingStop::Clipped);

  const std::vector<VesselOpening> openings = sources.openings(6.0);
  ASSERT_EQ(openings.size(), 3u);
  EXPECT_EQ(openings[0].conductance, 0.0);
  EXPECT_EQ(openings[1].conductance, 0.0);
  EXPECT_GT(openings[2].conductance, 0.0);  // the ooze still runs
}

TEST(Bleeding, capillary_ooze_decays_with_its_time_constant_and_clots) {
  const CutPlane cut = cut_plane(0.03, 0.005);
  BleedingSources sources;
  EXPECT_EQ(sources.add_cut(0, {}, cut.nodes, cut.triangles, 10.0), 0);
  ASSERT_EQ(sources.sources().size(), 1u);
  const double tau = sources.physiology().ooze_time_constant;
  const double g0 = sources.physiology().capillary_conductance * 0.01 * 0.01 / 2.0;
  EXPECT_NEAR(sources.openings(10.0)[0].conductance / g0, 1.0, 1e-12);
  EXPECT_NEAR(sources.openings(10.0 + tau)[0].conductance / g0, std::exp(-1.0), 1e-12);
  EXPECT_EQ(sources.sources()[0].stop, BleedingStop::Bleeding);
  EXPECT_EQ(sources.openings(10.0 + 4.7 * tau)[0].conductance, 0.0);
  EXPECT_EQ(sources.sources()[0].stop, BleedingStop::Clotted);
}

TEST(Bleeding, a_pulsing_artery_spurts_in_time_with_its_wave_and_a_steady_one_does_not) {
  const core::VesselTree tree = forked_artery();
  const CutPlane cut = cut_plane(0.03);
  BleedingSources sources;
  ASSERT_EQ(sources.add_cut(0, std::span(&tree, 1), cut.nodes, cut.triangles, 0.0), 2);
  // Branch 0 pulses at 75 beats a minute, its wave arriving 5 ms after each beat; branch 1 stays
  // steady.
  sources.set_pulse(0, 0.8, 0.005, 0.25);
  const double mean = sources.sources()[0].pressure;
  EXPECT_NEAR(sources.openings(0.005)[0].pressure, 1.25 * mean, 1e-9 * mean);  // the spurt
  EXPECT_NEAR(sources.openings(0.405)[0].pressure, 0.75 * mean, 1e-9 * mean);  // diastole
  EXPECT_NEAR(sources.openings(0.805)[0].pressure, 1.25 * mean, 1e-9 * mean);  // next beat
  EXPECT_EQ(sources.openings(0.405)[1].pressure, sources.sources()[1].pressure);
  // Over whole beats the pulse averages to the mean pressure.
  double sum = 0.0;
  for (int k = 0; k < 800; ++k)
    sum += sources.openings(0.001 * k)[0].pressure;
  EXPECT_NEAR(sum / 800.0, mean, 1e-9 * mean);
  EXPECT_THROW(sources.set_pulse(7, 0.8, 0.0, 0.25), std::out_of_range);
}

TEST(OpenedVessels, a_hollow_vessel_cut_across_its_wall_ring_opens_and_a_cut_beside_it_does_not) {
  // A vessel body whose wall is all the tissue: the cut's faces ring the lumen (r 2 mm) at
  // z = 10 mm without crossing the axis.
  core::VesselTree tree;
  tree.id = "artery";
  tree.kind = "arterial";
  tree.segments.push_back({0, -1, {0, 0, 0}, {0, 0, 0.02}, 2e-3, 0.0});
  std::vector<core::Vec3> nodes;
  std::vector<core::Triangle> ring;
  for (int k = 0; k < 8; ++k) {
    const double a = 2.0 * std::numbers::pi * k / 8.0, b = 2.0 * std::numbers::pi * (k + 1) / 8.0;
    const int base = static_cast<int>(nodes.size());
    nodes.push_back({1.6e-3 * std::cos(a), 1.6e-3 * std::sin(a), 0.01});
    nodes.push_back({2.4e-3 * std::cos(a), 2.4e-3 * std::sin(a), 0.01});
    nodes.push_back({2.4e-3 * std::cos(b), 2.4e-3 * std::sin(b), 0.01});
    ring.push_back({base, base + 1, base + 2});
  }
  const auto opened = find_opened_vessels(tree, nodes, ring, BleedingPhysiology{});
  ASSERT_EQ(opened.size(), 1u);
  EXPECT_NEAR(opened[0].site.z(), 0.01, 1e-9);
  // The same faces on one side of the axis only (a cut beside a vessel in solid tissue).
  std::vector<core::Triangle> beside(ring.begin(), ring.begin() + 3);
  EXPECT_TRUE(find_opened_vessels(tree, nodes, beside, BleedingPhysiology{}).empty());
}

TEST(Bleeding, a_clip_between_the_root_and_the_opening_stops_it_and_one_beyond_does_not) {
  const core::VesselTree tree = forked_artery();
  const CutPlane cut = cut_plane(0.03);  // opens both branches 10/17.3 of the way along
  BleedingSources sources;
  ASSERT_EQ(sources.add_cut(3, std::span(&tree, 1), cut.nodes, cut.triangles, 2.0), 2);
  const double opening = 0.01 / 0.0173;
  EXPECT_NEAR(sources.sources()[0].along, opening, 1e-9);
  const auto on = [&](int segment, double along) {
    const core::VesselSegment& s = tree.segments[static_cast<std::size_t>(segment)];
    return core::Vec3(s.proximal + along * (s.distal - s.proximal));
  };
  constexpr double kReach = 1.5e-3;

  // Beyond the opening on the +x branch, beside the vessels, on another body or another tree:
  // nothing stops.
  EXPECT_EQ(sources.clip_at(3, tree, on(1, 0.9), kReach, 4.0), 0);
  EXPECT_EQ(sources.clip_at(3, tree, on(1, 0.3) + core::Vec3(0, 0.005, 0), kReach, 4.0), 0);
  EXPECT_EQ(sources.clip_at(0, tree, on(1, 0.3), kReach, 4.0), 0);
  core::VesselTree other = tree;
  other.id = "other-tree";
  EXPECT_EQ(sources.clip_at(3, other, on(1, 0.3), kReach, 4.0), 0);
  EXPECT_EQ(sources.sources()[0].stop, BleedingStop::Bleeding);

  // Upstream of the opening on the same branch: that branch stops, its sister bleeds on.
  EXPECT_EQ(sources.clip_at(3, tree, on(1, 0.3), kReach, 5.0), 1);
  EXPECT_EQ(sources.sources()[0].stop, BleedingStop::Clipped);
  EXPECT_EQ(sources.sources()[0].stopped_at, 5.0);
  EXPECT_EQ(sources.sources()[1].stop, BleedingStop::Bleeding);
  // On the root, which feeds the sister: it stops too (and the clipped one is not counted again).
  EXPECT_EQ(sources.clip_at(3, tree, on(0, 0.5), kReach, 6.0), 1);
  EXPECT_EQ(sources.sources()[1].stop, BleedingStop::Clipped);
  EXPECT_EQ(sources.sources()[0].stopped_at, 5.0);
  EXPECT_EQ(sources.sources()[2].stop, BleedingStop::Bleeding);  // the ooze is not a vessel
}
