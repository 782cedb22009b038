#pragma once
// test helper: a collider's contacts against the exact reference, with the worst differences
#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>
#include <vector>

#include "clothbench/sim/collider.hpp"
#include "test_support.hpp"

namespace clothbench::test {

/// Worst differences between contacts and an exact reference (depth compared where both hit).
struct ContactDiff {
  std::size_t points = 0;
  std::size_t hit_mismatch = 0;
  double depth_max = 0;     ///< [m]
  double normal_max = 0;    ///< [deg]
  double velocity_max = 0;  ///< worst |dv| / max(1 % |v_ref|, 1e-4 m/s); <= 1 passes
  std::size_t first_mismatch = 0;
  double hit_agreement() const { return points ? 1.0 - double(hit_mismatch) / double(points) : 1.0; }
};

inline ContactDiff compare_contacts(const std::vector<Contact>& got, const std::vector<Contact>& ref) {
  ContactDiff d;
  d.points = ref.size();
  for (std::size_t i = 0; i < ref.size(); ++i) {
    if (got[i].hit != ref[i].hit) {
      if (d.hit_mismatch++ == 0) d.first_mismatch = i;
      continue;
    }
    if (!ref[i].hit) continue;
    d.depth_max = std::max(d.depth_max, double(std::abs(got[i].depth - ref[i].depth)));
    d.normal_max = std::max(d.normal_max, angle_deg(got[i].normal, ref[i].normal));
    const double allowed = std::max(0.01 * double(ref[i].body_velocity.norm()), 1e-4);
    d.velocity_max = std::max(d.velocity_max, double((got[i].body_velocity - ref[i].body_velocity).norm()) / allowed);
  }
  return d;
}

inline std::string describe(const ContactDiff& d) {
  std::ostringstream s;
  s << d.points << " points: hit agreement " << 100.0 * d.hit_agreement() << " % (" << d.hit_mismatch
    << " differ, first #" << d.first_mismatch << "), depth error max " << d.depth_max << " m, normal error max "
    << d.normal_max << " deg, velocity error max " << d.velocity_max << " x allowed";
  return s.str();
}

}  // namespace clothbench::test
