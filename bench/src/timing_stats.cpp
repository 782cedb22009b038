// Aggregates and the gate's statistics (timing_stats.hpp).
#include "clothbench/bench/timing_stats.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace clothbench {

double median(std::vector<double> v) {
  if (v.empty()) return NAN;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

double mean(const std::vector<double>& v) {
  return v.empty() ? NAN : std::accumulate(v.begin(), v.end(), 0.0) / double(v.size());
}

double stddev(const std::vector<double>& v) {
  if (v.size() < 2) return 0;
  const double m = mean(v);
  double ss = 0;
  for (double x : v) ss += (x - m) * (x - m);
  return std::sqrt(ss / double(v.size() - 1));
}

namespace {

// U of new against old: pairs where the new time is larger, ties count one half
double u_statistic(const std::vector<double>& old_t, const std::vector<double>& new_t) {
  double u = 0;
  for (double x : old_t)
    for (double y : new_t) u += y > x ? 1 : y == x ? 0.5 : 0;
  return u;
}

// one-sided p of U >= u under equal distributions: normal approximation with continuity correction
double p_at_least(double u, double n1, double n2) {
  const double mu = n1 * n2 / 2, sd = std::sqrt(n1 * n2 * (n1 + n2 + 1) / 12);
  return 0.5 * std::erfc((u - 0.5 - mu) / sd / std::sqrt(2.0));
}

}  // namespace

TimingComparison compare_timings(const std::vector<double>& old_t, const std::vector<double>& new_t,
                                 double threshold) {
  TimingComparison c;
  c.n_old = static_cast<int>(old_t.size());
  c.n_new = static_cast<int>(new_t.size());
  if (old_t.empty() || new_t.empty()) return c;
  // Hodges-Lehmann on log times: the median of the pairwise log ratios, and the 95 % interval between
  // the k-th smallest and k-th largest of them, k from U's normal quantile (Lehmann 1975)
  std::vector<double> d;
  for (double x : old_t)
    for (double y : new_t) d.push_back(std::log(y / x));
  std::sort(d.begin(), d.end());
  const double n1 = c.n_old, n2 = c.n_new, m = double(d.size());
  c.ratio = std::exp(median(d));
  const double k = std::floor(n1 * n2 / 2 - 1.96 * std::sqrt(n1 * n2 * (n1 + n2 + 1) / 12));
  const std::size_t lo = static_cast<std::size_t>(std::clamp(k, 0.0, m - 1));
  c.ratio_lo = std::exp(d[lo]);
  c.ratio_hi = std::exp(d[d.size() - 1 - lo]);
  c.p_slower = p_at_least(u_statistic(old_t, new_t), n1, n2);
  c.judged = c.n_old >= kMinRepetitions && c.n_new >= kMinRepetitions;
  c.regression = c.judged && c.p_slower < 0.05 && c.ratio > 1 + threshold;
  return c;
}

}  // namespace clothbench
