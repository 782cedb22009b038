#pragma once
// The integrators behind make_integrator (sim/src only).
#include <memory>

#include "clothbench/sim/integrator.hpp"

namespace clothbench {

std::unique_ptr<Integrator> make_explicit_euler(const IntegratorParams& params);
std::unique_ptr<Integrator> make_implicit_euler(const IntegratorParams& params);
std::unique_ptr<Integrator> make_rk45(const IntegratorParams& params);
std::unique_ptr<Integrator> make_projective(const IntegratorParams& params);

}  // namespace clothbench
