#pragma once
/// `sphere`: an analytic sphere, exact and O(1) per point, for small scenes (demo, tablecloth
/// on a moving sphere). Its radius is fixed; a body frame given to it (a sphere body's mesh) moves
/// it: centre = the mean of the frame's vertices, velocity = the mean of their velocities.
#include "clothbench/sim/collider.hpp"

namespace clothbench {

class SphereCollider final : public Collider {
 public:
  /// Sphere of `radius` [m] at `center` [m] moving with `velocity` [m/s].
  SphereCollider(const Vec3& center, Real radius, ColliderOptions options = {});
  std::string_view name() const override { return "sphere"; }
  /// The sphere follows the frame (see above); a frame without vertices leaves it where it is.
  void set_body(const BodyFrame& body) override { update_body(body); }
  void update_body(const BodyFrame& body) override;
  /// Moves the sphere directly.
  void set_sphere(const Vec3& center, const Vec3& velocity);
  void query(PointsView points, ContactsOut out) override;
  CollideStats stats() const override { return stats_; }

 private:
  Vec3 center_;
  Vec3 velocity_ = Vec3::Zero();
  Real radius_;
  ColliderOptions options_;
  CollideStats stats_;
};

}  // namespace clothbench
