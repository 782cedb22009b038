// linear_fit: least squares and R^2.
#include "clothbench/experiments/statistics.hpp"

#include <cmath>

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

}  // namespace clothbench
