// The accuracy oracle: exact signed distance (Embree or the brute fallback) and its statistics.
#include "clothbench/bench/oracle.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "clothbench/sim/mesh_query.hpp"
#include "surface_points.hpp"

namespace clothbench {
namespace {

const BodyFrame& capsule() {
  static const BodyFrame body = make_capsule_body(Vec3(0, 1, 0), 0.12f, 0.5f);
  return body;
}

// points at known signed distances: centroids of the capsule's side triangles (vertical faces)
// pushed along their normal by depth_mm[i] (negative: inside)
Points3 points_at(const std::vector<double>& depth_mm) {
  const BodyFrame& b = capsule();
  Points3 p(3, Eigen::Index(depth_mm.size()));
  int found = 0;
  for (int t = 0; t < b.triangle_count() && found < p.cols(); ++t) {
    const Vec3 v0 = b.positions.col(b.triangles(0, t)), v1 = b.positions.col(b.triangles(1, t)),
               v2 = b.positions.col(b.triangles(2, t));
    const Vec3 n = (v1 - v0).cross(v2 - v0).normalized();
    const Vec3 centroid = (v0 + v1 + v2) / 3;
    if (std::abs(n.y()) > 1e-4f || std::abs(centroid.y() - 1.0f) > 0.15f) continue;
    p.col(found) = centroid + Real(depth_mm[std::size_t(found)] / 1000.0) * n;
    ++found;
  }
  return p;
}

TEST(Oracle, SignedDistanceAgreesWithBrute) {
  const Oracle oracle(capsule());
  const PseudoNormals pseudo(capsule());
  const Points3 points = test::surface_points(capsule(), 2000, 9);
  std::vector<Real> d;
  oracle.signed_distance(points, d);
  ASSERT_EQ(d.size(), 2000u);
  for (Eigen::Index i = 0; i < points.cols(); ++i) {
    const ClosestPoint cp = closest_point_brute(capsule(), points.col(i));
    const Real dist = std::sqrt(cp.dist2);
    const Real expected = (Vec3(points.col(i)) - cp.point).dot(pseudo.at(cp)) < 0 ? -dist : dist;
    ASSERT_NEAR(d[std::size_t(i)], expected, 1e-6) << "point " << i;
  }
}

TEST(Oracle, KnownDepthsGiveTheirStatistics) {
  // 5 inside at 1..5 mm, 15 outside at 1..15 mm, and one NaN point (skipped)
  std::vector<double> depth;
  for (int k = 1; k <= 5; ++k) depth.push_back(-k);
  for (int k = 1; k <= 15; ++k) depth.push_back(k);
  Points3 points = points_at(depth);
  points.conservativeResize(3, points.cols() + 1);
  points.col(points.cols() - 1) = Vec3::Constant(std::numeric_limits<Real>::quiet_NaN());
  const Oracle oracle(capsule());
  std::vector<Real> d;
  oracle.signed_distance(points, d);
  for (std::size_t i = 0; i < depth.size(); ++i) ASSERT_NEAR(d[i] * 1000, depth[i], 1e-3) << "point " << i;
  EXPECT_TRUE(std::isnan(d.back()));

  const Accuracy a = oracle.measure(points);
  EXPECT_EQ(a.points, 20u);
  EXPECT_EQ(a.inside, 5u);
  EXPECT_NEAR(a.inside_pct, 25.0, 1e-9);
  EXPECT_NEAR(a.depth_max_mm, 5.0, 1e-3);
  EXPECT_NEAR(a.depth_mean_mm, 3.0, 1e-3);
  EXPECT_NEAR(a.depth_p95_mm, 4.0, 1e-3);  // nearest rank 19 of 20: fifteen zeros, then 1..5
}

TEST(Oracle, FewInsideGiveZeroPercentileAndMovesWithTheBody) {
  std::vector<double> depth(40, 2.0);
  depth[0] = -3.0;
  const Points3 points = points_at(depth);
  Oracle oracle(capsule());
  Accuracy a = oracle.measure(points);
  EXPECT_EQ(a.inside, 1u);
  EXPECT_NEAR(a.depth_max_mm, 3.0, 1e-3);
  EXPECT_EQ(a.depth_p95_mm, 0.0);
  // the body moves 1 cm outward along +x: points on the +x side end up inside
  BodyFrame moved = capsule();
  moved.positions.row(0) *= 1.2f;
  oracle.update_body(moved);
  a = oracle.measure(points);
  EXPECT_GT(a.inside, 1u);
  EXPECT_THROW(oracle.update_body(make_sphere_body(Vec3::Zero(), 0.1f)), std::invalid_argument);
}

}  // namespace
}  // namespace clothbench
