#include "clothbench/bench/oracle.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>

#include "clothbench/config.h"
#include "clothbench/sim/mesh_query.hpp"
#include "clothbench/sim/timer.hpp"

#ifdef CLOTHBENCH_WITH_EMBREE
#include "clothbench/collide_os/embree_distance.hpp"
#endif

namespace clothbench {

#ifdef CLOTHBENCH_WITH_EMBREE

// Embree point query over the whole body
struct Oracle::Impl {
  EmbreeDistance distance;

  explicit Impl(const BodyFrame& body) { distance.set_body(body); }
  void update(const BodyFrame& body) { distance.update_body(body); }
  void signed_distance(PointsView points, Real* out) const { distance.signed_distance(points, out); }
  void segment_crossings(PointsView vertices, const Pairs& segments, std::uint8_t* out) const {
    distance.segment_crossings(vertices, segments, out);
  }
};

bool Oracle::uses_embree() { return true; }

#else

// fallback without Embree: every triangle per point, same sign rule
struct Oracle::Impl {
  BodyFrame body;
  PseudoNormals pseudo;

  explicit Impl(const BodyFrame& b) : body(b) {
    validate_body(body, "oracle");
    pseudo = PseudoNormals(body);
  }
  void update(const BodyFrame& b) {
    validate_body(b, "oracle");
    if (b.vertex_count() != body.vertex_count() || b.triangle_count() != body.triangle_count() ||
        b.triangles != body.triangles)
      throw std::invalid_argument("oracle: update_body needs the topology of the first frame");
    body.positions = b.positions;
    pseudo = PseudoNormals(body);
  }
  void signed_distance(PointsView points, Real* out) const {
    for (std::size_t i = 0; i < points.count; ++i) {
      const Vec3 p = points[i];
      if (!p.allFinite()) {
        out[i] = std::numeric_limits<Real>::quiet_NaN();
        continue;
      }
      const ClosestPoint cp = closest_point_brute(body, p);
      const Real dist = std::sqrt(cp.dist2);
      out[i] = (p - cp.point).dot(pseudo.at(cp)) < 0 ? -dist : dist;
    }
  }
  void segment_crossings(PointsView vertices, const Pairs& segments, std::uint8_t* out) const {
    for (Eigen::Index k = 0; k < segments.cols(); ++k) {
      const Vec3 a = vertices[std::size_t(segments(0, k))], b = vertices[std::size_t(segments(1, k))];
      // every triangle until one is met
      bool hit = false;
      for (int t = 0; t < body.triangle_count() && !hit && a.allFinite() && b.allFinite(); ++t)
        hit = segment_crosses_triangle(a, b, body.positions.col(body.triangles(0, t)),
                                       body.positions.col(body.triangles(1, t)),
                                       body.positions.col(body.triangles(2, t)));
      out[k] = hit ? 1 : 0;
    }
  }
};

bool Oracle::uses_embree() { return false; }

#endif

Pairs structural_springs(const ClothMesh& mesh) {
  Pairs out(2, mesh.count(SpringKind::kStructural));
  Eigen::Index n = 0;
  for (int s = 0; s < mesh.spring_count(); ++s)
    if (mesh.kind[std::size_t(s)] == SpringKind::kStructural) out.col(n++) = mesh.springs.col(s);
  return out;
}

bool segment_crosses_triangle(const Vec3& a, const Vec3& b, const Vec3& t0, const Vec3& t1, const Vec3& t2) {
  // Moller-Trumbore in double: the line a + t (b - a) meets the plane inside the closed triangle
  const Eigen::Vector3d o = a.cast<double>(), d = b.cast<double>() - o, v0 = t0.cast<double>();
  const Eigen::Vector3d e1 = t1.cast<double>() - v0, e2 = t2.cast<double>() - v0;
  const Eigen::Vector3d p = d.cross(e2);
  const double det = e1.dot(p);
  if (det == 0) return false;  // parallel, zero-length segment or degenerate triangle
  const Eigen::Vector3d s = o - v0;
  const double u = s.dot(p) / det;
  if (u < 0 || u > 1) return false;
  const Eigen::Vector3d q = s.cross(e1);
  const double v = d.dot(q) / det;
  if (v < 0 || u + v > 1) return false;
  // and within the segment, ends included
  const double t = e2.dot(q) / det;
  return t >= 0 && t <= 1;
}

Oracle::Oracle(const BodyFrame& body) : impl_(std::make_unique<Impl>(body)) {}
Oracle::~Oracle() = default;
Oracle::Oracle(Oracle&&) noexcept = default;
Oracle& Oracle::operator=(Oracle&&) noexcept = default;

void Oracle::update_body(const BodyFrame& body) { impl_->update(body); }

void Oracle::signed_distance(PointsView points, std::vector<Real>& out) const {
  out.resize(points.count);
  impl_->signed_distance(points, out.data());
}

void Oracle::segment_crossings(PointsView vertices, const Pairs& segments, std::vector<std::uint8_t>& out) const {
  // indices checked here, so the query loops need not
  if (segments.cols() > 0 && (segments.minCoeff() < 0 || std::size_t(segments.maxCoeff()) >= vertices.count))
    throw std::invalid_argument("oracle: a segment index lies outside the " + std::to_string(vertices.count) +
                                " cloth vertices");
  out.resize(std::size_t(segments.cols()));
  impl_->segment_crossings(vertices, segments, out.data());
}

void Oracle::measure_crossings(PointsView vertices, const Pairs& segments, Accuracy& a) const {
  const Stopwatch clock;
  std::vector<std::uint8_t> crosses;
  segment_crossings(vertices, segments, crosses);
  // segments with a non-finite end are not tested
  a.segments = 0;
  a.crossings = 0;
  for (Eigen::Index k = 0; k < segments.cols(); ++k) {
    if (!vertices[std::size_t(segments(0, k))].allFinite() || !vertices[std::size_t(segments(1, k))].allFinite())
      continue;
    ++a.segments;
    a.crossings += crosses[std::size_t(k)];
  }
  a.crossings_pct = a.segments > 0 ? 100.0 * double(a.crossings) / double(a.segments) : 0.0;
  a.crossings_ms = clock.ms();
}

void Oracle::measure_faces(PointsView vertices, const Quads& quads, Accuracy& a) const {
  if (quads.cols() > 0 && (quads.minCoeff() < 0 || std::size_t(quads.maxCoeff()) >= vertices.count))
    throw std::invalid_argument("oracle: a quad index lies outside the " + std::to_string(vertices.count) +
                                " cloth vertices");
  // midpoints as the face-body queries compute them
  Points3 mid(3, quads.cols());
  for (Eigen::Index q = 0; q < quads.cols(); ++q)
    mid.col(q) = 0.25f * (vertices[std::size_t(quads(0, q))] + vertices[std::size_t(quads(1, q))] +
                          vertices[std::size_t(quads(2, q))] + vertices[std::size_t(quads(3, q))]);
  std::vector<Real> depth;
  signed_distance(mid, depth);
  // non-finite midpoints are not tested
  a.faces = 0;
  a.faces_inside = 0;
  for (const Real d : depth) {
    if (!std::isfinite(d)) continue;
    ++a.faces;
    a.faces_inside += d < 0 ? 1 : 0;
  }
  a.faces_inside_pct = a.faces > 0 ? 100.0 * double(a.faces_inside) / double(a.faces) : 0.0;
}

Accuracy Oracle::measure(PointsView points) const {
  const Stopwatch clock;
  std::vector<Real> depth;
  signed_distance(points, depth);
  const double depth_ms = clock.ms();
  Accuracy a = penetration(depth);
  a.depth_ms = depth_ms;
  return a;
}

Accuracy Oracle::penetration(const std::vector<Real>& depth) {
  // penetration [mm] of every finite point; 0 outside
  Accuracy a;
  std::vector<double> pen;
  pen.reserve(depth.size());
  double sum = 0;
  for (std::size_t k = 0; k < depth.size(); ++k) {
    const Real d = depth[k];
    if (!std::isfinite(d)) continue;
    const double p = d < 0 ? -1000.0 * double(d) : 0.0;
    pen.push_back(p);
    if (d < 0) {
      ++a.inside;
      sum += p;
      if (p > a.depth_max_mm) a.depth_max_mm = p, a.deepest = static_cast<long>(k);
    }
  }
  a.points = pen.size();
  if (a.points == 0) return a;
  a.inside_pct = 100.0 * double(a.inside) / double(a.points);
  a.depth_mean_mm = a.inside > 0 ? sum / double(a.inside) : 0.0;
  // 95th percentile (nearest rank) over all points: 0 unless at least 5 % are inside
  const std::size_t rank = static_cast<std::size_t>(std::ceil(0.95 * double(a.points))) - 1;
  std::nth_element(pen.begin(), pen.begin() + std::ptrdiff_t(rank), pen.end());
  a.depth_p95_mm = pen[rank];
  return a;
}

Points3 points_off_surface(const BodyFrame& body, int count, Real lo, Real hi, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> tri(0, body.triangle_count() - 1);
  std::uniform_real_distribution<Real> unit(0, 1);
  Points3 p(3, count);
  for (int i = 0; i < count; ++i) {
    const int t = tri(rng);
    const Vec3 a = body.positions.col(body.triangles(0, t)), b = body.positions.col(body.triangles(1, t)),
               c = body.positions.col(body.triangles(2, t));
    Real u = unit(rng), v = unit(rng);
    if (u + v > 1) u = 1 - u, v = 1 - v;
    const Vec3 n = (b - a).cross(c - a).normalized();
    p.col(i) = a + u * (b - a) + v * (c - a) + (lo + (hi - lo) * unit(rng)) * n;
  }
  return p;
}

}  // namespace clothbench
