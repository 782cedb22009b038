#include "clothbench/sim/body_frame.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <unordered_map>

namespace clothbench {

Box3 bounding_box(const Points3& points) {
  if (points.cols() == 0) throw std::invalid_argument("bounding_box: empty point set");
  return {points.rowwise().minCoeff(), points.rowwise().maxCoeff()};
}

Points3 angle_weighted_normals(const Points3& positions, const Tris& triangles) {
  Points3 n(3, positions.cols());
  angle_weighted_normals_into(positions, triangles, n);
  return n;
}

void angle_weighted_normals_into(const Points3& positions, const Tris& triangles, Points3& n) {
  n.setZero(3, positions.cols());
  for (Eigen::Index t = 0; t < triangles.cols(); ++t) {
    // face normal weighted by the interior angle at each corner
    const Vec3 p[3] = {positions.col(triangles(0, t)), positions.col(triangles(1, t)),
                       positions.col(triangles(2, t))};
    const Vec3 fn = (p[1] - p[0]).cross(p[2] - p[0]);
    const Real len = fn.norm();
    if (!(len > 0)) continue;
    const Vec3 unit = fn / len;
    for (int k = 0; k < 3; ++k) {
      const Vec3 e1 = p[(k + 1) % 3] - p[k];
      const Vec3 e2 = p[(k + 2) % 3] - p[k];
      const Real denom = e1.norm() * e2.norm();
      if (!(denom > 0)) continue;
      const Real c = std::clamp(e1.dot(e2) / denom, Real(-1), Real(1));
      n.col(triangles(k, t)) += std::acos(c) * unit;
    }
  }
  for (Eigen::Index v = 0; v < n.cols(); ++v) {
    const Real len = n.col(v).norm();
    if (len > 0) n.col(v) /= len;
  }
}

EdgeCheck check_edges(const Tris& triangles) {
  // count undirected edges by a 64-bit key
  std::unordered_map<std::uint64_t, int> uses;
  uses.reserve(static_cast<std::size_t>(triangles.cols()) * 3);
  for (Eigen::Index t = 0; t < triangles.cols(); ++t) {
    for (int k = 0; k < 3; ++k) {
      std::uint32_t a = static_cast<std::uint32_t>(triangles(k, t));
      std::uint32_t b = static_cast<std::uint32_t>(triangles((k + 1) % 3, t));
      if (a > b) std::swap(a, b);
      ++uses[(std::uint64_t(a) << 32) | b];
    }
  }
  EdgeCheck check;
  for (const auto& [key, count] : uses) {
    if (count == 1) ++check.boundary_edges;
    if (count > 2) ++check.non_manifold_edges;
  }
  return check;
}

void validate_body(const BodyFrame& body, const std::string& what) {
  const Eigen::Index nv = body.positions.cols();
  if (nv == 0) throw std::invalid_argument(what + ": body has no vertices");
  if (body.triangles.cols() == 0) throw std::invalid_argument(what + ": body has no triangles");
  if (body.normals.cols() != nv || body.velocities.cols() != nv)
    throw std::invalid_argument(what + ": normals/velocities do not match the vertex count");
  if (!body.positions.allFinite())
    throw std::invalid_argument(what + ": body has non-finite vertex coordinates");
  if (!body.velocities.allFinite())
    throw std::invalid_argument(what + ": body has non-finite vertex velocities");
  if (body.triangles.minCoeff() < 0 || body.triangles.maxCoeff() >= nv)
    throw std::invalid_argument(what + ": triangle index out of range (" + std::to_string(nv) +
                                " vertices)");
}

void finish_static_body(BodyFrame& body) {
  body.normals = angle_weighted_normals(body.positions, body.triangles);
  body.velocities = Points3::Zero(3, body.positions.cols());
  body.moving = false;
}

namespace {

// latitude-longitude grid of rings between two poles; `ring` gives (radius, y) per ring
template <class RingFn>
BodyFrame make_revolved(int rings, int nlon, RingFn ring) {
  BodyFrame b;
  const int nv = 2 + rings * nlon;
  b.positions.resize(3, nv);
  const auto [r0, ybot] = ring(-1);
  const auto [r1, ytop] = ring(rings);
  (void)r0;
  (void)r1;
  b.positions.col(0) = Vec3(0, ybot, 0);
  b.positions.col(nv - 1) = Vec3(0, ytop, 0);
  for (int i = 0; i < rings; ++i) {
    const auto [r, y] = ring(i);
    for (int j = 0; j < nlon; ++j) {
      const Real phi = Real(2 * M_PI) * Real(j) / Real(nlon);
      b.positions.col(1 + i * nlon + j) = Vec3(r * std::cos(phi), y, -r * std::sin(phi));
    }
  }
  std::vector<Eigen::Vector3i> tris;
  auto id = [&](int i, int j) { return 1 + i * nlon + ((j % nlon) + nlon) % nlon; };
  for (int j = 0; j < nlon; ++j) tris.emplace_back(0, id(0, j + 1), id(0, j));
  for (int i = 0; i + 1 < rings; ++i)
    for (int j = 0; j < nlon; ++j) {
      tris.emplace_back(id(i, j), id(i, j + 1), id(i + 1, j + 1));
      tris.emplace_back(id(i, j), id(i + 1, j + 1), id(i + 1, j));
    }
  for (int j = 0; j < nlon; ++j) tris.emplace_back(nv - 1, id(rings - 1, j), id(rings - 1, j + 1));
  b.triangles.resize(3, static_cast<Eigen::Index>(tris.size()));
  for (std::size_t t = 0; t < tris.size(); ++t) b.triangles.col(static_cast<Eigen::Index>(t)) = tris[t];
  finish_static_body(b);
  return b;
}

}  // namespace

BodyFrame make_sphere_body(const Vec3& center, Real radius, int nlat, int nlon) {
  if (nlat < 2 || nlon < 3 || !(radius > 0)) throw std::invalid_argument("make_sphere_body: bad size");
  BodyFrame b = make_revolved(nlat - 1, nlon, [&](int i) {
    const Real theta = Real(M_PI) * Real(i + 1) / Real(nlat);  // from the bottom pole
    return std::pair<Real, Real>(radius * std::sin(theta), -radius * std::cos(theta));
  });
  b.positions.colwise() += center;
  return b;
}

BodyFrame make_capsule_body(const Vec3& center, Real radius, Real length, int nlat, int nlon) {
  if (nlat < 2 || nlon < 3 || !(radius > 0) || !(length >= 0))
    throw std::invalid_argument("make_capsule_body: bad size");
  // nlat-1 rings per hemisphere including the equator rings at +-length/2
  const int half = nlat / 2;
  BodyFrame b = make_revolved(2 * half, nlon, [&](int i) {
    const bool top = i >= half;
    const int k = top ? i - half : i;  // 0..half-1
    const Real theta = top ? Real(M_PI / 2) * Real(k) / Real(half)
                           : Real(M_PI / 2) * Real(k + 1) / Real(half) - Real(M_PI / 2);
    const Real y = radius * std::sin(theta) + (top ? length / 2 : -length / 2);
    if (i == -1) return std::pair<Real, Real>(0, -length / 2 - radius);
    if (i == 2 * half) return std::pair<Real, Real>(0, length / 2 + radius);
    return std::pair<Real, Real>(radius * std::cos(theta), y);
  });
  b.positions.colwise() += center;
  return b;
}

BodyFrame subdivide_body(const BodyFrame& body) {
  // one new vertex per undirected edge, four triangles per triangle
  std::unordered_map<std::uint64_t, int> mid;
  std::vector<Vec3> pos, vel;
  for (Eigen::Index v = 0; v < body.positions.cols(); ++v) {
    pos.push_back(body.positions.col(v));
    vel.push_back(body.velocities.col(v));
  }
  auto midpoint = [&](int a, int b) {
    const std::uint64_t key = (std::uint64_t(std::min(a, b)) << 32) | std::uint32_t(std::max(a, b));
    auto [it, fresh] = mid.emplace(key, static_cast<int>(pos.size()));
    if (fresh) {
      pos.push_back(0.5f * (pos[a] + pos[b]));
      vel.push_back(0.5f * (vel[a] + vel[b]));
    }
    return it->second;
  };
  BodyFrame out;
  out.triangles.resize(3, body.triangles.cols() * 4);
  for (Eigen::Index t = 0; t < body.triangles.cols(); ++t) {
    const int a = body.triangles(0, t), b = body.triangles(1, t), c = body.triangles(2, t);
    const int ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
    out.triangles.col(4 * t + 0) << a, ab, ca;
    out.triangles.col(4 * t + 1) << ab, b, bc;
    out.triangles.col(4 * t + 2) << ca, bc, c;
    out.triangles.col(4 * t + 3) << ab, bc, ca;
  }
  out.positions.resize(3, static_cast<Eigen::Index>(pos.size()));
  out.velocities.resize(3, static_cast<Eigen::Index>(pos.size()));
  for (std::size_t v = 0; v < pos.size(); ++v) {
    out.positions.col(static_cast<Eigen::Index>(v)) = pos[v];
    out.velocities.col(static_cast<Eigen::Index>(v)) = vel[v];
  }
  out.normals = angle_weighted_normals(out.positions, out.triangles);
  out.time_s = body.time_s;
  out.moving = body.moving;
  return out;
}

}  // namespace clothbench
