// The strain-limiter family: the registry by name and the rules' public entry points.
#include "clothbench/sim/limiter.hpp"

#include <algorithm>
#include <stdexcept>

#include "limiters.hpp"
#include "stretch_rules.hpp"

namespace clothbench {

void Limiter::limit_velocities(LimitState&, bool) {}
void Limiter::limit_positions(LimitState&) {}

const std::vector<LimiterInfo>& limiter_registry() {
  static const std::vector<LimiterInfo> r{
      {"none", "no limit", false, make_no_limit},
      {"stiff", "dressing 4.1: stiffer springs", true, make_stiff_limit},
      {"position", "Provot 1995 (dressing 4.2, walking 3.1): position modification", true, make_position_limit},
      {"velocity-zero", "dressing 4.3: stretching velocities zeroed", true, make_velocity_zero_limit},
      {"velocity", "walking Eq. 5: stretching velocities averaged", true, make_velocity_limit},
      {"directional", "walking Eq. 6 with our reading of its rules", true, make_directional_limit},
      {"directional-literal", "walking Eq. 6 and its rules as stated", true, make_directional_literal_limit},
      {"tethers", "Kim, Chentanez, Mueller 2012: long-range attachments, then walking Eq. 5", false,
       make_tether_limit},
      {"follow", "Mueller, Kim, Chentanez 2012: follow the leader, swept from the held points", false,
       make_follow_limit},
      {"projection", "Goldenthal et al. 2007: fast projection of the over-stretched structural springs", false,
       make_projection_limit},
      {"impulses", "Catto 2005: walking Eq. 5 as accumulated impulses, warm-started from the last step", false,
       make_impulses_limit}};
  return r;
}

std::vector<std::string> limiter_names() {
  std::vector<std::string> names;
  for (const LimiterInfo& l : limiter_registry()) names.push_back(l.name);
  return names;
}

void check_limiter(const std::string& name) {
  std::string known;
  for (const LimiterInfo& l : limiter_registry()) {
    if (name == l.name) return;
    known += (known.empty() ? "" : ", ") + std::string(l.name);
  }
  throw std::invalid_argument("limit: unknown method '" + name + "' (" + known + ")");
}

std::unique_ptr<Limiter> make_limiter(const std::string& name, const LimiterParams& params) {
  check_limiter(name);
  const auto& r = limiter_registry();
  return std::find_if(r.begin(), r.end(), [&](const LimiterInfo& l) { return name == l.name; })->make(params);
}

std::pair<Real, Real> average_stretch(Real va, Real vb, Real wa, Real wb, Real target) {
  return stretch_rules::average(va, vb, wa, wb, target);
}

std::pair<Real, Real> directional_stretch(Real va, Real vb, Real cos_alpha, Real wa, Real wb, Real target,
                                          bool literal) {
  return stretch_rules::directional(va, vb, cos_alpha, wa, wb, target, literal);
}

}  // namespace clothbench
