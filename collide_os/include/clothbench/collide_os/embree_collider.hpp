#pragma once
/// `embree`: object-space collider on an Embree BVH with rtcPointQuery closest points. It shares
/// one scene wrapper over a shared float vertex buffer with EmbreeDistance (embree_distance.hpp),
/// the exact signed distance of the accuracy oracle: a static body is built at quality HIGH; once it moves, a dynamic scene
/// (build quality LOW, geometry REFIT) is refitted per frame. Answers equal `brute`'s (same closest-point, sign and interpolation code).
#include <memory>

#include "clothbench/sim/collider.hpp"

namespace clothbench {

/// The Embree collider. Non-copyable; Embree handles stay inside the .cpp files (pimpl).
class EmbreeCollider final : public Collider {
 public:
  /// Uses options.tol [m], options.search_radius [m], options.coherent and options.threads (Embree build threads
  /// and query worker threads; recorded in stats().threads).
  explicit EmbreeCollider(const ColliderOptions& options);
  ~EmbreeCollider() override;

  std::string_view name() const override { return "embree"; }
  /// Builds the BVH, HIGH quality for a static body, refittable for a moving one (timed in
  /// stats().setup_ms). Throws std::invalid_argument for an empty body,
  /// non-finite vertices or an out-of-range index; std::runtime_error for an Embree error.
  void set_body(const BodyFrame& body) override;
  /// Refits the BVH to new positions (same topology; a static build is rebuilt refittable the
  /// first time); timed in stats().update_ms.
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

/// Factory used by the registry (name "embree").
std::unique_ptr<Collider> make_embree_collider(const ColliderOptions& options);

}  // namespace clothbench
