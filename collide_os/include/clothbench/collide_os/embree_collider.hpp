#pragma once
/// `embree`: object-space collider on an Embree BVH with rtcPointQuery closest points, and the
/// exact signed distance the accuracy oracle uses. Both share one scene wrapper over a shared
/// float vertex buffer: a static body is built at quality HIGH; once it moves, a dynamic scene
/// (build quality LOW, geometry REFIT) is refitted per frame. Answers equal `brute`'s (same closest-point, sign and interpolation code).
#include <cstdint>
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

/// Exact signed distance to a closed body, for the accuracy oracle (DESIGN.md): closest point
/// over the whole body (unbounded radius), sign from angle-weighted pseudo-normals; and exact
/// segment-surface crossings (cloth springs through body triangles).
/// One thread. Non-copyable, movable.
class EmbreeDistance {
 public:
  EmbreeDistance();
  ~EmbreeDistance();
  EmbreeDistance(EmbreeDistance&&) noexcept;
  EmbreeDistance& operator=(EmbreeDistance&&) noexcept;
  EmbreeDistance(const EmbreeDistance&) = delete;
  EmbreeDistance& operator=(const EmbreeDistance&) = delete;

  /// Builds the BVH; throws std::invalid_argument for a malformed body (see validate_body).
  void set_body(const BodyFrame& body);
  /// Refits to new positions (same topology); throws std::invalid_argument otherwise.
  void update_body(const BodyFrame& body);
  /// depth_out[i] = signed distance of points[i] to the surface [m], < 0 inside; NaN for a
  /// non-finite point or before set_body. depth_out holds points.count values.
  void signed_distance(PointsView points, Real* depth_out) const;
  /// Segments against the body surface, one Embree occlusion ray each: crosses_out[k] = 1 when
  /// the closed segment from vertices[segments(0, k)] to vertices[segments(1, k)] [m] meets a
  /// body triangle, else 0 (also for a zero-length or non-finite segment, or before set_body).
  /// Indices must lie in [0, vertices.count); crosses_out holds segments.cols() values.
  void segment_crossings(PointsView vertices, const Pairs& segments, std::uint8_t* crosses_out) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace clothbench
