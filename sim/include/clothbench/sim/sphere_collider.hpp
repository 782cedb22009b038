#pragma once
/// `sphere`: an analytic sphere, exact and O(1) per point, for small scenes (demo, tablecloth
/// on a moving sphere). It ignores body meshes; its shape is set with set_sphere().
#include "clothbench/sim/collider.hpp"

namespace clothbench {

class SphereCollider final : public Collider {
 public:
  /// Sphere of `radius` [m] at `center` [m] moving with `velocity` [m/s].
  SphereCollider(const Vec3& center, Real radius, ColliderOptions options = {});
  std::string_view name() const override { return "sphere"; }
  /// Meshes are ignored: the sphere is analytic.
  void set_body(const BodyFrame&) override {}
  void update_body(const BodyFrame&) override {}
  /// Moves the sphere (a moving-sphere scene calls this once per frame).
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
