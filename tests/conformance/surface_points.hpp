#pragma once
// test helper: query points concentrated near a body surface, fixed seed
#include <random>
#include <vector>

#include "clothbench/sim/body_frame.hpp"

namespace clothbench::test {

/// `count` points [m] (3 x count): a share `near_share` on the surface (random triangle picked by
/// area, random barycentric point) offset along the face normal by a uniform amount in
/// [-offset, +offset]; the rest uniform in the bounding box grown by `margin` on every side.
inline Points3 surface_points(const BodyFrame& body, int count, unsigned seed, double near_share = 0.8,
                              Real offset = 0.03f, Real margin = 0.05f) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<Real> unit(0, 1);
  // triangle areas for picking by area
  std::vector<double> area(static_cast<std::size_t>(body.triangle_count()));
  for (int t = 0; t < body.triangle_count(); ++t) {
    const Vec3 a = body.positions.col(body.triangles(0, t)), b = body.positions.col(body.triangles(1, t)),
               c = body.positions.col(body.triangles(2, t));
    area[std::size_t(t)] = 0.5 * double((b - a).cross(c - a).norm());
  }
  std::discrete_distribution<int> pick(area.begin(), area.end());
  const Box3 box = bounding_box(body.positions);
  const Vec3 lo = box.min - Vec3::Constant(margin), size = box.size() + Vec3::Constant(2 * margin);
  Points3 p(3, count);
  const int near = static_cast<int>(near_share * count);
  for (int i = 0; i < count; ++i) {
    if (i >= near) {
      p.col(i) = lo + Vec3(unit(rng), unit(rng), unit(rng)).cwiseProduct(size);
      continue;
    }
    // a surface point pushed along the face normal
    const int t = pick(rng);
    const Vec3 a = body.positions.col(body.triangles(0, t)), b = body.positions.col(body.triangles(1, t)),
               c = body.positions.col(body.triangles(2, t));
    Real u = unit(rng), v = unit(rng);
    if (u + v > 1) u = 1 - u, v = 1 - v;
    const Vec3 n = (b - a).cross(c - a).normalized();
    p.col(i) = a + u * (b - a) + v * (c - a) + (2 * unit(rng) - 1) * offset * n;
  }
  return p;
}

}  // namespace clothbench::test
