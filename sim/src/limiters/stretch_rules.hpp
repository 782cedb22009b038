#pragma once
// The velocity limits' rules for one over-stretched spring (limiter.hpp documents them), inline for the sweep's
// per-spring step. sim/src only.
#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "clothbench/sim/collider.hpp"
#include "clothbench/sim/types.hpp"

namespace clothbench::stretch_rules {

// the length a spring of current length `len` may end the step with: max_len = (1 + threshold) l0, or, one already
// longer, its length shortened by `most` (speed dt) at most: all of the excess in one step would be a speed that
// outlives it
inline Real allowed_length(Real len, Real max_len, Real most) {
  return std::max(max_len, len) - std::max(std::min(len - max_len, most), Real(0));
}

// walking Eq. 5 averages, keeping the relative velocity `target`; with unequal masses the mass-weighted mean keeps
// momentum (the papers' points all have one mass, where both are the same)
inline std::pair<Real, Real> average(Real va, Real vb, Real wa, Real wb, Real target) {
  const Real mean = (wa * va + wb * vb) / (wa + wb);
  return {mean - target * wb / (wa + wb), mean + target * wa / (wa + wb)};
}

// walking Eq. 6: the cosine of the angle between a spring's unit vector u (end a to end b) and the directional vector
// v_dir = v_grav + v_object, v_grav = g dt (zero while sewing: no gravity acts), v_object the velocity of the body
// where the spring's ends collide with it (their mean when both do, zero when neither does); 0 when v_dir is zero
inline Real directional_cos(const Vec3& u, const Vec3& gravity, Real dt, const std::vector<Contact>& contacts, int a,
                            int b) {
  Vec3 v_object = Vec3::Zero();
  if (!contacts.empty()) {
    const Contact& ca = contacts[static_cast<std::size_t>(a)];
    const Contact& cb = contacts[static_cast<std::size_t>(b)];
    if (ca.hit && cb.hit)
      v_object = 0.5f * (ca.body_velocity + cb.body_velocity);
    else if (ca.hit)
      v_object = ca.body_velocity;
    else if (cb.hit)
      v_object = cb.body_velocity;
  }
  const Vec3 v_dir = gravity * dt + v_object;
  return v_dir.norm() > 0 ? u.dot(v_dir.normalized()) : Real(0);
}

// walking Eq. 6 rules: perpendicular springs average, others: the rear point catches up with the front
inline std::pair<Real, Real> directional(Real va, Real vb, Real cos_alpha, Real wa, Real wb, Real target, bool literal) {
  if (std::abs(cos_alpha) < 0.3f) return average(va, vb, wa, wb, target);
  const std::pair<Real, Real> catch_up =
      cos_alpha > 0 ? std::pair<Real, Real>{vb - target, vb} : std::pair<Real, Real>{va, va + target};
  if (literal) return catch_up;
  // our guard: catching up must not add kinetic energy to the pair (it does not keep momentum, and taken literally
  // it diverges on a cloth draped over a sphere); where it would, Eq. 5 instead
  const auto energy = [&](Real a, Real b) { return wa * a * a + wb * b * b; };
  return energy(catch_up.first, catch_up.second) > energy(va, vb) ? average(va, vb, wa, wb, target) : catch_up;
}

}  // namespace clothbench::stretch_rules
