#pragma once
/// The collider contract of DESIGN.md: every detection method answers the same batched question.
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>

#include "clothbench/sim/body_frame.hpp"
#include "clothbench/sim/types.hpp"

namespace clothbench {

/// Answer for one query point. Sign convention (as MuJoCo's mjContact): depth < 0 inside.
/// When hit is false, depth is only a lower bound (>= tol, possibly +inf) and normal and
/// body_velocity are zero; consumers must not read them.
struct Contact {
  bool hit = false;          ///< inside the body or closer than tol to its surface
  float depth = 0;           ///< signed distance to the body surface [m]; < 0 inside
  Vec3 normal = Vec3::Zero();         ///< unit outward body normal at the contact
  Vec3 body_velocity = Vec3::Zero();  ///< body surface velocity there [m/s]; zero if static
};

/// Removes from velocity v its motion into the body at contact c, relative to the body's surface: the normal
/// component heading in (sliding along the body and leaving it stay). Returns the normal speed removed [m/s], 0 when
/// v was not heading in.
inline Real stop_into_body(Eigen::Ref<Vec3> v, const Contact& c) {
  const Real vn = (v - c.body_velocity).dot(c.normal);
  if (!(vn < 0)) return 0;
  v -= vn * c.normal;
  return -vn;
}

/// Read-only view of packed query points (3 x count floats, column-major xyz) [m].
struct PointsView {
  const Real* xyz = nullptr;
  std::size_t count = 0;
  PointsView() = default;
  PointsView(const Points3& p) : xyz(p.data()), count(static_cast<std::size_t>(p.cols())) {}  // NOLINT
  PointsView(const Real* data, std::size_t n) : xyz(data), count(n) {}
  Eigen::Map<const Vec3> operator[](std::size_t i) const { return Eigen::Map<const Vec3>(xyz + 3 * i); }
};

/// Writable view of `count` contacts, one per query point.
struct ContactsOut {
  Contact* data = nullptr;
  std::size_t count = 0;
  Contact& operator[](std::size_t i) const { return data[i]; }
};

/// Cumulative counters and timings of a collider [ms]. Timings are wall clock, one thread
/// unless `threads` says otherwise.
struct CollideStats {
  double setup_ms = 0;        ///< set_body: maps rendered or BVH built (and uploads)
  double update_ms = 0;       ///< all update_body calls: re-render or refit
  double query_ms = 0;        ///< all query calls
  std::int64_t updates = 0;   ///< update_body calls
  std::int64_t queries = 0;   ///< query calls
  std::int64_t points = 0;    ///< points queried
  std::int64_t hits = 0;      ///< points answered hit
  std::int64_t degenerate = 0;///< points that could not be answered (NaN input, ...): hit=false
  std::int64_t searches = 0;  ///< object space: points that needed a closest-point search (the
                              ///< rest were answered from their bounds: box, temporal coherence)
  int threads = 1;            ///< worker threads used by the backend
};

/// Options every collider understands; backends ignore what does not apply to them.
struct ColliderOptions {
  Real tol = 0.005f;            ///< hit when closer than this to the surface [m] (dressing Eq. 5)
  Real search_radius = 0.05f;   ///< object space: closest points searched within this [m]
  int map_size = 320;           ///< image space: map resolution [pixels] (dressing 5.4)
  bool side_layer = true;       ///< image space: one extra pixel layer around the silhouette
  Real side_layer_mm = 0;       ///< image space: > 0 widens that layer to this many millimetres
                                ///< (at least one pixel), so it does not thin as the map grows
  int views = 2;                ///< image space: 2 (the papers' front/back), 4 (+ along +-X) or 6 (+ +-Y)
  int layers = 1;               ///< image space: surfaces each pair keeps along its axis, peeled from its + face
                                ///< (1: the papers' first and last surface only; up to 8)
  bool tangent_plane = true;    ///< image space: refine near points by the surface's tangent plane (ours);
                                ///< false: the papers' comparison along the view axis alone (dressing Eq. 9)
  bool overlapping_parts = true;///< image space: the body is parts that overlap and fold through each other (a skinned
                                ///< body): cloth between two parts is pinched where they meet, and a line folded through
                                ///< itself does not call a point outside; false for a sheet of cloth standing in for one
  bool fit_extent = false;      ///< image space: map square fitted to the body, not body height
  bool float_maps = true;       ///< image space: float targets (false: 8-bit colours, Eq. 6/9)
  Real max_speed = 3.0f;        ///< image space, 8-bit velocity encoding: maxv [m/s] (walking Eq. 9)
  int threads = 1;              ///< object space: worker threads (embree)
  bool coherent = true;         ///< object space: each point's bound and closest triangle carried
                                ///< between queries (false: every point searched from scratch)
  Real query_margin_mm = 100;   ///< image space, moving bodies: the runner asks for the map rows that the cloth's
                                ///< bounding box grown by this spans (set_query_region) [mm]; 0: every row
  Real voxel_size = 0.002f;     ///< vdb: voxel edge of the body's signed distance field [m]
  bool face_normals = false;    ///< fcl, embree, brute: respond along the closest triangle's face normal (the
                                ///< dressing paper's object space, section 7) instead of interpolated vertex normals
};

/// Pluggable cloth-body collision detection. Non-copyable; owns its GL/FCL/Embree handles.
class Collider {
 public:
  Collider() = default;
  Collider(const Collider&) = delete;
  Collider& operator=(const Collider&) = delete;
  virtual ~Collider() = default;

  /// Registry name: "is-gl", "is-cpu", "fcl", "embree", "brute"; "sphere" (the analytic collider of the
  /// sphere scenes, made by the runner, not the registry).
  virtual std::string_view name() const = 0;
  /// What answers the queries where that is hardware or a driver (image space: "OSMesa: Mesa llvmpipe ...",
  /// "EGL device 0 ...: NVIDIA ..."); empty for the rest.
  virtual std::string device() const { return {}; }
  /// Set-up for a body: maps rendered or BVH built. Throws std::runtime_error /
  /// std::invalid_argument with a clear message on bad input.
  virtual void set_body(const BodyFrame& body) = 0;
  /// Each animation frame: re-render maps or refit the BVH. Same topology as set_body.
  virtual void update_body(const BodyFrame& body) = 0;
  /// A hint for the next update_body calls: the queries come from within `region` (the cloth's box, grown by what
  /// it can move in a frame). A collider may skip work for the body outside it (image space draws only the map
  /// rows it spans) and then answer a point outside it as if no body were there. Default: ignored.
  virtual void set_query_region(const Box3& region) { (void)region; }
  /// Prepares the next update_body(body) ahead of it, on another thread than the queries' if the caller likes
  /// (the body's motion is prescribed, so the next frame's maps can be drawn while the cloth steps through this
  /// one): true when it did, and the update_body with that same frame that must follow then only makes it current.
  /// Only query() and stats() may run meanwhile, and nothing else on this collider. Default: false, nothing
  /// prepared (update_body does all of the work).
  virtual bool prepare_body(const BodyFrame& body) {
    (void)body;
    return false;
  }
  /// Hot path: one Contact per point. Never throws; NaN points are counted as degenerate.
  virtual void query(PointsView points, ContactsOut out) = 0;
  /// Cumulative timings and counts since construction.
  virtual CollideStats stats() const = 0;
};

}  // namespace clothbench
