#include "clothbench/sim/mesh_query.hpp"

#include <gtest/gtest.h>

#include <random>

#include "clothbench/sim/brute_collider.hpp"
#include "clothbench/sim/sphere_collider.hpp"
#include "test_support.hpp"

namespace clothbench {
namespace {

TEST(MeshQuery, ClosestPointRegions) {
  const Vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  EXPECT_EQ(closest_point_on_triangle(Vec3(0.2f, 0.2f, 1), a, b, c).feature, 0);
  EXPECT_TRUE(test::near_vec(closest_point_on_triangle(Vec3(0.2f, 0.2f, 1), a, b, c).point, Vec3(0.2f, 0.2f, 0), 1e-6));
  EXPECT_EQ(closest_point_on_triangle(Vec3(-1, -1, 0), a, b, c).feature, 4);
  EXPECT_EQ(closest_point_on_triangle(Vec3(0.5f, -1, 0), a, b, c).feature, 1);
  EXPECT_EQ(closest_point_on_triangle(Vec3(1, 1, 0), a, b, c).feature, 2);
  EXPECT_NEAR(closest_point_on_triangle(Vec3(1, 1, 0), a, b, c).dist2, 0.5f, 1e-6);
}

// brute force on a fine sphere mesh agrees with the analytic sphere in sign and distance
TEST(MeshQuery, BruteMatchesAnalyticSphere) {
  const BodyFrame mesh = make_sphere_body(Vec3::Zero(), 0.3f, 48, 96);
  BruteForceCollider brute;
  brute.set_body(mesh);
  SphereCollider exact(Vec3::Zero(), 0.3f);
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(-0.4f, 0.4f);
  Points3 pts(3, 2000);
  for (int i = 0; i < pts.cols(); ++i) pts.col(i) = Vec3(u(rng), u(rng), u(rng));
  std::vector<Contact> a(pts.cols()), b(pts.cols());
  brute.query(pts, {a.data(), a.size()});
  exact.query(pts, {b.data(), b.size()});
  int sign_agree = 0;
  for (int i = 0; i < pts.cols(); ++i) {
    sign_agree += (a[i].depth < 0) == (b[i].depth < 0);
    EXPECT_NEAR(a[i].depth, b[i].depth, 2e-3) << "point " << i;  // chord error of the mesh
  }
  EXPECT_GE(sign_agree, 1990);
  EXPECT_EQ(brute.stats().points, 2000);
}

// dressing section 7's response normal: the closest triangle's face normal, not the interpolated vertex normal
TEST(MeshQuery, FaceNormalsAreTheClosestTrianglesOwn) {
  const BodyFrame coarse = make_sphere_body(Vec3::Zero(), 0.3f, 6, 12);
  ColliderOptions options;
  options.face_normals = true;
  BruteForceCollider faces(options), vertices;
  faces.set_body(coarse);
  vertices.set_body(coarse);
  Points3 p(3, 1);
  // just inside, next to a mesh vertex: there the interpolated normal is the vertex's, about 15 degrees off the face's
  p.col(0) = 0.98f * coarse.positions.col(20) + 0.002f * (coarse.positions.col(21) - coarse.positions.col(20));
  std::vector<Contact> f(1), v(1);
  faces.query(p, {f.data(), 1});
  vertices.query(p, {v.data(), 1});
  ASSERT_TRUE(f[0].hit);
  const ClosestPoint cp = closest_point_brute(coarse, p.col(0));
  const auto corner = [&](int k) { return coarse.positions.col(coarse.triangles(k, cp.triangle)); };
  const Vec3 face = (corner(1) - corner(0)).cross(corner(2) - corner(0)).normalized();
  EXPECT_NEAR(f[0].normal.dot(face), 1, 1e-5);
  EXPECT_LT(v[0].normal.dot(face), 0.9999f);  // the vertex normals' blend differs
  EXPECT_FLOAT_EQ(f[0].depth, v[0].depth);    // only the normal changes
}

TEST(MeshQuery, NaNPointsAreCountedDegenerate) {
  BruteForceCollider brute;
  brute.set_body(make_sphere_body(Vec3::Zero(), 0.3f, 8, 16));
  Points3 pts(3, 2);
  pts.col(0) = Vec3(std::nanf(""), 0, 0);
  pts.col(1) = Vec3(0, 0, 0);
  std::vector<Contact> c(2);
  brute.query(pts, {c.data(), c.size()});
  EXPECT_FALSE(c[0].hit);
  EXPECT_TRUE(c[1].hit);
  EXPECT_LT(c[1].depth, 0);
  EXPECT_EQ(brute.stats().degenerate, 1);
}

}  // namespace
}  // namespace clothbench
