#pragma once
// internal: what every object-space collider shares: the contract's answer from a closest-point
// search, and the checks of set_body / update_body
#include <limits>
#include <stdexcept>
#include <string>

#include "clothbench/sim/collider.hpp"
#include "clothbench/sim/mesh_query.hpp"

namespace clothbench::detail {

/// Contact for p from `find(p, radius)` (exact closest point strictly within radius [m], or
/// triangle = -1): within search_radius the exact answer; otherwise a point outside the body's
/// bounding box `box` is far outside, and for the rest an unbounded search decides inside (exact
/// depth, hit) or far outside (hit = false, depth = search_radius, a lower bound).
template <class Find>
Contact answer_point(const BodyFrame& body, const PseudoNormals& pseudo, const Box3& box, const Vec3& p,
                     const ColliderOptions& options, const Find& find) {
  const ClosestPoint near = find(p, options.search_radius);
  if (near.triangle >= 0) return contact_from_closest(body, pseudo, p, near, options.tol);
  Contact far;
  far.depth = options.search_radius;
  // outside the bounding box of a closed mesh is outside the mesh
  if ((p.array() < box.min.array()).any() || (p.array() > box.max.array()).any()) return far;
  // nothing within the radius: only a point deep inside can still be a hit
  const ClosestPoint any = find(p, std::numeric_limits<Real>::infinity());
  const Contact c = contact_from_closest(body, pseudo, p, any, options.tol);
  return c.hit ? c : far;
}

/// Throws std::invalid_argument naming `what` when `body` cannot replace `current` in
/// update_body: no body set yet, a different topology, or a malformed frame.
inline void check_update(const BodyFrame& current, bool has_body, const BodyFrame& body, const std::string& what) {
  if (!has_body) throw std::invalid_argument(what + ": update_body called before set_body");
  validate_body(body, what);
  if (body.vertex_count() != current.vertex_count() || body.triangle_count() != current.triangle_count() ||
      body.triangles != current.triangles)
    throw std::invalid_argument(what + ": update_body needs the topology of set_body (" +
                                std::to_string(current.vertex_count()) + " vertices, " +
                                std::to_string(current.triangle_count()) + " triangles)");
}

/// Takes a checked frame's motion (positions, normals, velocities, time) into `current`; the
/// triangles are the same by check_update.
inline void adopt_frame(BodyFrame& current, const BodyFrame& body) {
  current.positions = body.positions;
  current.normals = body.normals;
  current.velocities = body.velocities;
  current.time_s = body.time_s;
  current.moving = body.moving;
}

}  // namespace clothbench::detail
