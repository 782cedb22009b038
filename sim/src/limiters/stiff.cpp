// `stiff` (dressing 4.1): every spring stiffer by `stiff_factor`, which Eq. 4 pays for with a smaller time step.
#include "limiters.hpp"

namespace clothbench {

namespace {

class StiffLimit final : public Limiter {
 public:
  explicit StiffLimit(Real factor) : factor_(factor) {}
  std::unique_ptr<Limiter> clone() const override { return std::make_unique<StiffLimit>(*this); }
  Real stiffness_factor() const override { return factor_; }

 private:
  Real factor_;
};

}  // namespace

std::unique_ptr<Limiter> make_stiff_limit(const LimiterParams& params) {
  return std::make_unique<StiffLimit>(params.stiff_factor);
}

}  // namespace clothbench
