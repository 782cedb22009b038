// The body between animation frames: contacts moved back in time along the body's normal velocity.
#include "clothbench/bench/body_between_frames.hpp"

namespace clothbench {

void BodyBetweenFrames::query(PointsView points, ContactsOut out) {
  inner_.query(points, out);
  if (!(tau_ > 0) && skin_ == 0) return;
  for (std::size_t i = 0; i < out.count; ++i) {
    Contact& c = out[i];
    if (!c.hit) continue;
    c.depth += c.normal.dot(c.body_velocity) * tau_ - skin_;  // d(t - tau) = d(t) + (n . v_body) tau, less the skin (Durupinar Eq. 4's threshold)
    c.hit = c.depth < tol_;
  }
}

}  // namespace clothbench
