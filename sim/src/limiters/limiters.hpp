#pragma once
// The members of the strain-limiter family behind make_limiter, one file each (sim/src only).
#include <memory>

#include "clothbench/sim/limiter.hpp"

namespace clothbench {

std::unique_ptr<Limiter> make_no_limit(const LimiterParams& params);
std::unique_ptr<Limiter> make_stiff_limit(const LimiterParams& params);
std::unique_ptr<Limiter> make_position_limit(const LimiterParams& params);
std::unique_ptr<Limiter> make_velocity_zero_limit(const LimiterParams& params);
std::unique_ptr<Limiter> make_velocity_limit(const LimiterParams& params);
std::unique_ptr<Limiter> make_directional_limit(const LimiterParams& params);
std::unique_ptr<Limiter> make_directional_literal_limit(const LimiterParams& params);
std::unique_ptr<Limiter> make_tether_limit(const LimiterParams& params);
std::unique_ptr<Limiter> make_follow_limit(const LimiterParams& params);
std::unique_ptr<Limiter> make_projection_limit(const LimiterParams& params);
std::unique_ptr<Limiter> make_impulses_limit(const LimiterParams& params);

}  // namespace clothbench
