// `directional` (walking Eq. 6, our reading): over-stretched springs about perpendicular to the directional vector
// v_dir = v_grav + v_object average (Eq. 5); on the others the rear point catches up with the front one. A held rear
// point (attached, in contact, or already following one) cannot catch up, so the front follows it and is held in
// turn; catching up that would add kinetic energy averages instead (directional_literal.cpp: the rules as stated).
#include <cmath>
#include <limits>

#include "limiters.hpp"
#include "stretch_rules.hpp"
#include "velocity_sweep.hpp"

namespace clothbench {

namespace {

class Directional final : public VelocitySweep<Directional> {
  using Base = VelocitySweep<Directional>;

 public:
  using Base::Base;

  std::pair<Real, Real> split(int a, int b, const Vec3& u, Real va, Real vb, Real target) {
    const Real cos_a = stretch_rules::directional_cos(u, this->s_->gravity, this->dt_, this->s_->contacts, a, b);
    const int rear = cos_a > 0 ? a : b;
    auto& held = this->held_;
    if (std::abs(cos_a) >= 0.3f && held[static_cast<std::size_t>(rear)]) {
      // a held rear point cannot catch up: the front follows it and is held in turn (our reading)
      const Real na = rear == a ? va : vb - target;
      const int front = rear == a ? b : a;
      if (this->hold(front)) this->mark_changed(front, std::numeric_limits<Real>::infinity());
      return {na, na + target};
    }
    return stretch_rules::directional(va, vb, cos_a, this->mass(a), this->mass(b), target, false);
  }
};

}  // namespace

std::unique_ptr<Limiter> make_directional_limit(const LimiterParams& params) {
  return std::make_unique<Directional>(params);
}

}  // namespace clothbench
