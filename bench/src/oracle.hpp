#pragma once
/// The accuracy oracle of DESIGN.md: exact signed distance of query points to the body, from
/// exact geometry and independent of the collider under test (closest point + angle-weighted
/// pseudo-normal sign; the bodies are closed meshes). Uses Embree's point query when the build
/// has CLOTHBENCH_WITH_EMBREE; otherwise (documented fallback) every triangle per point
/// (closest_point_brute), exact but O(points x triangles).
#include <cstddef>
#include <memory>
#include <vector>

#include "clothbench/sim/body_frame.hpp"
#include "clothbench/sim/collider.hpp"

namespace clothbench {

/// Penetration of a point set into the body. Penetration = max(0, -signed distance).
struct Accuracy {
  double inside_pct = 0;     ///< share of points inside the body [%]
  double depth_max_mm = 0;   ///< deepest penetration, positive [mm]; 0 if none inside
  double depth_mean_mm = 0;  ///< mean penetration over the inside points [mm]; 0 if none
  double depth_p95_mm = 0;   ///< 95th percentile of penetration over all points [mm]; 0 when < 5 % inside
  std::size_t points = 0;    ///< finite points measured (non-finite points are skipped)
  std::size_t inside = 0;    ///< points inside (signed distance < 0)
};

/// Exact signed distance to one body frame. Movable, not copyable.
class Oracle {
 public:
  /// Builds the distance structure; throws std::invalid_argument for a malformed body.
  explicit Oracle(const BodyFrame& body);
  ~Oracle();
  Oracle(Oracle&&) noexcept;
  Oracle& operator=(Oracle&&) noexcept;
  Oracle(const Oracle&) = delete;
  Oracle& operator=(const Oracle&) = delete;

  /// Moves to a new frame of the same body (same topology); throws std::invalid_argument otherwise.
  void update_body(const BodyFrame& body);
  /// Penetration statistics of the points [m] against the current frame.
  Accuracy measure(PointsView points) const;
  /// out[i] = signed distance of points[i] [m], < 0 inside; NaN for a non-finite point.
  /// `out` is resized to points.count.
  void signed_distance(PointsView points, std::vector<Real>& out) const;
  /// True when the Embree point query answers; false for the brute-force fallback.
  static bool uses_embree();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace clothbench
