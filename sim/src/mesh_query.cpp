#include "clothbench/sim/mesh_query.hpp"

#include <cmath>
#include <limits>
#include <unordered_map>

namespace clothbench {

ClosestPoint closest_point_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  // Voronoi regions of the vertices, then edges, then the face (Ericson 5.1.5)
  ClosestPoint r;
  auto done = [&](const Vec3& bary, int feature) {
    r.bary = bary;
    r.point = bary[0] * a + bary[1] * b + bary[2] * c;
    r.dist2 = (p - r.point).squaredNorm();
    r.feature = feature;
    return r;
  };
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const Real d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return done(Vec3(1, 0, 0), 4);
  const Vec3 bp = p - b;
  const Real d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return done(Vec3(0, 1, 0), 5);
  const Real vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) {
    const Real v = d1 / (d1 - d3);
    return done(Vec3(1 - v, v, 0), 1);
  }
  const Vec3 cp = p - c;
  const Real d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return done(Vec3(0, 0, 1), 6);
  const Real vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) {
    const Real w = d2 / (d2 - d6);
    return done(Vec3(1 - w, 0, w), 3);
  }
  const Real va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    const Real w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return done(Vec3(0, 1 - w, w), 2);
  }
  const Real denom = va + vb + vc;
  if (!(std::abs(denom) > 0)) return done(Vec3(1, 0, 0), 4);  // degenerate: fall back to a vertex
  const Real v = vb / denom, w = vc / denom;
  return done(Vec3(1 - v - w, v, w), 0);
}

PseudoNormals::PseudoNormals(const BodyFrame& body) : tris_(&body.triangles) {
  const Tris& t = body.triangles;
  const Eigen::Index nt = t.cols();
  face_.resize(3, nt);
  for (Eigen::Index i = 0; i < nt; ++i) {
    const Vec3 n = (body.positions.col(t(1, i)) - body.positions.col(t(0, i)))
                       .cross(body.positions.col(t(2, i)) - body.positions.col(t(0, i)));
    const Real len = n.norm();
    face_.col(i) = len > 0 ? Vec3(n / len) : Vec3::Zero();
  }
  // edge pseudo-normal: sum of the unit normals of the faces sharing the edge
  std::unordered_map<std::uint64_t, Vec3> edge_sum;
  edge_sum.reserve(static_cast<std::size_t>(nt) * 2);
  auto key = [&](Eigen::Index i, int k) {
    std::uint32_t a = static_cast<std::uint32_t>(t(k, i)), b = static_cast<std::uint32_t>(t((k + 1) % 3, i));
    if (a > b) std::swap(a, b);
    return (std::uint64_t(a) << 32) | b;
  };
  for (Eigen::Index i = 0; i < nt; ++i)
    for (int k = 0; k < 3; ++k) {
      auto [it, fresh] = edge_sum.emplace(key(i, k), Vec3::Zero());
      it->second += face_.col(i);
    }
  edge_.resize(3, 3 * nt);
  for (Eigen::Index i = 0; i < nt; ++i)
    for (int k = 0; k < 3; ++k) edge_.col(3 * i + k) = edge_sum[key(i, k)];
  vertex_ = angle_weighted_normals(body.positions, t);
}

Vec3 PseudoNormals::at(const ClosestPoint& cp) const {
  if (cp.feature == 0) return face_.col(cp.triangle);
  if (cp.feature <= 3) return edge_.col(3 * cp.triangle + (cp.feature - 1));
  return vertex_.col((*tris_)(cp.feature - 4, cp.triangle));
}

Contact contact_from_closest(const BodyFrame& body, const PseudoNormals& pseudo, const Vec3& p,
                             const ClosestPoint& cp, Real tol, bool face_normal) {
  Contact c;
  if (cp.triangle < 0) {
    c.depth = std::numeric_limits<float>::infinity();
    return c;
  }
  const Real dist = std::sqrt(cp.dist2);
  const bool inside = (p - cp.point).dot(pseudo.at(cp)) < 0;
  c.depth = inside ? -dist : dist;
  c.hit = inside || dist < tol;
  if (!c.hit) return c;
  // barycentric interpolation of vertex normals and velocities at the closest point
  Vec3 n = Vec3::Zero(), v = Vec3::Zero();
  for (int k = 0; k < 3; ++k) {
    const int vi = body.triangles(k, cp.triangle);
    n += cp.bary[k] * body.normals.col(vi);
    v += cp.bary[k] * body.velocities.col(vi);
  }
  if (face_normal) {
    const auto corner = [&](int k) { return body.positions.col(body.triangles(k, cp.triangle)); };
    n = (corner(1) - corner(0)).cross(corner(2) - corner(0));
  }
  const Real len = n.norm();
  c.normal = len > 0 ? Vec3(n / len) : pseudo.at(cp).normalized();
  c.body_velocity = v;
  return c;
}

ClosestPoint closest_point_brute(const BodyFrame& body, const Vec3& p) {
  ClosestPoint best;
  best.dist2 = std::numeric_limits<Real>::infinity();
  for (Eigen::Index t = 0; t < body.triangles.cols(); ++t) {
    ClosestPoint cp = closest_point_on_triangle(p, body.positions.col(body.triangles(0, t)),
                                                body.positions.col(body.triangles(1, t)),
                                                body.positions.col(body.triangles(2, t)));
    if (cp.dist2 < best.dist2) {
      best = cp;
      best.triangle = static_cast<int>(t);
    }
  }
  return best;
}

}  // namespace clothbench
