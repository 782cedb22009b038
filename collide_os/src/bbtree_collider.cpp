#include "clothbench/collide_os/bbtree_collider.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

#include "clothbench/sim/timer.hpp"
#include "object_space.hpp"

namespace clothbench {

namespace {

constexpr int kArity = 4;  // a quad tree of bounding boxes (dressing §7)

// a box of the tree: an inner node's children are nodes [first, first + count), a leaf's faces
// are faces[first, first + count) (at most kArity)
struct Node {
  Box3 box;
  int first = 0;
  int count = 0;
  bool leaf = false;
};

Real distance2(const Box3& b, const Vec3& p) {
  return (b.min - p).cwiseMax(p - b.max).cwiseMax(Vec3::Zero()).squaredNorm();
}

Box3 merged(const Box3& a, const Box3& b) { return {a.min.cwiseMin(b.min), a.max.cwiseMax(b.max)}; }

// barycentric coordinates of q in triangle (a, b, c), q in its plane (Ericson 3.4)
Vec3 barycentric(const Vec3& q, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 v0 = b - a, v1 = c - a, v2 = q - a;
  const Real d00 = v0.dot(v0), d01 = v0.dot(v1), d11 = v1.dot(v1), d20 = v2.dot(v0), d21 = v2.dot(v1);
  const Real den = d00 * d11 - d01 * d01;
  const Real v = (d11 * d20 - d01 * d21) / den, w = (d00 * d21 - d01 * d20) / den;
  return {1 - v - w, v, w};
}

}  // namespace

struct BbtreeCollider::Impl {
  ColliderOptions options;
  BodyFrame body;
  std::vector<int> faces;  // face indices, each leaf's contiguous
  std::vector<Node> nodes; // root first; children after their parent (refit runs backwards)
  Points3 normals;         // unit face normals (3 x nt); zero for a degenerate face
  bool has_body = false;
  CollideStats stats;

  Vec3 corner(int t, int k) const { return body.positions.col(body.triangles(k, t)); }
  Vec3 centroid(int t) const { return (corner(t, 0) + corner(t, 1) + corner(t, 2)) / 3; }

  // node `n` over faces[begin, end): a leaf, or kArity children cut at the quartiles of the face
  // centroids along their longest extent
  void split(int n, int begin, int end) {
    if (end - begin <= kArity) {
      nodes[std::size_t(n)].first = begin, nodes[std::size_t(n)].count = end - begin, nodes[std::size_t(n)].leaf = true;
      return;
    }
    Box3 spread{centroid(faces[std::size_t(begin)]), centroid(faces[std::size_t(begin)])};
    for (int i = begin; i < end; ++i) spread = merged(spread, {centroid(faces[std::size_t(i)]), centroid(faces[std::size_t(i)])});
    int axis = 0;
    spread.size().maxCoeff(&axis);
    std::sort(faces.begin() + begin, faces.begin() + end,
              [&](int a, int b) { return centroid(a)(axis) < centroid(b)(axis); });
    const int first = static_cast<int>(nodes.size());
    nodes[std::size_t(n)].first = first, nodes[std::size_t(n)].count = kArity;
    nodes.resize(nodes.size() + kArity);
    for (int k = 0; k < kArity; ++k)
      split(first + k, begin + (end - begin) * k / kArity, begin + (end - begin) * (k + 1) / kArity);
  }

  // face normals and every box from the current positions, leaves up
  void refit() {
    for (int t = 0; t < body.triangle_count(); ++t) {
      const Vec3 n = (corner(t, 1) - corner(t, 0)).cross(corner(t, 2) - corner(t, 0));
      normals.col(t) = n.norm() > 0 ? Vec3(n.normalized()) : Vec3::Zero();
    }
    for (std::size_t i = nodes.size(); i-- > 0;) {
      Node& n = nodes[i];
      const auto box_of = [&](int k) {
        return n.leaf ? face_box(faces[std::size_t(n.first + k)]) : nodes[std::size_t(n.first + k)].box;
      };
      n.box = box_of(0);
      for (int k = 1; k < n.count; ++k) n.box = merged(n.box, box_of(k));
    }
  }

  void build() {
    faces.resize(std::size_t(body.triangle_count()));
    std::iota(faces.begin(), faces.end(), 0);
    nodes.assign(1, Node{});
    split(0, 0, body.triangle_count());
    normals.resize(3, body.triangle_count());
    refit();
  }

  Box3 face_box(int t) const {
    return {corner(t, 0).cwiseMin(corner(t, 1)).cwiseMin(corner(t, 2)),
            corner(t, 0).cwiseMax(corner(t, 1)).cwiseMax(corner(t, 2))};
  }

  // the vertex-face test of one point against a leaf's faces: among the faces whose box, grown by
  // tol, holds the point and which the point projects into, the one nearest along its normal
  void test_leaf(const Node& leaf, const Vec3& p, int& best, Real& best_depth, Vec3& best_bary) const {
    for (int k = 0; k < leaf.count; ++k) {
      const int t = faces[std::size_t(leaf.first + k)];
      const Vec3 n = normals.col(t);
      if (n.isZero() || distance2(face_box(t), p) > options.tol * options.tol) continue;
      const Real s = n.dot(p - corner(t, 0));
      const Vec3 bary = barycentric(p - s * n, corner(t, 0), corner(t, 1), corner(t, 2));
      if (bary.minCoeff() < -1e-5f || (best >= 0 && std::abs(s) >= std::abs(best_depth))) continue;
      best = t, best_depth = s, best_bary = bary;
    }
  }

  Contact answer(const Vec3& p) const {
    const Real reach2 = options.tol * options.tol;
    int best = -1;
    Real depth = 0;
    Vec3 bary = Vec3::Zero();
    int stack[256];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
      const Node& n = nodes[std::size_t(stack[--top])];
      if (distance2(n.box, p) > reach2) continue;
      if (n.leaf) {
        test_leaf(n, p, best, depth, bary);
        continue;
      }
      for (int k = 0; k < n.count && top < 256; ++k) stack[top++] = n.first + k;
    }
    Contact c;
    c.depth = options.tol;
    if (best < 0 || depth >= options.tol) return c;
    c.hit = true;
    c.depth = depth;
    c.normal = normals.col(best);
    if (body.moving)
      for (int k = 0; k < 3; ++k) c.body_velocity += bary(k) * body.velocities.col(body.triangles(k, best));
    return c;
  }
};

BbtreeCollider::BbtreeCollider(const ColliderOptions& options) : impl_(std::make_unique<Impl>()) {
  impl_->options = options;
}

BbtreeCollider::~BbtreeCollider() = default;

void BbtreeCollider::set_body(const BodyFrame& body) {
  Stopwatch sw;
  validate_body(body, "bbtree collider");
  impl_->has_body = false;
  impl_->body = body;
  impl_->build();
  impl_->has_body = true;
  impl_->stats.setup_ms += sw.ms();
}

void BbtreeCollider::update_body(const BodyFrame& body) {
  Stopwatch sw;
  detail::check_update(impl_->body, impl_->has_body, body, "bbtree collider");
  detail::adopt_frame(impl_->body, body);
  impl_->refit();
  impl_->stats.update_ms += sw.ms();
  ++impl_->stats.updates;
}

void BbtreeCollider::query(PointsView points, ContactsOut out) {
  Stopwatch sw;
  Impl& s = *impl_;
  for (std::size_t i = 0; i < points.count; ++i) {
    const Vec3 p = points[i];
    if (!s.has_body || !p.allFinite()) {
      out[i] = Contact{};
      ++s.stats.degenerate;
      continue;
    }
    out[i] = s.answer(p);
    s.stats.hits += out[i].hit;
    ++s.stats.searches;
  }
  s.stats.points += static_cast<std::int64_t>(points.count);
  ++s.stats.queries;
  s.stats.query_ms += sw.ms();
}

CollideStats BbtreeCollider::stats() const { return impl_->stats; }

std::unique_ptr<Collider> make_bbtree_collider(const ColliderOptions& options) {
  return std::make_unique<BbtreeCollider>(options);
}

}  // namespace clothbench
