#include "clothbench/collide_os/bbtree_collider.hpp"

#include <cmath>

#include "clothbench/collide_os/object_space_collider.hpp"
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

// the quad tree of face boxes with the faces' normals (dressing §7) and its vertex-face test
class BbtreeCollider final : public ObjectSpaceCollider {
 public:
  explicit BbtreeCollider(const ColliderOptions& options) : ObjectSpaceCollider(options, {"bbtree", Keeps::kFrame}) {}

 private:
  void build(const BodyFrame& body) override {
    tree_.build(body);
    fit_normals();
  }

  // every box and face normal, to the new positions
  void refit(const BodyFrame& body) override {
    (void)body;
    tree_.refit();
    fit_normals();
  }

  // unit face normals; zero for a degenerate face
  void fit_normals() {
    normals_.resize(3, body().triangle_count());
    for (int t = 0; t < body().triangle_count(); ++t) {
      const Vec3 n = (tree_.corner(t, 1) - tree_.corner(t, 0)).cross(tree_.corner(t, 2) - tree_.corner(t, 0));
      normals_.col(t) = n.norm() > 0 ? Vec3(n.normalized()) : Vec3::Zero();
    }
  }

  // the vertex-face test, one tree search per point: among the faces whose box, grown by tol,
  // holds p and which p projects into, the one nearest along its normal
  Contact answer(const Vec3& p, detail::PointMemory* memory, std::int64_t& searches) const override {
    (void)memory;
    ++searches;
    const Real tol = options().tol;
    int best = -1;
    Real depth = 0;
    Vec3 bary = Vec3::Zero();
    Real reach2 = tol * tol;
    tree_.visit(p, reach2, [&](int t) {
      const Vec3 n = normals_.col(t);
      if (n.isZero()) return;
      const Real s = n.dot(p - tree_.corner(t, 0));
      const Vec3 b = barycentric(p - s * n, tree_.corner(t, 0), tree_.corner(t, 1), tree_.corner(t, 2));
      if (b.minCoeff() < -1e-5f || (best >= 0 && std::abs(s) >= std::abs(depth))) return;
      best = t, depth = s, bary = b;
    });
    Contact c;
    c.depth = tol;
    if (best < 0 || depth >= tol) return c;
    c.hit = true;
    c.depth = depth;
    c.normal = normals_.col(best);
    const BodyFrame& b = body();
    if (b.moving)
      for (int k = 0; k < 3; ++k) c.body_velocity += bary(k) * b.velocities.col(b.triangles(k, best));
    return c;
  }

  detail::TriangleTree tree_;  // the quad tree of face boxes (dressing §7)
  Points3 normals_;            // unit face normals (3 x nt); zero for a degenerate face
};

}  // namespace

std::unique_ptr<Collider> make_bbtree_collider(const ColliderOptions& options) {
  return std::make_unique<BbtreeCollider>(options);
}

}  // namespace clothbench
