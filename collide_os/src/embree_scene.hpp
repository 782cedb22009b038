#pragma once
// internal: one Embree device and scene over a body, exact closest points on it
#include <embree3/rtcore.h>

#include <cstdint>
#include <string>
#include <vector>

#include "clothbench/sim/mesh_query.hpp"

namespace clothbench::detail {

/// Owns an Embree device, scene and triangle geometry (non-copyable, not movable: the device
/// error callback points at it). A static body is built at quality HIGH; a moving one is flagged
/// dynamic with build quality LOW and the geometry REFIT, so refit() updates the BVH instead of
/// rebuilding it. Flagged robust, so segment queries keep full arithmetic accuracy.
class EmbreeScene {
 public:
  /// threads: Embree build threads (>= 1). Throws std::runtime_error when no device opens.
  explicit EmbreeScene(int threads);
  ~EmbreeScene();
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  /// Builds the BVH over the body's positions and triangles (validated by the caller), for
  /// refitting when `moving`. Throws std::runtime_error naming the Embree error.
  void build(const BodyFrame& body, bool moving);
  /// Refits the BVH to the body's new positions (same topology as build); a BVH built static is
  /// rebuilt for refitting first. Throws std::runtime_error.
  void refit(const BodyFrame& body);
  /// Exact closest point of the body to p closer than `radius` [m] (infinity: unbounded);
  /// triangle = -1 when none is. Thread-safe; never throws.
  ClosestPoint closest(const Vec3& p, Real radius) const;
  /// True when the closed segment a -> b [m] meets a body triangle (one occlusion ray, either
  /// face). False for a zero-length segment. Thread-safe; never throws.
  bool segment_hits(const Vec3& a, const Vec3& b) const;

 private:
  void check(const std::string& what);
  void release_scene();

  RTCDevice device_ = nullptr;
  RTCScene scene_ = nullptr;
  RTCGeometry geometry_ = nullptr;
  std::vector<float> vertices_;         // shared vertex buffer: xyz per vertex + 1 spare float (3 nv + 1) [m]
  std::vector<std::uint32_t> indices_;  // shared index buffer (3 nt)
  std::string error_;                   // last message from the device error callback
  bool moving_ = false;                 // built dynamic, for refitting
};

}  // namespace clothbench::detail
