#include "simulator/physics/spring_pulls.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <limits>

#include "core/random.h"

namespace viscera::sim {
namespace {

/// A random net of `count` springs over 40 knots with stretched, compressed, damped and
/// zero-length springs, the last spring ending on the last knot (the four-wide loads there).
struct RandomNet {
  std::vector<core::Vec3> x, v;
  CubicSprings springs;
};

RandomNet random_net(std::size_t count, std::uint64_t seed) {
  core::Rng rng(seed);
  RandomNet net;
  for (int n = 0; n < 40; ++n) {
    net.x.emplace_back(rng.uniform(-0.02, 0.02), rng.uniform(-0.02, 0.02),
                       rng.uniform(-0.02, 0.02));
    net.v.emplace_back(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
  }
  net.x[7] = net.x[3];  // springs 3–7 have no length
  for (std::size_t s = 0; s < count; ++s) {
    int i = static_cast<int>(rng.uniform(0, 39.99)), j = static_cast<int>(rng.uniform(0, 39.99));
    if (i == j) j = (i + 1) % 40;
    if (s == count - 1) j = 39;
    if (s == count - 1 && i == 39) i = 0;
    if (s % 11 == 5) i = 3, j = 7;
    net.springs.knots.push_back({i, j});
    const double length =
        (net.x[static_cast<std::size_t>(j)] - net.x[static_cast<std::size_t>(i)]).norm();
    net.springs.rest_length.push_back(length > 0.0 ? length * rng.uniform(0.7, 1.3) : 0.004);
    net.springs.coefficients.push_back(
        {rng.uniform(0.5, 5.0), rng.uniform(-20.0, 40.0), rng.uniform(0.0, 400.0)});
    net.springs.damping.push_back(rng.uniform(0.0, 0.5));
  }
  return net;
}

bool same_bits(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

TEST(SpringPulls, four_wide_gives_the_bits_of_one_at_a_time) {
  if (!four_wide_springs_supported()) GTEST_SKIP() << "this processor has no AVX2";
  for (const std::size_t count : {1u, 4u, 7u, 64u, 257u}) {
    const RandomNet net = random_net(count, 17 + count);
    for (const bool damped : {false, true}) {
      std::vector<SpringPull> one(count), four(count);
      compute_spring_pulls(net.x, net.v, net.springs, damped, 0, count, one.data(),
                           SpringKernel::OneAtATime);
      compute_spring_pulls(net.x, net.v, net.springs, damped, 0, count, four.data(),
                           SpringKernel::FourWide);
      for (std::size_t s = 0; s < count; ++s) {
        EXPECT_TRUE(same_bits(one[s].x, four[s].x) && same_bits(one[s].y, four[s].y) &&
                    same_bits(one[s].z, four[s].z) && same_bits(one[s].energy, four[s].energy))
            << "spring " << s << " of " << count << (damped ? " damped" : "");
      }
    }
  }
}

TEST(SpringPulls, a_range_starting_mid_net_gives_the_same_pulls) {
  const RandomNet net = random_net(64, 5);
  std::vector<SpringPull> whole(64), part(61);
  compute_spring_pulls(net.x, net.v, net.springs, true, 0, 64, whole.data());
  compute_spring_pulls(net.x, net.v, net.springs, true, 3, 64, part.data());
  for (std::size_t s = 3; s < 64; ++s) {
    EXPECT_TRUE(same_bits(whole[s].x, part[s - 3].x) &&
                same_bits(whole[s].energy, part[s - 3].energy))
        << s;
  }
}

TEST(SpringPulls, pulls_follow_the_cubic_and_the_damping_element) {
  // Knots 1 cm apart along x, rest length 8 mm: ε = 0.25; knot 1 moving away at 2 m/s.
  CubicSprings springs{
      {{0, 1}, {1, 2}}, {0.008, 0.01}, {{{2.0, 30.0, 400.0}}, {{1, 0, 0}}}, {0.5, 0.0}};
  const std::vector<core::Vec3> x = {{0, 0, 0}, {0.01, 0, 0}, {0.01, 0, 0}};
  const std::vector<core::Vec3> v = {{0, 0, 0}, {2.0, 0, 0}, {0, 0, 0}};
  std::vector<SpringPull> p(2);
  compute_spring_pulls(x, v, springs, true, 0, 2, p.data());
  const double e = 0.25;
  const double cubic = 2.0 * e + 30.0 * e * e + 400.0 * e * e * e;
  EXPECT_NEAR(p[0].x, cubic + 0.5 * 2.0, 1e-12);
  EXPECT_EQ(p[0].y, 0.0);
  EXPECT_NEAR(p[0].energy,
              0.008 * (2.0 * e * e / 2 + 30.0 * e * e * e / 3 + 400.0 * std::pow(e, 4) / 4), 1e-15);
  EXPECT_LT(p[1].energy, 0.0);  // no length: no pull
  EXPECT_EQ(p[1].x, 0.0);
}

}  // namespace
}  // namespace viscera::sim
