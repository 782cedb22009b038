#pragma once
/// The body between animation frames: a collider holds the body posed at a frame's end, yet the cloth
/// steps through the whole frame. BodyBetweenFrames wraps any collider and answers a step taken `tau` seconds
/// before that pose with each contact's depth as it was then, to first order in the body's motion along its
/// normal: d(t - tau) = d(t) + (n . v_body) tau. A surface moving outward has not yet reached the cloth it holds
/// at the frame's end, so it sweeps the cloth out over the frame's steps instead of swallowing it at once; the
/// last step of a frame (tau = 0) sees the posed body exactly. Only contacts the inner collider reports as hit
/// carry a normal and a body velocity; a point the body reaches only before the pose (a retreating surface) is
/// left as the inner collider answered it.
///
/// The body is also answered `skin` thicker (in every phase: the runner wraps the dressing collider too): every
/// hit contact's depth is lowered by `skin`, so the response (push_out included) holds the cloth that far ahead
/// of the surface it moves with: push_out then acts as
/// Durupinar's Eq. 4 (a point closer to the surface than a threshold is moved out along the normal) besides her
/// Eq. 3 (a point beneath it is brought to it). Cloth resting on the surface
/// with nothing between would be caught a fraction of a millimetre inside by the errors of the first-order
/// motion above, and the straight spring between two resting vertices cuts the curved surface it lies on by
/// L^2 / (8 R); the skin covers both (walking-t2 measures it with and without).
#include "clothbench/sim/collider.hpp"

namespace clothbench {

class BodyBetweenFrames final : public Collider {
 public:
  /// `tol`: the hit distance of the inner collider's options [m] (ColliderOptions::tol); `skin` in [0, tol) [m].
  BodyBetweenFrames(Collider& inner, Real tol, Real skin = 0) : inner_(inner), tol_(tol), skin_(skin) {}
  std::string_view name() const override { return inner_.name(); }
  std::string device() const override { return inner_.device(); }
  void set_body(const BodyFrame& body) override { inner_.set_body(body); }
  void update_body(const BodyFrame& body) override { inner_.update_body(body); }
  bool prepare_body(const BodyFrame& body) override { return inner_.prepare_body(body); }
  void set_query_region(const Box3& region) override { inner_.set_query_region(region); }
  /// The next queries are answered `tau` >= 0 seconds before the pose of the last set_body/update_body.
  void set_time_before_pose(Real tau) { tau_ = tau; }
  Collider& inner() const { return inner_; }
  void query(PointsView points, ContactsOut out) override;
  CollideStats stats() const override { return inner_.stats(); }

 private:
  Collider& inner_;
  Real tol_, skin_;
  Real tau_ = 0;
};

}  // namespace clothbench
