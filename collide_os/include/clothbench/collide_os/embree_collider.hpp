#pragma once
/// `embree`: object-space collider on an Embree BVH with rtcPointQuery closest points, and the
/// exact signed distance the accuracy oracle uses. Both share one scene wrapper: a dynamic scene
/// (build quality LOW, geometry REFIT) over a shared float vertex buffer, so moving bodies are
/// refitted. Answers equal `brute`'s (same closest-point, sign and interpolation code).
#include <cstdint>
#include <memory>

#include "clothbench/sim/collider.hpp"

namespace clothbench {

/// The Embree collider. Non-copyable; Embree handles stay inside the .cpp files (pimpl).
class EmbreeCollider final : public Collider {
 public:
  /// Uses options.tol [m], options.search_radius [m] and options.threads (Embree build threads
  /// and query worker threads; recorded in stats().threads).
  explicit EmbreeCollider(const ColliderOptions& options);
  ~EmbreeCollider() override;

  std::string_view name() const override { return "embree"; }
  /// Builds the BVH (timed in stats().setup_ms). Throws std::invalid_argument for an empty body,
  /// non-finite vertices or an out-of-range index; std::runtime_error for an Embree error.
  void set_body(const BodyFrame& body) override;
  /// Refits the BVH to new positions (same topology); timed in stats().update_ms.
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
