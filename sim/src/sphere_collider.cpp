#include "clothbench/sim/sphere_collider.hpp"

#include <stdexcept>

#include "clothbench/sim/timer.hpp"

namespace clothbench {

SphereCollider::SphereCollider(const Vec3& center, Real radius, ColliderOptions options)
    : center_(center), radius_(radius), options_(options) {
  if (!(radius > 0) || !center.allFinite())
    throw std::invalid_argument("sphere collider: radius must be > 0 and the centre finite");
}

void SphereCollider::set_sphere(const Vec3& center, const Vec3& velocity) {
  center_ = center;
  velocity_ = velocity;
  ++stats_.updates;
}

void SphereCollider::update_body(const BodyFrame& body) {
  if (body.positions.cols() == 0) return;
  const Vec3 velocity = body.velocities.cols() == body.positions.cols() ? Vec3(body.velocities.rowwise().mean())
                                                                          : Vec3::Zero();
  set_sphere(body.positions.rowwise().mean(), velocity);
}

void SphereCollider::query(PointsView points, ContactsOut out) {
  Stopwatch sw;
  for (std::size_t i = 0; i < points.count; ++i) {
    const Vec3 d = points[i] - center_;
    Contact c;
    const Real len = d.norm();
    if (!std::isfinite(len)) {
      ++stats_.degenerate;
      out[i] = c;
      continue;
    }
    c.depth = len - radius_;
    c.hit = c.depth < options_.tol;
    if (c.hit) {
      c.normal = len > 0 ? Vec3(d / len) : Vec3::UnitY();
      c.body_velocity = velocity_;
      ++stats_.hits;
    }
    out[i] = c;
  }
  stats_.points += static_cast<std::int64_t>(points.count);
  ++stats_.queries;
  stats_.query_ms += sw.ms();
}

}  // namespace clothbench
