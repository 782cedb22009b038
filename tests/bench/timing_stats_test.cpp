// The gate's statistics on synthetic samples (no timing is measured here): identical distributions
// must not be called a regression, a 1.3x slow-down with 9 repetitions must be, at the noise this
// machine shows between repetitions.
#include "clothbench/bench/timing_stats.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace clothbench {
namespace {

// the spread of repeated runs here: `reproduce --quick --repetitions 9 --only dressing-t1,dressing-t2,dressing-f8,
// integrators` measured a coefficient of variation of 1.3 % (median of 96 configurations), 2.4 % (90th
// percentile) and 7.4 % at most (2026-11-24); the test's 10 % is above all of them
constexpr double kNoise = 0.10;

std::vector<double> sample(std::mt19937& rng, int n, double scale) {
  std::normal_distribution<double> log_noise(0, kNoise);
  std::vector<double> v;
  for (int i = 0; i < n; ++i) v.push_back(scale * std::exp(log_noise(rng)));
  return v;
}

// how many of 100 trials compare_timings flags, old at 1 ms against new at `factor` ms
int flagged(double factor, int reps, unsigned seed) {
  std::mt19937 rng(seed);
  int n = 0;
  for (int trial = 0; trial < 100; ++trial) {
    const auto old_t = sample(rng, reps, 1.0), new_t = sample(rng, reps, factor);
    n += compare_timings(old_t, new_t, 0.10).regression;
  }
  return n;
}

TEST(TimingStats, IdenticalDistributionsAreNotARegressionInAtLeast95Of100Trials) {
  for (unsigned seed : {1u, 2u, 3u}) EXPECT_LE(flagged(1.0, 9, seed), 5) << "seed " << seed;
}

TEST(TimingStats, ASlowDownOf30PercentWithNineRepetitionsIsFlaggedInAtLeast95Of100Trials) {
  for (unsigned seed : {1u, 2u, 3u}) EXPECT_GE(flagged(1.3, 9, seed), 95) << "seed " << seed;
}

TEST(TimingStats, NoVerdictBelowTheMinimumRepetitions) {
  const TimingComparison c = compare_timings({1, 1.01, 0.99}, {2, 2.02, 1.98}, 0.1);
  EXPECT_FALSE(c.judged);
  EXPECT_FALSE(c.regression);  // twice as slow, but three runs cannot say so at p < 0.05
  EXPECT_NEAR(c.ratio, 2.0, 0.03);
}

TEST(TimingStats, TheRatioIntervalCoversTheTrueFactorAbout95PercentOfTheTime) {
  std::mt19937 rng(7);
  int covered = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const auto old_t = sample(rng, 9, 1.0), new_t = sample(rng, 9, 1.5);
    const TimingComparison c = compare_timings(old_t, new_t, 0.1);
    ASSERT_TRUE(c.judged);
    ASSERT_LE(c.ratio_lo, c.ratio);
    ASSERT_LE(c.ratio, c.ratio_hi);
    covered += c.ratio_lo <= 1.5 && 1.5 <= c.ratio_hi;
  }
  EXPECT_GE(covered, 180);  // 95 % nominal; binomial spread at n = 200 is about 3 %
  EXPECT_LE(covered, 200);
  // the other way round it is faster, not slower
  const auto old_t = sample(rng, 9, 1.0), new_t = sample(rng, 9, 1.5);
  const TimingComparison back = compare_timings(new_t, old_t, 0.1);
  EXPECT_GT(back.p_slower, 0.99);
  EXPECT_FALSE(back.regression);
}

TEST(TimingStats, Aggregates) {
  const std::vector<double> v{1, 2, 3, 4};
  EXPECT_DOUBLE_EQ(median(v), 2.5);
  EXPECT_DOUBLE_EQ(mean(v), 2.5);
  EXPECT_NEAR(stddev(v), std::sqrt(5.0 / 3.0), 1e-12);
  EXPECT_DOUBLE_EQ(stddev({3}), 0);
}

}  // namespace
}  // namespace clothbench
