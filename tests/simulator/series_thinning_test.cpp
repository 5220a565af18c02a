// The bounded series of a session report (issue 21 §4): an hour's report keeps no more samples
// than its capacity, evenly spaced over the whole session.

#include "simulator/session/series_thinning.h"

#include <gtest/gtest.h>

#include <vector>

namespace viscera::sim {
namespace {

TEST(SeriesThinning, keeps_everything_below_its_capacity) {
  SeriesThinning thinning(64);
  std::vector<long long> series;
  for (long long i = 0; i < 64; ++i)
    thinning.offer(series, i, i);
  ASSERT_EQ(series.size(), 64u);
  EXPECT_EQ(thinning.stride(), 1);
  for (long long i = 0; i < 64; ++i)
    EXPECT_EQ(series[static_cast<std::size_t>(i)], i);
}

TEST(SeriesThinning, a_long_series_stays_within_capacity_and_covers_the_whole_run_evenly) {
  SeriesThinning thinning(100);
  std::vector<long long> series;
  const long long offered = 1'000'000;
  for (long long i = 0; i < offered; ++i)
    thinning.offer(series, i, i);
  ASSERT_LE(series.size(), 100u);
  ASSERT_GE(series.size(), 50u);  // never thinned below half
  EXPECT_EQ(series.front(), 0);
  const long long stride = thinning.stride();
  EXPECT_EQ(stride, 16384);  // 1e6 / 100 rounded up to a power of two
  for (std::size_t i = 1; i < series.size(); ++i)
    EXPECT_EQ(series[i] - series[i - 1], stride) << "at entry " << i;
  EXPECT_GT(series.back(), offered - stride - 1);  // reaches the end of the run
}

TEST(SeriesThinning, the_last_sample_is_kept_off_the_stride) {
  SeriesThinning thinning(10);
  std::vector<long long> series;
  for (long long i = 0; i < 37; ++i)
    thinning.offer(series, i, i);
  thinning.offer(series, 37, 37LL, true);
  EXPECT_EQ(series.back(), 37);
  EXPECT_EQ(series.front(), 0);
}

TEST(SeriesThinning, the_same_offers_give_the_same_series) {
  // A replay thins its checkpoints as the recording did: the rule depends only on the numbers.
  SeriesThinning a(16), b(16);
  std::vector<long long> first, second;
  for (long long i = 0; i < 5000; i += 1) {
    a.offer(first, i, i * 7);
    if (b.due(i)) b.offer(second, i, i * 7);  // the session asks due() before a costly hash
  }
  EXPECT_EQ(first, second);
}

}  // namespace
}  // namespace viscera::sim
