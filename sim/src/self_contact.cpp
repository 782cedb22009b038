// Cloth against itself: Bridson, Fedkiw and Anderson 2002, section 7.1 (the inelastic repulsion impulse).
#include "clothbench/sim/self_contact.hpp"

#include <algorithm>

#include "clothbench/sim/mesh_query.hpp"

namespace clothbench {

namespace {

int root(std::vector<int>& parent, int i) {
  while (parent[std::size_t(i)] != i) i = parent[std::size_t(i)] = parent[std::size_t(parent[std::size_t(i)])];
  return i;
}

}  // namespace

void SelfContacts::group_points(const ClothMesh& mesh, const std::vector<std::vector<int>>& sewn) {
  // one point: a sewn group, and a seam pair, whose partners must be free to meet
  point_ = sewn_point_of(static_cast<std::size_t>(mesh.positions.cols()), sewn);
  const auto join = [&](int a, int b) { point_[std::size_t(root(point_, a))] = root(point_, b); };
  for (Eigen::Index p = 0; p < mesh.seam_pairs.cols(); ++p) join(mesh.seam_pairs(0, p), mesh.seam_pairs(1, p));
  for (std::size_t i = 0; i < point_.size(); ++i) point_[i] = root(point_, int(i));
}

long SelfContacts::respond(const ClothMesh& mesh, const std::vector<std::vector<int>>& sewn, const Points3& x,
                           Points3& v, const Scalars& inv_m, Real thickness) {
  if (point_.size() != static_cast<std::size_t>(mesh.positions.cols()) || sewn != grouped_) {
    group_points(mesh, sewn);  // only when seams have merged since
    grouped_ = sewn;
  }
  // the candidates, pairs within twice the thickness, are found again once a point has moved half a thickness
  // since they were: until then no other pair can have come within the thickness
  if (built_.cols() != x.cols() || !((x - built_).colwise().squaredNorm().maxCoeff() < 0.25f * thickness * thickness))
    find_candidates(mesh, x, 2 * thickness);
  long answered = 0;
  for (const auto& [i, t] : candidates_) {
    const auto& c = triangles_[std::size_t(t)];
    if (std::any_of(c.begin(), c.end(), [&](int k) { return point_[std::size_t(k)] == point_[std::size_t(i)]; }))
      continue;
    answered += stop(i, c, x, v, inv_m, thickness) ? 1 : 0;
  }
  return answered;
}

void SelfContacts::find_candidates(const ClothMesh& mesh, const Points3& x, Real reach) {
  if (triangles_.empty())
    for (Eigen::Index q = 0; q < mesh.quads.cols(); ++q) {
      triangles_.push_back({mesh.quads(0, q), mesh.quads(1, q), mesh.quads(2, q)});
      triangles_.push_back({mesh.quads(0, q), mesh.quads(2, q), mesh.quads(3, q)});
    }
  built_ = x;
  candidates_.clear();
  // cells about a spring long: a point's box spans one to eight
  grid_.build(x, triangles_, std::max(double(mesh.rest_length.mean()), 2.0 * double(reach)));
  seen_.assign(triangles_.size(), -1);
  for (Eigen::Index i = 0; i < x.cols(); ++i) {
    const Vec3 p = x.col(i), lo = p.array() - reach, hi = p.array() + reach;
    grid_.near(lo, hi, [&](int t) {
      const auto& c = triangles_[std::size_t(t)];
      if (seen_[std::size_t(t)] == i) return;
      seen_[std::size_t(t)] = i;
      const Vec3 a = x.col(c[0]), b = x.col(c[1]), d = x.col(c[2]);
      const bool apart = (a.cwiseMin(b).cwiseMin(d).array() > hi.array()).any() ||
                         (a.cwiseMax(b).cwiseMax(d).array() < lo.array()).any();
      // a triangle with a corner at the point's own vertex never is one (sewn points are checked at each step)
      if (!apart && c[0] != i && c[1] != i && c[2] != i && closest_point_on_triangle(p, a, b, d).dist2 < reach * reach)
        candidates_.emplace_back(i, t);
    });
  }
}

bool SelfContacts::stop(Eigen::Index i, const TriangleGrid::Triangle& c, const Points3& x, Points3& v,
                        const Scalars& inv_m, Real thickness) {
  const Vec3 p = x.col(i), a = x.col(c[0]), b = x.col(c[1]), d = x.col(c[2]);
  const ClosestPoint cp = closest_point_on_triangle(p, a, b, d);
  if (!(cp.dist2 < thickness * thickness)) return false;
  // the triangle's normal towards the point's side
  Vec3 n = (b - a).cross(d - a);
  if (!(n.squaredNorm() > 0)) return false;
  n.normalize();
  if ((p - cp.point).dot(n) < 0) n = -n;
  Vec3 vt = Vec3::Zero();
  Real w = inv_m[i];
  for (int k = 0; k < 3; ++k) {
    const int j = c[std::size_t(k)];
    vt += cp.bary[k] * v.col(j), w += cp.bary[k] * cp.bary[k] * inv_m[j];
  }
  const Real approach = (v.col(i) - vt).dot(n);
  if (!(approach < 0) || !(w > 0)) return false;
  const Real impulse = -approach / w;  // brings the relative normal velocity to zero
  v.col(i) += inv_m[i] * impulse * n;
  for (int k = 0; k < 3; ++k) v.col(c[std::size_t(k)]) -= cp.bary[k] * inv_m[c[std::size_t(k)]] * impulse * n;
  return true;
}

}  // namespace clothbench
