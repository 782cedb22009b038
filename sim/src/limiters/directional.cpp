// `directional` (walking Eq. 6 with our reading of its rules: directional.hpp).
#include "directional.hpp"

namespace clothbench {

std::unique_ptr<Limiter> make_directional_limit(const LimiterParams& params) {
  return std::make_unique<Directional<false>>(params);
}

}  // namespace clothbench
