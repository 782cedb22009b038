// linear_fit: least squares and R^2; power_fit: the exponent of y = a + b x^k with its profile confidence interval;
// fit_growth: both on a series of timings against size, with the verdict.
#include "clothbench/experiments/statistics.hpp"

#include <algorithm>
#include <boost/math/distributions/fisher_f.hpp>
#include <cmath>
#include <limits>
#include <utility>

#include "clothbench/bench/report.hpp"

namespace clothbench {

void linear_fit(const std::vector<double>& x, const std::vector<double>& y, double& a, double& b, double& r2) {
  const double n = double(x.size());
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < x.size(); ++i) sx += x[i], sy += y[i], sxx += x[i] * x[i], sxy += x[i] * y[i];
  b = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  a = (sy - b * sx) / n;
  double ss_res = 0, ss_tot = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    ss_res += std::pow(y[i] - (a + b * x[i]), 2);
    ss_tot += std::pow(y[i] - sy / n, 2);
  }
  r2 = ss_tot > 0 ? 1 - ss_res / ss_tot : 1;
}

namespace {

// the residual sum of squares of y = a + b x^k at a fixed k (a linear least squares in x^k)
double power_sse(const std::vector<double>& x, const std::vector<double>& y, double k, double& a, double& b) {
  std::vector<double> xk(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) xk[i] = std::pow(x[i], k);
  double r2 = 0;
  linear_fit(xk, y, a, b, r2);
  double sse = 0;
  for (std::size_t i = 0; i < x.size(); ++i) sse += std::pow(y[i] - (a + b * xk[i]), 2);
  return sse;
}

}  // namespace

PowerFit power_fit(const std::vector<double>& x, const std::vector<double>& y, double confidence) {
  PowerFit f;
  const std::size_t n = x.size();
  if (n < 4) return f;  // three parameters and at least one degree of freedom left
  // x scaled to its largest value keeps x^k in range for every k of the grid (b scales, k does not)
  double scale = 0;
  for (double v : x) scale = std::max(scale, v);
  std::vector<double> xs(n);
  for (std::size_t i = 0; i < n; ++i) xs[i] = x[i] / scale;
  constexpr double kLow = 0.2, kHigh = 3, kStep = 0.005;
  std::vector<double> ks, sses;
  double best = std::numeric_limits<double>::infinity();
  for (double k = kLow; k <= kHigh + 1e-12; k += kStep) {
    double a = 0, b = 0;
    const double sse = power_sse(xs, y, k, a, b);
    ks.push_back(k), sses.push_back(sse);
    if (sse < best) best = sse, f.k = k, f.a = a, f.b = b / std::pow(scale, k);
  }
  // profile likelihood interval (Bates & Watts 1988, Nonlinear Regression Analysis, ch. 6): every k whose SSE stays
  // within the F bound
  const double dof = double(n) - 3;
  const double bound = best * (1 + boost::math::quantile(boost::math::fisher_f(1, dof), confidence) / dof);
  f.k_low = kHigh, f.k_high = kLow;
  for (std::size_t i = 0; i < ks.size(); ++i)
    if (sses[i] <= bound) f.k_low = std::min(f.k_low, ks[i]), f.k_high = std::max(f.k_high, ks[i]);
  f.at_grid_edge = f.k_low <= kLow + kStep / 2 || f.k_high >= kHigh - kStep / 2;  // the grid sums steps: not exact
  return f;
}

Growth judge_growth(const PowerFit& medians, const std::vector<PowerFit>& series) {
  if (medians.at_grid_edge) return Growth::kUndecided;
  if (medians.linear()) return Growth::kLinear;
  const bool above = medians.k_low > 1;
  for (const PowerFit& s : series)
    if ((s.k > 1) != above) return Growth::kStraddles;
  return above ? Growth::kAbove : Growth::kBelow;
}

const char* growth_text(Growth g) {
  switch (g) {
    case Growth::kLinear: return "linear (1 inside the interval)";
    case Growth::kAbove: return "above linear (every repeated series too)";
    case Growth::kBelow: return "below linear (every repeated series too)";
    case Growth::kUndecided: return "undecided (the sizes do not bound the exponent)";
    case Growth::kStraddles: return "undecided (the interval excludes 1, the repeated series lie on both sides of it)";
  }
  return "";
}

GrowthFit fit_growth(const std::vector<double>& x, const std::vector<double>& y,
                     const std::vector<std::vector<double>>& runs) {
  GrowthFit f;
  double a = 0, b = 0;
  linear_fit(x, y, a, b, f.r2);
  for (std::size_t i = 0; i < x.size(); ++i) f.residual = std::max(f.residual, std::abs(y[i] - (a + b * x[i])) / y[i]);
  f.medians = power_fit(x, y);
  for (const auto& run : runs) f.repeated.push_back(power_fit(x, run));
  f.growth = judge_growth(f.medians, f.repeated);
  return f;
}

Spread spread(std::vector<double> v) {
  if (v.empty()) return {};
  std::sort(v.begin(), v.end());
  return {v[v.size() / 2], v.front(), v.back(), v.size()};
}

std::string runs_text(const Spread& s, int digits) {
  if (s.runs < 2) return "one run";
  return "median of " + std::to_string(s.runs) + " runs, " + num(s.lo, digits) + "-" + num(s.hi, digits);
}

std::string median_range(std::vector<double> v, int digits) {
  if (v.empty()) return "-";
  const Spread s = spread(std::move(v));
  return num(s.median, digits) + " (" + num(s.lo, digits) + "-" + num(s.hi, digits) + ")";
}

}  // namespace clothbench
