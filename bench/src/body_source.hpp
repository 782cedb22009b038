#pragma once
// The body of a run and its motion (bench/src only: the runner's phases share it).
#include <optional>

#include "clothbench/bench/scene.hpp"
#include "clothbench/io/body_loader.hpp"

namespace clothbench::runner_detail {

// the body and its motion: a (possibly animated) mesh, or a sphere moving at constant velocity
class BodySource {
 public:
  // throws InputError for a body the scene cannot run (a proxy of a sphere, a window outside the clip)
  explicit BodySource(const Scene& scene);

  bool moves() const { return t1_ > t0_; }
  double dress_time() const { return dress_; }
  double start() const { return t0_; }
  double end() const { return t1_; }
  bool is_sphere() const { return !model_; }
  Vec3 sphere_center(double t) const { return spec_.center + spec_.velocity * Real(t); }

  // the frame the colliders see at time t (animation time, or seconds of sphere motion): the collision proxy's when
  // there is one (body.collision_triangles)
  void frame_into(BodyFrame& out, double t) const { frame_into(proxy_ ? proxy_ : model_, out, t); }
  // the exact body at `used`'s time, for the oracle and the pictures: `used` itself without a proxy, else `scratch`
  const BodyFrame& exact(const BodyFrame& used, BodyFrame& scratch) const {
    if (!proxy_) return used;
    frame_into(model_, scratch, used.time_s);
    return scratch;
  }
  bool has_proxy() const { return proxy_.has_value(); }

 private:
  void frame_into(const std::optional<BodyModel>& model, BodyFrame& out, double t) const;

  BodySpec spec_;
  std::optional<BodyModel> model_, proxy_;
  BodyFrame sphere_;
  int anim_ = -1;
  double dress_ = 0, t0_ = 0, t1_ = 0;
};

}  // namespace clothbench::runner_detail
