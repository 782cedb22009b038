#pragma once
// Sewn points (Durupinar 3.1): the vertices of a merged group move as one point, shared by the Simulator (merging)
// and the strain limiters (a sewn point is one point to the limit too). sim/src only.
#include <algorithm>
#include <vector>

#include "clothbench/sim/types.hpp"

namespace clothbench {

// Gives each group the mass-weighted mean velocity (and, with `x`, position) of its members, or of its attached
// members when it has any; changed(i, |dv|) is called for each free member whose velocity changed by more than
// 1 um/s.
template <class Changed>
void move_as_one(const std::vector<std::vector<int>>& groups, const Scalars& m, const Scalars& inv_m, Points3& v,
                 Points3* x, Changed&& changed) {
  for (const auto& group : groups) {
    Vec3 xm = Vec3::Zero(), vm = Vec3::Zero();
    Real w = 0;
    const bool attached = std::any_of(group.begin(), group.end(), [&](int i) { return inv_m[i] == 0; });
    for (int i : group) {
      if (attached && inv_m[i] > 0) continue;
      if (x) xm += m[i] * x->col(i);
      vm += m[i] * v.col(i);
      w += m[i];
    }
    for (int i : group) {
      if (inv_m[i] == 0) continue;
      const Real change = (v.col(i) - vm / w).norm();
      if (change > Real(1e-6)) changed(i, change);
      v.col(i) = vm / w;
      if (x) x->col(i) = xm / w;
    }
  }
}

// An impulse J at quad q's midpoint, J/4 to each corner, changes the midpoint's velocity by J times this. point(i):
// the point vertex i moves as (corners of one sewn point move it together); w(i): the inverse mass of that point
// (0: held).
template <class Point, class InverseMass>
Real quad_midpoint_inverse_mass(const Quads& quads, Eigen::Index q, Point&& point, InverseMass&& w) {
  Real sum = 0;
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b)
      if (point(quads(a, q)) == point(quads(b, q))) sum += w(quads(b, q));
  return sum / 16;
}

}  // namespace clothbench
