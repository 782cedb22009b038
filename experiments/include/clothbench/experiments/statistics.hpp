#pragma once
/// Statistics the experiments report beside their tables (timing statistics of runs: bench/timing_stats.hpp).
#include <cstddef>
#include <string>
#include <vector>

namespace clothbench {

/// Least squares y = a + b x over the points, and its R^2.
void linear_fit(const std::vector<double>& x, const std::vector<double>& y, double& a, double& b, double& r2);

/// y = a + b x^k by least squares (k on a grid of 0.005 from 0.2 to 3), and the `confidence` interval of the
/// exponent k from the profile of the residual sum of squares (F test); k = 1 inside it: linear. Needs 4 points.
struct PowerFit {
  double a = 0, b = 0, k = 0;
  double k_low = 0, k_high = 0;
  bool at_grid_edge = false;  ///< the interval reaches the grid's end: the points do not bound the exponent
  /// The points bound the exponent and 1 lies inside its interval.
  bool linear() const { return !at_grid_edge && k_low <= 1 && 1 <= k_high; }
};
PowerFit power_fit(const std::vector<double>& x, const std::vector<double>& y, double confidence = 0.95);

/// How time grows with size, judged on the fit to the medians and on the exponents of the repeated series (run j of
/// every size: a series of its own, so that drift between runs shows). The medians' interval decides; the series can
/// only withhold a departure from linear, when their exponents lie on both sides of 1.
enum class Growth { kLinear, kAbove, kBelow, kUndecided, kStraddles };
Growth judge_growth(const PowerFit& medians, const std::vector<PowerFit>& series);
/// The verdict in words: "linear (1 inside the interval)", "above linear", ...
const char* growth_text(Growth g);

/// Time against size fitted as dressing Fig. 8 is judged: the exponent of the medians `y`, of each repeated series in
/// `runs` (the j-th run of every size), their verdict, and a straight line's R^2 and largest relative residual
/// beside them. x, y and every series list the sizes in one order.
struct GrowthFit {
  PowerFit medians;
  std::vector<PowerFit> repeated;
  Growth growth = Growth::kUndecided;
  double r2 = 0, residual = 0;
};
GrowthFit fit_growth(const std::vector<double>& x, const std::vector<double>& y,
                     const std::vector<std::vector<double>>& runs);

/// How many runs a timing verdict or headline rests on (its configuration run again so many times).
constexpr int kVerdictRuns = 5;

/// Repeated measurements of one thing: their median (of an even count, the upper middle value), least and most.
struct Spread {
  double median = 0, lo = 0, hi = 0;
  std::size_t runs = 0;
};
Spread spread(std::vector<double> v);
/// "median of 5 runs, 13.6-15.9" (`digits` decimals), or "one run" of a single measurement.
std::string runs_text(const Spread& s, int digits);

/// "median (min-max)" of the values, each with `digits` decimals (of an even count, the upper middle value).
std::string median_range(std::vector<double> v, int digits);

}  // namespace clothbench
