#pragma once
// internal: a quad tree of axis-aligned boxes over a body's triangles, refitted in place. bbtree's
// vertex-face test walks it (dressing §7), vdb finds exact closest points on it for the points its
// field does not cover.
#include <algorithm>
#include <limits>
#include <numeric>
#include <utility>
#include <vector>

#include "clothbench/sim/mesh_query.hpp"
#include "object_space.hpp"

namespace clothbench::detail {

class TriangleTree {
 public:
  static constexpr int kArity = 4;

  /// Builds the tree over `body`'s triangles (validated by the caller) and fits it; the tree keeps
  /// a pointer to `body`, which must outlive it and keep its topology (refit() after moves).
  void build(const BodyFrame& body) {
    body_ = &body;
    faces_.resize(std::size_t(body.triangle_count()));
    std::iota(faces_.begin(), faces_.end(), 0);
    nodes_.assign(1, Node{});
    split(0, 0, body.triangle_count());
    refit();
  }

  /// Every box fitted to the body's current positions, leaves up.
  void refit() {
    for (std::size_t i = nodes_.size(); i-- > 0;) {
      Node& n = nodes_[i];
      const auto box_of = [&](int k) { return n.leaf ? face_box(faces_[std::size_t(n.first + k)]) : nodes_[std::size_t(n.first + k)].box; };
      n.box = box_of(0);
      for (int k = 1; k < n.count; ++k) n.box = merged(n.box, box_of(k));
    }
  }

  /// Calls face(t) for every triangle t whose box lies within sqrt(reach2) of p [m^2]; face may
  /// lower reach2 (a nearest search, then `nearest_first` prunes more) but never raise it.
  template <class Face>
  void visit(const Vec3& p, Real& reach2, const Face& face, bool nearest_first = false) const {
    int stack[512];  // depth first: at most 3 per level waiting
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
      const Node& n = nodes_[std::size_t(stack[--top])];
      if (squared_distance_to_box(p, n.box) > reach2) continue;
      if (n.leaf) {
        for (int k = 0; k < n.count; ++k) {
          const int t = faces_[std::size_t(n.first + k)];
          if (squared_distance_to_box(p, face_box(t)) <= reach2) face(t);
        }
        continue;
      }
      // the children within reach (with nearest_first, the nearest popped first)
      std::pair<Real, int> near[kArity];
      int m = 0;
      for (int k = 0; k < n.count; ++k) {
        const Real d2 = squared_distance_to_box(p, nodes_[std::size_t(n.first + k)].box);
        if (d2 > reach2) continue;
        int at = m++;  // insertion, farthest first
        for (; nearest_first && at > 0 && near[at - 1].first < d2; --at) near[at] = near[at - 1];
        near[at] = {d2, n.first + k};
      }
      for (int k = 0; k < m && top < int(sizeof stack / sizeof *stack); ++k) stack[top++] = near[k].second;
    }
  }

  /// The exact closest point of the body to p (triangle -1 for a body without triangles).
  ClosestPoint closest(const Vec3& p) const {
    ClosestPoint best;
    Real reach2 = std::numeric_limits<Real>::infinity();
    visit(p, reach2, [&](int t) {
      ClosestPoint cp = closest_point_on_triangle(p, corner(t, 0), corner(t, 1), corner(t, 2));
      if (!(cp.dist2 < reach2)) return;
      cp.triangle = t;
      best = cp;
      reach2 = cp.dist2;
    }, true);
    return best;
  }

  Vec3 corner(int t, int k) const { return body_->positions.col(body_->triangles(k, t)); }

  Box3 face_box(int t) const {
    return {corner(t, 0).cwiseMin(corner(t, 1)).cwiseMin(corner(t, 2)),
            corner(t, 0).cwiseMax(corner(t, 1)).cwiseMax(corner(t, 2))};
  }

 private:
  // an inner node's children are nodes [first, first + count), a leaf's triangles
  // faces_[first, first + count) (at most kArity)
  struct Node {
    Box3 box;
    int first = 0;
    int count = 0;
    bool leaf = false;
  };

  static Box3 merged(const Box3& a, const Box3& b) { return {a.min.cwiseMin(b.min), a.max.cwiseMax(b.max)}; }
  Vec3 centroid(int t) const { return (corner(t, 0) + corner(t, 1) + corner(t, 2)) / 3; }

  // node n over faces_[begin, end): a leaf, or kArity children cut at the quartiles of the
  // triangle centroids along their longest extent
  void split(int n, int begin, int end) {
    if (end - begin <= kArity) {
      nodes_[std::size_t(n)].first = begin, nodes_[std::size_t(n)].count = end - begin;
      nodes_[std::size_t(n)].leaf = true;
      return;
    }
    Box3 spread{centroid(faces_[std::size_t(begin)]), centroid(faces_[std::size_t(begin)])};
    for (int i = begin; i < end; ++i) {
      const Vec3 c = centroid(faces_[std::size_t(i)]);
      spread = merged(spread, {c, c});
    }
    int axis = 0;
    spread.size().maxCoeff(&axis);
    std::sort(faces_.begin() + begin, faces_.begin() + end,
              [&](int a, int b) { return centroid(a)(axis) < centroid(b)(axis); });
    const int first = static_cast<int>(nodes_.size());
    nodes_[std::size_t(n)].first = first, nodes_[std::size_t(n)].count = kArity;
    nodes_.resize(nodes_.size() + kArity);
    for (int k = 0; k < kArity; ++k)
      split(first + k, begin + (end - begin) * k / kArity, begin + (end - begin) * (k + 1) / kArity);
  }

  const BodyFrame* body_ = nullptr;
  std::vector<int> faces_;   // triangle indices, each leaf's contiguous
  std::vector<Node> nodes_;  // root first; children after their parent (refit runs backwards)
};

}  // namespace clothbench::detail
