// `none`: no strain limit (the cloth stretches as its springs let it).
#include "limiters.hpp"

namespace clothbench {

namespace {

class NoLimit final : public Limiter {
 public:
  std::unique_ptr<Limiter> clone() const override { return std::make_unique<NoLimit>(*this); }
};

}  // namespace

std::unique_ptr<Limiter> make_no_limit(const LimiterParams&) { return std::make_unique<NoLimit>(); }

}  // namespace clothbench
