#pragma once
// internal: the helpers behind ObjectSpaceCollider (object_space_collider.hpp) and EmbreeDistance:
// the contract's answer from a closest-point search, temporal coherence, the checks of update_body
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "clothbench/sim/collider.hpp"
#include "clothbench/sim/mesh_query.hpp"

namespace clothbench::detail {

/// Contact for p from `find(p, radius)` (exact closest point strictly within radius [m], or
/// triangle = -1), searching from scratch (no memory: see the overload below): within search_radius the exact answer; otherwise a point
/// outside the body's bounding box `box` is far outside, and for the rest an unbounded search
/// decides inside (exact depth, hit) or far outside (hit = false, depth = search_radius, a lower
/// bound). What ColliderOptions::coherent = false selects. Counts the point in `searches`.
template <class Find>
Contact answer_point(const BodyFrame& body, const PseudoNormals& pseudo, const Box3& box, const Vec3& p,
                     const ColliderOptions& options, const Find& find, std::int64_t& searches) {
  ++searches;
  const ClosestPoint near = find(p, options.search_radius);
  if (near.triangle >= 0) return contact_from_closest(body, pseudo, p, near, options.tol, options.face_normals);
  Contact far;
  far.depth = options.search_radius;
  // outside the bounding box of a closed mesh is outside the mesh
  if ((p.array() < box.min.array()).any() || (p.array() > box.max.array()).any()) return far;
  // nothing within the radius: only a point deep inside can still be a hit
  const ClosestPoint any = find(p, std::numeric_limits<Real>::infinity());
  const Contact c = contact_from_closest(body, pseudo, p, any, options.tol, options.face_normals);
  return c.hit ? c : far;
}

/// What one query point left behind for the next query of the same point array.
struct PointMemory {
  Vec3 at = Vec3::Zero();  ///< where it was answered [m]
  Real outside = 0;        ///< lower bound of its distance outside the body there [m]; 0: none
  int triangle = -1;       ///< its closest triangle then, -1 when none was searched
  double body_moved = 0;   ///< Coherence::body_moved() then [m]
};

/// Temporal coherence of object-space queries: per point array (the simulator's vertices, its
/// quad midpoints) the memory of each point, and how far any body vertex has moved so far. Only
/// bounds are carried, never answers, so answers equal those of a search from scratch whatever
/// points a caller passes; the same array is merely faster.
class Coherence {
 public:
  /// Memory for the `count` points at `xyz`: kept from the last query of the same array and
  /// count, fresh otherwise (the least recently used of four arrays is forgotten).
  PointMemory* memory(const Real* xyz, std::size_t count) {
    ++clock_;
    for (Slot& s : slots_)
      if (s.xyz == xyz && s.points.size() == count) return s.used = clock_, s.points.data();
    if (slots_.size() < 4) slots_.emplace_back();
    Slot& s = *std::min_element(slots_.begin(), slots_.end(), [](const Slot& a, const Slot& b) { return a.used < b.used; });
    s = Slot{xyz, std::vector<PointMemory>(count), clock_};
    return s.points.data();
  }
  /// The body moved from `before` to `after` (same vertex count): every surface point moved at
  /// most the largest vertex displacement (surface points are convex combinations of vertices).
  void body_moves(const Points3& before, const Points3& after) {
    body_moved_ += double((after - before).colwise().norm().maxCoeff());
  }
  double body_moved() const { return body_moved_; }
  void forget() { slots_.clear(); }

 private:
  struct Slot {
    const Real* xyz = nullptr;
    std::vector<PointMemory> points;
    std::uint64_t used = 0;
  };
  std::vector<Slot> slots_;
  std::uint64_t clock_ = 0;
  double body_moved_ = 0;
};

/// Squared distance from p to the box (0 inside it) [m^2]: a lower bound of the squared distance
/// to whatever the box holds.
inline Real squared_distance_to_box(const Vec3& p, const Box3& box) {
  return (box.min - p).cwiseMax(p - box.max).cwiseMax(Vec3::Zero()).squaredNorm();
}

/// Contact for p with its memory `*memory` (updated), or from scratch when `memory` is null: a
/// point that cannot have come within tol since it was last known outside (its bound, less its own
/// motion and the body's) is a miss without a search; the others search within the distance to
/// their last closest triangle (an exact upper bound; unbounded the first time), counted in
/// `searches`. Answers are exact: a miss's depth is a lower bound >= tol.
template <class Find>
Contact answer_point(const BodyFrame& body, const PseudoNormals& pseudo, const Box3& box, const Vec3& p,
                     const ColliderOptions& options, const Find& find, PointMemory* memory, double body_moved,
                     std::int64_t& searches) {
  if (!memory) return answer_point(body, pseudo, box, p, options, find, searches);
  PointMemory& m = *memory;
  constexpr Real kSlack = 1e-6f;  // float rounding of the stored distances [m]
  Contact miss;
  miss.depth = m.outside - (p - m.at).norm() - Real(body_moved - m.body_moved) - kSlack;
  if (m.outside > 0 && miss.depth >= options.tol) return miss;
  m.at = p;
  m.body_moved = body_moved;
  miss.depth = m.outside = std::sqrt(squared_distance_to_box(p, box));
  if (miss.depth >= options.tol) return miss;
  ++searches;
  ClosestPoint seed;
  Real radius = std::numeric_limits<Real>::infinity();
  if (m.triangle >= 0) {
    const auto corner = [&](int k) { return body.positions.col(body.triangles(k, m.triangle)); };
    seed = closest_point_on_triangle(p, corner(0), corner(1), corner(2));
    seed.triangle = m.triangle;
    radius = std::nextafter(std::sqrt(seed.dist2), radius);
  }
  ClosestPoint cp = find(p, radius);
  if (cp.triangle < 0) cp = seed;
  const Contact c = contact_from_closest(body, pseudo, p, cp, options.tol, options.face_normals);
  m.triangle = cp.triangle;
  m.outside = c.hit ? 0 : c.depth;
  return c;
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

}  // namespace clothbench::detail
