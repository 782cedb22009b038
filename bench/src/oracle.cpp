#include "oracle.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "clothbench/config.h"
#include "clothbench/sim/mesh_query.hpp"

#ifdef CLOTHBENCH_WITH_EMBREE
#include "clothbench/collide_os/embree_collider.hpp"
#endif

namespace clothbench {

#ifdef CLOTHBENCH_WITH_EMBREE

// Embree point query over the whole body
struct Oracle::Impl {
  EmbreeDistance distance;

  explicit Impl(const BodyFrame& body) { distance.set_body(body); }
  void update(const BodyFrame& body) { distance.update_body(body); }
  void signed_distance(PointsView points, Real* out) const { distance.signed_distance(points, out); }
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
};

bool Oracle::uses_embree() { return false; }

#endif

Oracle::Oracle(const BodyFrame& body) : impl_(std::make_unique<Impl>(body)) {}
Oracle::~Oracle() = default;
Oracle::Oracle(Oracle&&) noexcept = default;
Oracle& Oracle::operator=(Oracle&&) noexcept = default;

void Oracle::update_body(const BodyFrame& body) { impl_->update(body); }

void Oracle::signed_distance(PointsView points, std::vector<Real>& out) const {
  out.resize(points.count);
  impl_->signed_distance(points, out.data());
}

Accuracy Oracle::measure(PointsView points) const {
  std::vector<Real> depth;
  signed_distance(points, depth);
  // penetration [mm] of every finite point; 0 outside
  Accuracy a;
  std::vector<double> pen;
  pen.reserve(depth.size());
  double sum = 0;
  for (const Real d : depth) {
    if (!std::isfinite(d)) continue;
    const double p = d < 0 ? -1000.0 * double(d) : 0.0;
    pen.push_back(p);
    if (d < 0) {
      ++a.inside;
      sum += p;
      a.depth_max_mm = std::max(a.depth_max_mm, p);
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

}  // namespace clothbench
