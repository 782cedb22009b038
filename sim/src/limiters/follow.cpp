// `follow`: follow the leader (Mueller, Kim, Chentanez 2012, "Fast simulation of inextensible hair and fur") in the
// velocity sweep. Of an over-stretched spring the end fewer hops from a held point (attached or in contact) leads:
// it keeps its velocity and the other end takes all of the correction, so one sweep from the held points out holds
// every spring of a tree exactly (Eq. 5 averages the correction and hands half of it back at each link). Ends as
// far from the held points as each other average (walking Eq. 5), and so does cloth out of reach of any.
#include "limiters.hpp"
#include "stretch_rules.hpp"
#include "velocity_sweep.hpp"

namespace clothbench {

namespace {

class FollowTheLeader final : public VelocitySweep<FollowTheLeader> {
 public:
  using VelocitySweep::VelocitySweep;
  std::pair<Real, Real> split(int a, int b, const Vec3&, Real va, Real vb, Real target) const {
    const int la = level(a), lb = level(b);
    if (la >= 0 && (lb < 0 || la < lb)) return {va, va + target};  // a leads
    if (lb >= 0 && (la < 0 || lb < la)) return {vb - target, vb};  // b leads
    return stretch_rules::average(va, vb, mass(a), mass(b), target);  // walking Eq. 5
  }
};

}  // namespace

std::unique_ptr<Limiter> make_follow_limit(const LimiterParams& params) {
  return std::make_unique<FollowTheLeader>(params);
}

}  // namespace clothbench
