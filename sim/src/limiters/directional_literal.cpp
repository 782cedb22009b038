// `directional-literal`: walking Eq. 6 and the two rules after it as walking section 3.2 states them. After each
// iteration every spring longer than (1 + threshold) l0 has its ends' velocity components along the current
// p12 = p2 - p1 modified so that it stretches no further: about perpendicular to v_dir = v_grav + v_object
// (|cos alpha| < 0.3) both become their average (Eq. 5), otherwise the rear point's becomes the front one's
// (cos alpha > 0: the rear point is p1). Every spring, in index order, `passes` times, once a step. Ours
// (`directional`, directional.cpp) departs in each of: the end-of-step line, a relative velocity that ends the step
// at the threshold, mass-weighted means, an energy guard, held rear points, the sweep order and the second call
// after the collision response.
#include <cmath>

#include "../merged_points.hpp"
#include "limiters.hpp"
#include "stretch_rules.hpp"

namespace clothbench {

namespace {

class DirectionalLiteral final : public Limiter {
 public:
  explicit DirectionalLiteral(const LimiterParams& params) : params_(params) {}
  std::unique_ptr<Limiter> clone() const override { return std::make_unique<DirectionalLiteral>(*this); }

  void limit_velocities(LimitState& s, bool after_response) override {
    if (after_response) return;  // the paper checks the springs once, after each iteration
    const ClothMesh& mesh = s.mesh;
    for (int pass = 0; pass < params_.passes; ++pass, ++passes_) {
      for (Eigen::Index k = 0; k < mesh.springs.cols(); ++k) {
        const int a = mesh.springs(0, k), b = mesh.springs(1, k);
        const Vec3 p12 = s.x.col(b) - s.x.col(a);
        const Real len = p12.norm();
        if (!(len > (1 + params_.threshold) * mesh.rest_length[k])) continue;
        const Vec3 u = p12 / len;
        const Real cos_alpha = stretch_rules::directional_cos(u, s.gravity, s.dt, s.contacts, a, b);  // walking Eq. 6
        const Real va = u.dot(s.v.col(a)), vb = u.dot(s.v.col(b));
        // equal weights: Eq. 5's plain average; no target: the spring keeps no stretching velocity
        const auto [na, nb] = stretch_rules::directional(va, vb, cos_alpha, 1, 1, 0, true);
        if (s.inv_m[a] > 0) s.v.col(a) += (na - va) * u;  // an attached point moves with the body
        if (s.inv_m[b] > 0) s.v.col(b) += (nb - vb) * u;
      }
      move_as_one(s.merged, s.m, s.inv_m, s.v, nullptr, [](int, Real) {});  // a sewn point is one point
    }
  }

 private:
  LimiterParams params_;
};

}  // namespace

std::unique_ptr<Limiter> make_directional_literal_limit(const LimiterParams& params) {
  return std::make_unique<DirectionalLiteral>(params);
}

}  // namespace clothbench
