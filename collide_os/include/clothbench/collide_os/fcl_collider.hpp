#pragma once
/// `fcl`: object-space collider on an FCL kIOS bounding-volume tree (double precision; kIOS
/// answered the dressing shirt's queries faster than OBBRSS, see collide_os/README.md).
/// Per query point: the nearest body triangle within a bound from FCL's sphere-to-mesh distance, then the exact closest point, pseudo-normal sign and barycentric
/// normal/velocity from mesh_query.hpp, so answers equal `brute`'s. Moving bodies are refitted
/// (beginUpdateModel / updateVertex / endUpdateModel, top-down refit), never rebuilt.
#include <memory>

#include "clothbench/sim/collider.hpp"

namespace clothbench {

/// The FCL collider. Non-copyable; FCL types stay inside fcl_collider.cpp (pimpl).
class FclCollider final : public Collider {
 public:
  /// Uses options.tol [m], options.search_radius [m] and options.coherent; queries run on one thread.
  explicit FclCollider(const ColliderOptions& options);
  ~FclCollider() override;

  std::string_view name() const override { return "fcl"; }
  /// Builds the kIOS tree (conversion to double included in stats().setup_ms). Throws
  /// std::invalid_argument for an empty body, non-finite vertices or an out-of-range index.
  void set_body(const BodyFrame& body) override;
  /// Refits the tree to new positions (same topology); timed in stats().update_ms. Throws
  /// std::invalid_argument when set_body was not called or the topology differs.
  void update_body(const BodyFrame& body) override;
  /// One Contact per point: hit when inside or closer than tol, with the exact answer; a miss's
  /// depth is a lower bound >= tol. With options.coherent (default) each point of an array queried
  /// before keeps a bound: one that cannot have come within tol since (its own motion plus the
  /// body's) is a miss without a search, the others search within the distance to their last
  /// closest triangle. Without it, every point searches within search_radius, and points inside
  /// the body's box with nothing there get an unbounded search. NaN points: hit = false, counted
  /// in stats().degenerate; searches run are counted in stats().searches.
  void query(PointsView points, ContactsOut out) override;
  CollideStats stats() const override;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// Factory used by the registry (name "fcl").
std::unique_ptr<Collider> make_fcl_collider(const ColliderOptions& options);

}  // namespace clothbench
