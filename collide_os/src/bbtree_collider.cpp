#include "clothbench/collide_os/bbtree_collider.hpp"

#include <cmath>

#include "clothbench/sim/timer.hpp"
#include "object_space.hpp"
#include "triangle_tree.hpp"

namespace clothbench {

namespace {

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
  detail::TriangleTree tree;  // the quad tree of face boxes (dressing §7)
  Points3 normals;            // unit face normals (3 x nt); zero for a degenerate face
  bool has_body = false;
  CollideStats stats;

  void fit_normals() {
    normals.resize(3, body.triangle_count());
    for (int t = 0; t < body.triangle_count(); ++t) {
      const Vec3 n = (tree.corner(t, 1) - tree.corner(t, 0)).cross(tree.corner(t, 2) - tree.corner(t, 0));
      normals.col(t) = n.norm() > 0 ? Vec3(n.normalized()) : Vec3::Zero();
    }
  }

  // the vertex-face test: among the faces whose box, grown by tol, holds p and which p projects
  // into, the one nearest along its normal
  Contact answer(const Vec3& p) const {
    int best = -1;
    Real depth = 0;
    Vec3 bary = Vec3::Zero();
    Real reach2 = options.tol * options.tol;
    tree.visit(p, reach2, [&](int t) {
      const Vec3 n = normals.col(t);
      if (n.isZero()) return;
      const Real s = n.dot(p - tree.corner(t, 0));
      const Vec3 b = barycentric(p - s * n, tree.corner(t, 0), tree.corner(t, 1), tree.corner(t, 2));
      if (b.minCoeff() < -1e-5f || (best >= 0 && std::abs(s) >= std::abs(depth))) return;
      best = t, depth = s, bary = b;
    });
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
  impl_->tree.build(impl_->body);
  impl_->fit_normals();
  impl_->has_body = true;
  impl_->stats.setup_ms += sw.ms();
}

void BbtreeCollider::update_body(const BodyFrame& body) {
  Stopwatch sw;
  detail::check_update(impl_->body, impl_->has_body, body, "bbtree collider");
  detail::adopt_frame(impl_->body, body);
  impl_->tree.refit();
  impl_->fit_normals();
  impl_->stats.update_ms += sw.ms();
  ++impl_->stats.updates;
}

void BbtreeCollider::query(PointsView points, ContactsOut out) {
  Impl& s = *impl_;
  detail::answer_points(points, out, s.has_body, s.stats, [&s](std::size_t, const Vec3& p) {
    ++s.stats.searches;
    return s.answer(p);
  });
}

CollideStats BbtreeCollider::stats() const { return impl_->stats; }

std::unique_ptr<Collider> make_bbtree_collider(const ColliderOptions& options) {
  return std::make_unique<BbtreeCollider>(options);
}

}  // namespace clothbench
