// `velocity-zero` (dressing 4.3): the stretching components of an over-stretched spring's end velocities are set
// to zero, so it stretches no further.
#include "limiters.hpp"
#include "velocity_sweep.hpp"

namespace clothbench {

namespace {

class VelocityZero final : public VelocitySweep<VelocityZero> {
 public:
  using VelocitySweep::VelocitySweep;
  // the spring keeps no relative velocity along itself
  Real target(Real) const { return 0; }
  std::pair<Real, Real> split(int, int, const Vec3&, Real, Real, Real) const { return {0, 0}; }  // dressing 4.3
};

}  // namespace

std::unique_ptr<Limiter> make_velocity_zero_limit(const LimiterParams& params) {
  return std::make_unique<VelocityZero>(params);
}

}  // namespace clothbench
