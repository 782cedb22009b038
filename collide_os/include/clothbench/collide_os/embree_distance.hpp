#pragma once
/// EmbreeDistance: the accuracy oracle's exact signed distance and segment crossings on an Embree BVH
/// (src/embree_distance.cpp), sharing the scene wrapper of the `embree` collider (embree_collider.hpp).
#include <cstdint>
#include <memory>

#include "clothbench/sim/body_frame.hpp"
#include "clothbench/sim/collider.hpp"

namespace clothbench {

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
