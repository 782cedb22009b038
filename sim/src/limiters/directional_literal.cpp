// `directional-literal` (walking Eq. 6 and the two rules after it as stated: directional.hpp).
#include "directional.hpp"

namespace clothbench {

std::unique_ptr<Limiter> make_directional_literal_limit(const LimiterParams& params) {
  return std::make_unique<Directional<true>>(params);
}

}  // namespace clothbench
