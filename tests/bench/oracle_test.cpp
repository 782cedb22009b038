// The oracle's crossings (structural springs through body triangles) and penetrating faces, counted
// by hand on a box.
#include "clothbench/bench/oracle.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "clothbench/bench/report.hpp"
#include "clothbench/sim/mesh_query.hpp"
#include "surface_points.hpp"

namespace clothbench {
namespace {

constexpr Real kHalf = 0.15f;  // the box body spans [-kHalf, kHalf] on every axis [m]

// a closed box of 12 triangles, wound outward
BodyFrame box_body() {
  BodyFrame b;
  b.positions.resize(3, 8);
  for (int i = 0; i < 8; ++i)
    b.positions.col(i) = Vec3(i & 1 ? kHalf : -kHalf, i & 2 ? kHalf : -kHalf, i & 4 ? kHalf : -kHalf);
  const int quads[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  b.triangles.resize(3, 12);
  for (int f = 0; f < 6; ++f)
    for (int h = 0; h < 2; ++h) {
      int t[3] = {quads[f][0], quads[f][1 + h], quads[f][2 + h]};
      const Vec3 a = b.positions.col(t[0]), e1 = b.positions.col(t[1]) - a, e2 = b.positions.col(t[2]) - a;
      if (e1.cross(e2).dot(a + e1 / 3 + e2 / 3) < 0) std::swap(t[1], t[2]);
      b.triangles.col(2 * f + h) << t[0], t[1], t[2];
    }
  finish_static_body(b);
  return b;
}

// 7 x 7 vertices 0.1 m apart in the plane y = height, x and z in [-0.3, 0.3]
ClothMesh grid_at(Real height) {
  return make_grid_cloth(7, 7, 0.1f, Vec3(-0.3f, height, -0.3f), Vec3::UnitX(), Vec3::UnitZ());
}

Points3 two_points(const Vec3& a, const Vec3& b) {
  Points3 p(3, 2);
  p << a, b;
  return p;
}

Pairs one_segment() {
  Pairs s(2, 1);
  s << 0, 1;
  return s;
}

TEST(Crossings, SegmentTriangleByHand) {
  const Vec3 t0(0, 0, 0), t1(1, 0, 0), t2(0, 1, 0);
  EXPECT_TRUE(segment_crosses_triangle(Vec3(0.2f, 0.2f, -1), Vec3(0.2f, 0.2f, 1), t0, t1, t2));
  EXPECT_TRUE(segment_crosses_triangle(Vec3(0.2f, 0.2f, 1), Vec3(0.2f, 0.2f, -1), t0, t1, t2));  // either face
  EXPECT_TRUE(segment_crosses_triangle(Vec3(0.2f, 0.2f, 0), Vec3(0.2f, 0.2f, 1), t0, t1, t2));   // end on it
  EXPECT_FALSE(segment_crosses_triangle(Vec3(0.2f, 0.2f, 0.1f), Vec3(0.2f, 0.2f, 1), t0, t1, t2));
  EXPECT_FALSE(segment_crosses_triangle(Vec3(0.8f, 0.8f, -1), Vec3(0.8f, 0.8f, 1), t0, t1, t2));  // beside it
  EXPECT_FALSE(segment_crosses_triangle(Vec3(-1, 0.2f, 0), Vec3(1, 0.2f, 0), t0, t1, t2));        // in its plane
  EXPECT_FALSE(segment_crosses_triangle(Vec3(0.2f, 0.2f, 0), Vec3(0.2f, 0.2f, 0), t0, t1, t2));   // zero length
}

TEST(Crossings, GridThroughABoxCountedByHand) {
  // inside the box: x, z in {-0.1, 0, 0.1}; each of the 3 inside rows and 3 inside columns has
  // 2 springs leaving the box (-0.2 <-> -0.1 and 0.1 <-> 0.2) and 2 wholly inside
  const ClothMesh cloth = grid_at(0);
  const Pairs springs = structural_springs(cloth);
  ASSERT_EQ(springs.cols(), 2 * 7 * 6);
  const Oracle oracle(box_body());
  Accuracy a = oracle.measure(cloth.positions);
  oracle.measure_crossings(cloth.positions, springs, a);
  EXPECT_EQ(a.inside, 9u);
  EXPECT_EQ(a.segments, 84u);
  EXPECT_EQ(a.crossings, 12u);
  EXPECT_NEAR(a.crossings_pct, 100.0 * 12 / 84, 1e-9);
  EXPECT_GE(a.crossings_ms, 0.0);
  // shear and flexion springs also cross there: the count is the structural springs' only
  Accuracy all;
  oracle.measure_crossings(cloth.positions, cloth.springs, all);
  EXPECT_GT(all.crossings, a.crossings);
}

TEST(Crossings, PenetratingFacesCountedByHand) {
  // 6 x 6 vertices 0.12 m apart from -0.3: vertices inside at +-0.06 (2 x 2), quad midpoints
  // inside at -0.12, 0, 0.12 (3 x 3)
  ClothMesh cloth = make_grid_cloth(6, 6, 0.12f, Vec3(-0.3f, 0, -0.3f), Vec3::UnitX(), Vec3::UnitZ());
  ASSERT_EQ(cloth.quads.cols(), 25);
  const Oracle oracle(box_body());
  Accuracy a = oracle.measure(cloth.positions);
  oracle.measure_faces(cloth.positions, cloth.quads, a);
  EXPECT_EQ(a.inside, 4u);
  EXPECT_EQ(a.faces, 25u);
  EXPECT_EQ(a.faces_inside, 9u);
  EXPECT_NEAR(a.faces_inside_pct, 100.0 * 9 / 25, 1e-9);
  // a non-finite corner leaves its quad untested; a bad index throws
  cloth.positions.col(0).setConstant(std::numeric_limits<Real>::quiet_NaN());
  oracle.measure_faces(cloth.positions, cloth.quads, a);
  EXPECT_EQ(a.faces, 24u);
  cloth.quads(2, 5) = 36;
  EXPECT_THROW(oracle.measure_faces(cloth.positions, cloth.quads, a), std::invalid_argument);
}

TEST(Crossings, ClothOutsideCrossesNothing) {
  const ClothMesh cloth = grid_at(kHalf + 0.05f);
  const Oracle oracle(box_body());
  Accuracy a = oracle.measure(cloth.positions);
  oracle.measure_crossings(cloth.positions, structural_springs(cloth), a);
  EXPECT_EQ(a.inside, 0u);
  EXPECT_EQ(a.segments, 84u);
  EXPECT_EQ(a.crossings, 0u);
  EXPECT_EQ(a.crossings_pct, 0.0);
}

TEST(Crossings, SpringInsideCrossesNothingButCountsInside) {
  const Points3 p = two_points(Vec3(-0.05f, 0, 0), Vec3(0.05f, 0.1f, 0));
  const Oracle oracle(box_body());
  Accuracy a = oracle.measure(p);
  oracle.measure_crossings(p, one_segment(), a);
  EXPECT_EQ(a.inside, 2u);
  EXPECT_EQ(a.crossings, 0u);
}

TEST(Crossings, SpringThroughTheBodyWithBothEndsOutside) {
  // the tunnelling case vertex queries cannot see: no point inside, one crossing
  const Points3 p = two_points(Vec3(-0.2f, 0.05f, 0), Vec3(0.2f, 0.05f, 0));
  const Oracle oracle(box_body());
  Accuracy a = oracle.measure(p);
  oracle.measure_crossings(p, one_segment(), a);
  EXPECT_EQ(a.inside, 0u);
  EXPECT_EQ(a.crossings, 1u);
  EXPECT_NEAR(a.crossings_pct, 100.0, 1e-9);
}

TEST(Crossings, NonFiniteSegmentsAreNotTestedAndBadIndicesThrow) {
  Points3 p(3, 3);
  p << Vec3(-0.2f, 0, 0), Vec3(0.2f, 0, 0), Vec3::Constant(std::numeric_limits<Real>::quiet_NaN());
  Pairs s(2, 2);
  s << 0, 0, 1, 2;
  const Oracle oracle(box_body());
  Accuracy a;
  oracle.measure_crossings(p, s, a);
  EXPECT_EQ(a.segments, 1u);
  EXPECT_EQ(a.crossings, 1u);
  s(1, 1) = 3;
  EXPECT_THROW(oracle.measure_crossings(p, s, a), std::invalid_argument);
  s(1, 1) = -1;
  EXPECT_THROW(oracle.measure_crossings(p, s, a), std::invalid_argument);
}

TEST(Crossings, FollowTheBody) {
  // the box moves 0.5 m up: the grid at y = 0 no longer crosses it
  const ClothMesh cloth = grid_at(0);
  Oracle oracle(box_body());
  BodyFrame moved = box_body();
  moved.positions.row(1).array() += 0.5f;
  oracle.update_body(moved);
  Accuracy a;
  oracle.measure_crossings(cloth.positions, structural_springs(cloth), a);
  EXPECT_EQ(a.crossings, 0u);
}

TEST(Crossings, ReachTheJsonRowUnlessDiverged) {
  RunResult r;
  const ClothMesh cloth = grid_at(0);
  const Oracle oracle(box_body());
  r.accuracy = oracle.measure(cloth.positions);
  oracle.measure_crossings(cloth.positions, structural_springs(cloth), r.accuracy);
  nlohmann::json row = result_row(r, "box/grid");
  EXPECT_EQ(row["crossings"], 12);
  EXPECT_EQ(row["structural_springs"], 84);
  EXPECT_NEAR(row["crossings_pct"].get<double>(), 100.0 * 12 / 84, 1e-9);
  EXPECT_TRUE(row.contains("oracle_depth_ms") && row.contains("oracle_crossings_ms") &&
              row.contains("faces_inside_pct"));
  r.divergence = Divergence{};
  row = result_row(r, "box/grid");
  EXPECT_FALSE(row.contains("crossings"));
}

// --- signed distance (Embree or the brute fallback) and its statistics

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
  EXPECT_EQ(a.deepest, 4);  // the point 5 mm inside
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
  EXPECT_EQ(a.deepest, 0);
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
