#include "clothbench/sim/brute_collider.hpp"

#include "clothbench/sim/timer.hpp"

namespace clothbench {

BruteForceCollider::BruteForceCollider(ColliderOptions options) : options_(options) {}

void BruteForceCollider::set_body(const BodyFrame& body) {
  Stopwatch sw;
  validate_body(body, "brute collider");
  body_ = body;
  pseudo_ = PseudoNormals(body_);
  stats_.setup_ms += sw.ms();
}

void BruteForceCollider::update_body(const BodyFrame& body) {
  Stopwatch sw;
  body_ = body;
  pseudo_ = PseudoNormals(body_);
  stats_.update_ms += sw.ms();
  ++stats_.updates;
}

void BruteForceCollider::query(PointsView points, ContactsOut out) {
  Stopwatch sw;
  for (std::size_t i = 0; i < points.count; ++i) {
    const Vec3 p = points[i];
    if (!p.allFinite()) {
      out[i] = Contact{};
      ++stats_.degenerate;
      continue;
    }
    out[i] = contact_from_closest(body_, pseudo_, p, closest_point_brute(body_, p), options_.tol, options_.face_normals);
    stats_.hits += out[i].hit;
  }
  stats_.points += static_cast<std::int64_t>(points.count);
  ++stats_.queries;
  stats_.query_ms += sw.ms();
}

}  // namespace clothbench
