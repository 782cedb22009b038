// `position` (Provot 1995; dressing 4.2, walking 3.1): after the positions move, the ends of springs stretched past
// (1 + threshold) l0 are moved back to that length, `passes` times over all springs.
#include "limiters.hpp"

namespace clothbench {

namespace {

class PositionLimit final : public Limiter {
 public:
  explicit PositionLimit(const LimiterParams& params) : params_(params) {}
  std::unique_ptr<Limiter> clone() const override { return std::make_unique<PositionLimit>(*this); }

  void limit_positions(LimitState& s) override {
    const Real max_len_factor = 1 + params_.threshold;
    const ClothMesh& mesh = s.mesh;
    for (int pass = 0; pass < params_.passes; ++pass, ++passes_)
      for (Eigen::Index k = 0; k < mesh.springs.cols(); ++k) {
        const int a = mesh.springs(0, k), b = mesh.springs(1, k);
        const Vec3 d = s.x.col(b) - s.x.col(a);
        const Real len = d.norm(), max_len = max_len_factor * mesh.rest_length[k];
        const Real wa = s.inv_m[a] > 0 ? Real(1) : Real(0), wb = s.inv_m[b] > 0 ? Real(1) : Real(0);
        if (!(len > max_len) || wa + wb == 0) continue;
        // the velocities follow the moved positions, so Eq. 3 does not push them out again
        const Vec3 corr = (len - max_len) / len * d / (wa + wb);
        s.x.col(a) += wa * corr;
        s.x.col(b) -= wb * corr;
        s.v.col(a) += (wa / s.dt) * corr;
        s.v.col(b) -= (wb / s.dt) * corr;
      }
  }

 private:
  LimiterParams params_;
};

}  // namespace

std::unique_ptr<Limiter> make_position_limit(const LimiterParams& params) {
  return std::make_unique<PositionLimit>(params);
}

}  // namespace clothbench
