#pragma once
/// Statistics of repeated timings: the aggregates Google Benchmark writes for repetitions, and the
/// comparison `clothbench compare` gates on (one-sided Mann-Whitney U test, Hodges-Lehmann ratio with
/// its distribution-free confidence interval).
#include <string>
#include <vector>

namespace clothbench {

double median(std::vector<double> v);
double mean(const std::vector<double>& v);
/// Sample standard deviation (n - 1); 0 for fewer than two values.
double stddev(const std::vector<double>& v);

/// One side needs at least this many repetitions for a verdict: below it the one-sided U test cannot
/// reach p < 0.05 at all (3 against 3: the smallest p is 1/20) or has little power.
inline constexpr int kMinRepetitions = 5;

/// Old against new timings of one benchmark.
struct TimingComparison {
  int n_old = 0, n_new = 0;
  double ratio = 0;               ///< Hodges-Lehmann estimate of new / old (median of the pairwise ratios)
  double ratio_lo = 0, ratio_hi = 0;  ///< its 95 % confidence interval (distribution-free, from U's quantiles)
  double p_slower = 1;            ///< one-sided Mann-Whitney p that new is slower than old
  bool judged = false;            ///< both sides have kMinRepetitions or more
  bool regression = false;        ///< judged, p_slower < 0.05 and ratio > 1 + threshold
};

/// Compares two samples of positive times; `threshold` is the slow-down that counts (0.1 = 10 %).
TimingComparison compare_timings(const std::vector<double>& old_t, const std::vector<double>& new_t,
                                 double threshold);

}  // namespace clothbench
