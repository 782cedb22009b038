#pragma once
/// `fcl`: object-space collider on an FCL OBBRSS bounding-volume tree (double precision).
/// Per query point: the nearest body triangle within ColliderOptions::search_radius from FCL's
/// sphere-to-mesh distance, then the exact closest point, pseudo-normal sign and barycentric
/// normal/velocity from mesh_query.hpp, so answers equal `brute`'s. Moving bodies are refitted
/// (beginUpdateModel / updateVertex / endUpdateModel, top-down refit), never rebuilt.
#include <memory>

#include "clothbench/sim/collider.hpp"

namespace clothbench {

/// The FCL collider. Non-copyable; FCL types stay inside fcl_collider.cpp (pimpl).
class FclCollider final : public Collider {
 public:
  /// Uses options.tol [m] and options.search_radius [m]; queries run on one thread.
  explicit FclCollider(const ColliderOptions& options);
  ~FclCollider() override;

  std::string_view name() const override { return "fcl"; }
  /// Builds the OBBRSS tree (conversion to double included in stats().setup_ms). Throws
  /// std::invalid_argument for an empty body, non-finite vertices or an out-of-range index.
  void set_body(const BodyFrame& body) override;
  /// Refits the tree to new positions (same topology); timed in stats().update_ms. Throws
  /// std::invalid_argument when set_body was not called or the topology differs.
  void update_body(const BodyFrame& body) override;
  /// One Contact per point: hit when inside or closer than tol; a point outside and farther than
  /// search_radius answers hit = false, depth = search_radius (a lower bound). Points inside
  /// deeper than search_radius are found by an unbounded search. NaN points: hit = false,
  /// counted in stats().degenerate.
  void query(PointsView points, ContactsOut out) override;
  CollideStats stats() const override;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// Factory used by the registry (name "fcl").
std::unique_ptr<Collider> make_fcl_collider(const ColliderOptions& options);

}  // namespace clothbench
