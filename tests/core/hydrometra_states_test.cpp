#include "core/scenario/hydrometra_states.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "core/package/hydrometra_file.h"
#include "core/package/scenario_package.h"
#include "tests/core/scenario_fixtures.h"
#include "tests/support/test_paths.h"

namespace viscera::core {
namespace {

/// Five states 200 Pa apart over three nodes, each node's displacement a different nonlinear
/// function of the pressure (so a wrong bracket or weight shows).
HydrometraStates five_states() {
  HydrometraStates s;
  s.node_count = 3;
  for (int k = 0; k < 5; ++k) {
    const double p = 200.0 * k;
    s.pressures.push_back(p);
    for (int n = 0; n < 3; ++n)
      s.displacements.push_back(
          Vec3(std::sqrt(p) * 1e-4 * (n + 1), p * p * 1e-9, -std::sin(p * 1e-3 + n) * 1e-3));
  }
  return s;
}

TEST(HydrometraStates, a_stored_pressure_gives_its_state_exactly) {
  const HydrometraStates s = five_states();
  std::vector<Vec3> out(3);
  for (int k = 0; k < s.state_count(); ++k) {
    interpolate_hydrometra(s, s.pressures[static_cast<std::size_t>(k)], out);
    for (int n = 0; n < 3; ++n)
      EXPECT_EQ(out[static_cast<std::size_t>(n)], s.state(k)[static_cast<std::size_t>(n)])
          << "state " << k << " node " << n;
  }
}

TEST(HydrometraStates, half_way_gives_the_mean_of_the_neighbours) {
  const HydrometraStates s = five_states();
  std::vector<Vec3> out(3);
  for (int k = 0; k + 1 < s.state_count(); ++k) {
    const double p = 0.5 * (s.pressures[static_cast<std::size_t>(k)] +
                            s.pressures[static_cast<std::size_t>(k) + 1]);
    interpolate_hydrometra(s, p, out);
    for (int n = 0; n < 3; ++n) {
      const Vec3 mean = 0.5 * (s.state(k)[static_cast<std::size_t>(n)] +
                               s.state(k + 1)[static_cast<std::size_t>(n)]);
      EXPECT_EQ(out[static_cast<std::size_t>(n)], mean) << "interval " << k << " node " << n;
    }
  }
  // A quarter of the way: linear in pressure, not in the state index.
  interpolate_hydrometra(s, 250.0, out);
  EXPECT_NEAR(out[1].x(), 0.75 * s.state(1)[1].x() + 0.25 * s.state(2)[1].x(), 1e-18);
}

TEST(HydrometraStates, pressures_outside_the_range_are_clamped) {
  const HydrometraStates s = five_states();
  std::vector<Vec3> out(3);
  interpolate_hydrometra(s, -500.0, out);
  EXPECT_EQ(out[2], s.state(0)[2]);
  interpolate_hydrometra(s, 1e9, out);
  EXPECT_EQ(out[2], s.state(4)[2]);
  interpolate_hydrometra(s, std::nan(""), out);
  EXPECT_EQ(out[2], s.state(0)[2]);
  const PressureBracket b = bracket_pressure(s.pressures, 799.0);
  EXPECT_EQ(b.lower, 3);
  EXPECT_EQ(b.upper, 4);
  EXPECT_DOUBLE_EQ(b.t, 0.995);
  std::vector<Vec3> wrong(2);
  EXPECT_THROW(interpolate_hydrometra(s, 10.0, wrong), UsageError);
}

TEST(HydrometraFile, bytes_read_back_bit_for_bit_and_damage_is_refused) {
  const HydrometraStates s = five_states();
  const std::string bytes = hydrometra_bytes(s);
  EXPECT_EQ(bytes.size(), 24u + 8u * 5u + 24u * 5u * 3u);
  EXPECT_EQ(bytes.substr(0, 8), "VHYDRO01");
  EXPECT_EQ(read_hydrometra_bytes(bytes, "h.bin"), s);
  EXPECT_EQ(hydrometra_bytes(read_hydrometra_bytes(bytes, "h.bin")), bytes);
  EXPECT_THROW(read_hydrometra_bytes(bytes.substr(0, bytes.size() - 1), "h.bin"), InputError);
  std::string magic = bytes;
  magic[0] = 'X';
  EXPECT_THROW(read_hydrometra_bytes(magic, "h.bin"), InputError);
  // Pressures out of order (state 2 set to state 1's pressure) are refused.
  HydrometraStates unordered = s;
  unordered.pressures[2] = unordered.pressures[1];
  EXPECT_THROW(read_hydrometra_bytes(hydrometra_bytes(unordered), "h.bin"), InputError);
}

TEST(HydrometraFile, a_package_keeps_the_states_in_its_own_file) {
  const auto dir = viscera::testing::scratch_dir();
  const Scenario scenario = viscera::testing::full_scenario();
  const HydrometraStates& states = scenario.objects[0].hydrometra;
  ASSERT_FALSE(states.empty());
  write_package(scenario, dir / "p.vscene");
  EXPECT_EQ(viscera::testing::file_bytes(dir / "p.vscene" / hydrometra_file_of("uterus")),
            hydrometra_bytes(states));
  const Scenario back = read_package(dir / "p.vscene");
  EXPECT_EQ(back.objects[0].hydrometra, states);
  EXPECT_TRUE(back.objects[1].hydrometra.empty());

  // States that do not fit the body are refused when writing.
  Scenario wrong = scenario;
  wrong.objects[0].hydrometra.node_count += 1;
  wrong.objects[0].hydrometra.displacements.resize(
      wrong.objects[0].hydrometra.displacements.size() + 3);
  EXPECT_THROW(write_package(wrong, dir / "wrong.vscene"), ValidationError);
}

}  // namespace
}  // namespace viscera::core
