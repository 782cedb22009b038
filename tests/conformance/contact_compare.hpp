#pragma once
// test helper: a collider's contacts against the exact reference, with the worst differences
#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>
#include <vector>

#include "clothbench/sim/collider.hpp"
#include "test_support.hpp"

namespace clothbench::test {

/// The collider's answers to one query of `points`.
inline std::vector<Contact> run(Collider& c, const Points3& points) {
  std::vector<Contact> out(std::size_t(points.cols()));
  c.query(points, {out.data(), out.size()});
  return out;
}

/// Worst differences between contacts and an exact reference (depth compared where both hit).
struct ContactDiff {
  std::size_t points = 0;
  std::size_t hit_mismatch = 0;
  double depth_max = 0;     ///< [m]
  double normal_max = 0;    ///< [deg]
  double velocity_max = 0;  ///< worst |dv| / max(1 % |v_ref|, 1e-4 m/s); <= 1 passes
  std::size_t first_mismatch = 0;
  std::size_t shell_mismatch = 0;  ///< of hit_mismatch: reference depth within `shell` of tol
  std::size_t both_hit = 0;        ///< points both answer hit
  double depth_sum = 0;            ///< [m], over both_hit
  std::vector<double> depth_errors, normal_errors, velocity_errors;  ///< per both_hit point, as the maxima
  double hit_agreement() const { return points ? 1.0 - double(hit_mismatch) / double(points) : 1.0; }
  /// hit/no-hit agreement not counting the mismatches within the shell around tol
  double hit_agreement_off_shell() const {
    return points ? 1.0 - double(hit_mismatch - shell_mismatch) / double(points) : 1.0;
  }
  double depth_mean() const { return both_hit ? depth_sum / double(both_hit) : 0.0; }
  /// the q-quantile (0..1) of per-point errors (0 when none)
  static double quantile(std::vector<double> errors, double q) {
    if (errors.empty()) return 0.0;
    const auto k = static_cast<std::ptrdiff_t>(q * double(errors.size() - 1));
    std::nth_element(errors.begin(), errors.begin() + k, errors.end());
    return errors[std::size_t(k)];
  }
};

/// Differences of `got` from `ref`; a hit mismatch where the reference depth is within `shell`
/// [m] of `tol` [m] is also counted in shell_mismatch (the exact references answer every depth).
inline ContactDiff compare_contacts(const std::vector<Contact>& got, const std::vector<Contact>& ref,
                                    double tol = ColliderOptions{}.tol, double shell = 0) {
  ContactDiff d;
  d.points = ref.size();
  for (std::size_t i = 0; i < ref.size(); ++i) {
    if (got[i].hit != ref[i].hit) {
      if (d.hit_mismatch++ == 0) d.first_mismatch = i;
      d.shell_mismatch += std::abs(double(ref[i].depth) - tol) < shell;
      continue;
    }
    if (!ref[i].hit) continue;
    const double dd = std::abs(double(got[i].depth) - double(ref[i].depth));
    d.depth_max = std::max(d.depth_max, dd);
    d.depth_sum += dd;
    ++d.both_hit;
    d.depth_errors.push_back(dd);
    d.normal_errors.push_back(angle_deg(got[i].normal, ref[i].normal));
    d.normal_max = std::max(d.normal_max, d.normal_errors.back());
    const double allowed = std::max(0.01 * double(ref[i].body_velocity.norm()), 1e-4);
    d.velocity_errors.push_back(double((got[i].body_velocity - ref[i].body_velocity).norm()) / allowed);
    d.velocity_max = std::max(d.velocity_max, d.velocity_errors.back());
  }
  return d;
}

inline std::string describe(const ContactDiff& d) {
  std::ostringstream s;
  s << d.points << " points: hit agreement " << 100.0 * d.hit_agreement() << " % (" << d.hit_mismatch
    << " differ, " << d.shell_mismatch << " within the shell, first #" << d.first_mismatch << "), depth error max "
    << d.depth_max << " m, mean " << d.depth_mean() << " m, p99 " << ContactDiff::quantile(d.depth_errors, 0.99)
    << " m, normal error max " << d.normal_max << " deg, p90 " << ContactDiff::quantile(d.normal_errors, 0.9)
    << " deg, velocity error max " << d.velocity_max << " x allowed, p99 "
    << ContactDiff::quantile(d.velocity_errors, 0.99);
  return s.str();
}

}  // namespace clothbench::test
