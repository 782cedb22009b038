#pragma once
/// Statistics the experiments report beside their tables (timing statistics of runs: bench/timing_stats.hpp).
#include <vector>

namespace clothbench {

/// Least squares y = a + b x over the points, and its R^2.
void linear_fit(const std::vector<double>& x, const std::vector<double>& y, double& a, double& b, double& r2);

}  // namespace clothbench
