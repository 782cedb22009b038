// `velocity` (walking Eq. 5): the stretching components of an over-stretched spring's end velocities go to their
// (mass-weighted) mean, keeping the relative velocity that ends the step at the threshold length.
#include "limiters.hpp"
#include "stretch_rules.hpp"
#include "velocity_sweep.hpp"

namespace clothbench {

namespace {

class VelocityAverage final : public VelocitySweep<VelocityAverage> {
 public:
  using VelocitySweep::VelocitySweep;
  std::pair<Real, Real> split(int a, int b, const Vec3&, Real va, Real vb, Real target) const {
    return stretch_rules::average(va, vb, mass(a), mass(b), target);  // walking Eq. 5
  }
};

}  // namespace

std::unique_ptr<Limiter> make_velocity_limit(const LimiterParams& params) {
  return std::make_unique<VelocityAverage>(params);
}

}  // namespace clothbench
