#pragma once
/// The accuracy oracle of DESIGN.md: exact signed distance of query points to the body, from
/// exact geometry and independent of the collider under test (closest point + angle-weighted
/// pseudo-normal sign; the bodies are closed meshes). Uses Embree's point query when the build
/// has CLOTHBENCH_WITH_EMBREE; otherwise (documented fallback) every triangle per point
/// (closest_point_brute), exact but O(points x triangles).
/// Crossings: cloth segments (structural springs) that pass through a body triangle, the "holes"
/// of dressing section 7, which a body part poking between cloth vertices makes without putting
/// any vertex inside; one Embree occlusion ray per segment, or every triangle per segment without
/// Embree. Penetrating faces: cloth quads whose midpoint is inside.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "clothbench/sim/body_frame.hpp"
#include "clothbench/sim/cloth.hpp"
#include "clothbench/sim/collider.hpp"

namespace clothbench {

/// Accuracy against the body: penetration of a point set (penetration = max(0, -signed distance)),
/// crossings of cloth segments and penetrating faces, and what measuring them cost.
struct Accuracy {
  double inside_pct = 0;         ///< share of points inside the body [%]
  double depth_max_mm = 0;       ///< deepest penetration, positive [mm]; 0 if none inside
  long deepest = -1;             ///< index of the deepest point among those measured; -1 if none inside
  double depth_mean_mm = 0;      ///< mean penetration over the inside points [mm]; 0 if none
  double depth_p95_mm = 0;       ///< 95th percentile of penetration over all points [mm]; 0 when < 5 % inside
  std::size_t points = 0;        ///< finite points measured (non-finite points are skipped)
  std::size_t inside = 0;        ///< points inside (signed distance < 0)
  std::size_t segments = 0;      ///< finite segments tested for crossings (structural springs)
  std::size_t crossings = 0;     ///< segments that meet a body triangle; a segment wholly inside meets none
  double crossings_pct = 0;      ///< crossings / segments [%]; 0 when none were tested
  std::size_t faces = 0;         ///< finite cloth quads tested by measure_faces
  std::size_t faces_inside = 0;  ///< quads whose midpoint (mean of the 4 corners) is inside the body
  double faces_inside_pct = 0;   ///< faces_inside / faces [%]; 0 when none were tested
  double depth_ms = 0;           ///< cost of the signed-distance query of measure() [ms]
  double crossings_ms = 0;       ///< cost of the segment query of measure_crossings() [ms]
  std::size_t cloth_crossings = 0;  ///< structural springs through a triangle of the cloth itself (cloth_crossings.hpp)
  double cloth_crossings_pct = 0;   ///< cloth_crossings / segments [%]
};

/// The structural springs of a cloth (2 x ns_structural vertex indices): the segments whose
/// crossings the oracle counts (shear and flexion springs span more than one grid cell).
Pairs structural_springs(const ClothMesh& mesh);

/// Whether the closed segment a -> b [m] meets the closed triangle (t0, t1, t2), either face, in
/// double precision (Moller-Trumbore); false for a zero-length segment, a segment in the triangle's
/// plane or a degenerate triangle.
bool segment_crosses_triangle(const Vec3& a, const Vec3& b, const Vec3& t0, const Vec3& t1, const Vec3& t2);

/// Points to measure colliders with: `count` points on random body triangles (uniform over
/// triangles, not area), each moved along its face normal by a uniform amount in [lo, hi] [m]
/// (< 0 inside); fixed `seed`.
Points3 points_off_surface(const BodyFrame& body, int count, Real lo, Real hi, unsigned seed);

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
  /// The same statistics from the points' signed distances [m] (signed_distance's output; NaN: not counted).
  static Accuracy penetration(const std::vector<Real>& signed_distances);
  /// out[i] = signed distance of points[i] [m], < 0 inside; NaN for a non-finite point.
  /// `out` is resized to points.count.
  void signed_distance(PointsView points, std::vector<Real>& out) const;
  /// out[k] = 1 when segment k, from vertices[segments(0, k)] to vertices[segments(1, k)] [m],
  /// meets a body triangle, else 0 (also for a non-finite or zero-length segment); `out` is
  /// resized to segments.cols(). Throws std::invalid_argument for an index outside the vertices.
  void segment_crossings(PointsView vertices, const Pairs& segments, std::vector<std::uint8_t>& out) const;
  /// Fills a.segments, a.crossings, a.crossings_pct and a.crossings_ms for the segments (see
  /// segment_crossings; non-finite segments are not counted as tested). Throws as segment_crossings.
  void measure_crossings(PointsView vertices, const Pairs& segments, Accuracy& a) const;
  /// Fills a.faces, a.faces_inside and a.faces_inside_pct: penetrating faces, quads (4 x nq indices
  /// into `vertices` [m]) whose midpoint is inside, measured whether or not the run queried
  /// midpoints (dressing section 6). Quads with a non-finite corner are not tested. Throws
  /// std::invalid_argument for an index outside the vertices.
  void measure_faces(PointsView vertices, const Quads& quads, Accuracy& a) const;
  /// True when the Embree point query answers; false for the brute-force fallback.
  static bool uses_embree();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace clothbench
