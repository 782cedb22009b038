// The OpenVDB collider: against `brute` on a sphere and the walking body, bad input, NaN points,
// the bands' edges, rebuild per frame, and the warning for parts thinner than a voxel.
#include <gtest/gtest.h>

#include <filesystem>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "clothbench/collide_os/vdb_collider.hpp"
#include "clothbench/io/body_loader.hpp"
#include "clothbench/io/data_root.hpp"
#include "clothbench/sim/brute_collider.hpp"
#include "contact_compare.hpp"
#include "surface_points.hpp"

namespace clothbench {
namespace {

using test::run;

std::vector<Contact> brute_answers(const BodyFrame& body, const Points3& points) {
  BruteForceCollider brute;
  brute.set_body(body);
  return run(brute, points);
}

// the conformance suite's tolerances for vdb at the default 2 mm voxel (see there)
void expect_close_to_brute(const test::ContactDiff& d, bool analytic) {
  using Q = test::ContactDiff;
  EXPECT_GE(d.hit_agreement_off_shell(), analytic ? 0.9999 : 0.995);
  EXPECT_LE(analytic ? d.depth_max : Q::quantile(d.depth_errors, 0.99), 0.0005);
  EXPECT_LE(analytic ? d.normal_max : Q::quantile(d.normal_errors, 0.9), analytic ? 10.0 : 15.0);
  EXPECT_LE(analytic ? d.velocity_max : Q::quantile(d.velocity_errors, 0.99), 1.0);
}

// two bodies as one (disjoint, both closed)
BodyFrame merged(const BodyFrame& a, const BodyFrame& b) {
  BodyFrame m = a;
  m.positions.conservativeResize(3, a.vertex_count() + b.vertex_count());
  m.positions.rightCols(b.vertex_count()) = b.positions;
  m.triangles.conservativeResize(3, a.triangle_count() + b.triangle_count());
  m.triangles.rightCols(b.triangle_count()) = b.triangles.array() + a.vertex_count();
  finish_static_body(m);
  return m;
}

// a closed box of half extents `half` at `center`, subdivided three times (768 triangles)
BodyFrame box_body(const Vec3& center, const Vec3& half) {
  BodyFrame b;
  b.positions.resize(3, 8);
  for (int i = 0; i < 8; ++i)  // vertex i: bit 0 x, bit 1 y, bit 2 z on the + side
    b.positions.col(i) = center + Vec3(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1).cwiseProduct(half);
  b.triangles.resize(3, 12);
  b.triangles << 0, 0, 1, 1, 0, 0, 2, 2, 0, 0, 4, 4,  //
      4, 6, 3, 7, 1, 5, 6, 7, 2, 3, 5, 7,             //
      6, 2, 7, 5, 5, 4, 7, 3, 3, 1, 7, 6;
  finish_static_body(b);
  for (int k = 0; k < 3; ++k) b = subdivide_body(b);
  return b;
}

ColliderOptions voxel(Real size) {
  ColliderOptions o;
  o.voxel_size = size;
  return o;
}

double area(const BodyFrame& b) {
  double sum = 0;
  for (int t = 0; t < b.triangle_count(); ++t) {
    const Vec3 p = b.positions.col(b.triangles(0, t));
    sum += 0.5 * double((b.positions.col(b.triangles(1, t)) - p).cross(b.positions.col(b.triangles(2, t)) - p).norm());
  }
  return sum;
}

TEST(VdbCollider, SphereAgreesWithBrute) {
  const BodyFrame body = make_sphere_body(Vec3(0.1f, 1.2f, -0.05f), 0.15f);
  const Points3 points = test::surface_points(body, 10000, 11);
  VdbCollider vdb(ColliderOptions{});
  vdb.set_body(body);
  const test::ContactDiff d =
      test::compare_contacts(run(vdb, points), brute_answers(body, points), ColliderOptions{}.tol, 0.002);
  SCOPED_TRACE(test::describe(d));
  expect_close_to_brute(d, true);
  EXPECT_EQ(vdb.uncaptured_share(), 0.0);
  EXPECT_EQ(vdb.stats().points, 10000);
  EXPECT_GT(vdb.stats().setup_ms, 0.0);
}

TEST(VdbCollider, WalkingBodyAgreesWithBrute) {
  const std::string path = data_path("body/mh_female_walk.glb");
  if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " not found (set CLOTHBENCH_DATA)";
  const BodyModel model = load_body(path);
  const BodyFrame walk = model.frame(model.animation_index("walk_07_01"), 2.0);
  const Points3 points = test::surface_points(walk, 1000, 5);
  VdbCollider vdb(ColliderOptions{});
  vdb.set_body(model.rest());
  vdb.update_body(walk);
  const test::ContactDiff d =
      test::compare_contacts(run(vdb, points), brute_answers(walk, points), ColliderOptions{}.tol, 0.002);
  SCOPED_TRACE(test::describe(d));
  expect_close_to_brute(d, false);
  // surfaces inside other parts (eyes, mouth) and gaps between toes
  EXPECT_GT(vdb.uncaptured_share(), 0.0);
  EXPECT_LT(vdb.uncaptured_share(), 0.05);
  EXPECT_GT(vdb.stats().update_ms, 0.0);
  EXPECT_EQ(vdb.stats().updates, 1);
}

TEST(VdbCollider, UpdateEqualsFreshSetBody) {
  const BodyFrame base = make_sphere_body(Vec3(0, 1, 0), 0.2f, 24, 48);
  BodyFrame moved = base;
  for (int v = 0; v < moved.vertex_count(); ++v) {
    const Vec3 p = base.positions.col(v);
    moved.positions.col(v) = Vec3(1.2f * p.x() + 0.1f * p.y(), 0.9f * p.y(), p.z()) + Vec3(0.02f, -0.01f, 0.03f);
    moved.velocities.col(v) = Vec3(-p.z(), 0.1f, p.x());
  }
  moved.normals = angle_weighted_normals(moved.positions, moved.triangles);
  moved.moving = true;
  VdbCollider updated(ColliderOptions{}), fresh(ColliderOptions{});
  updated.set_body(base);
  updated.update_body(moved);
  fresh.set_body(moved);
  const Points3 points = test::surface_points(moved, 3000, 7);
  // the field is rebuilt from scratch each frame: answers are bit for bit those of set_body
  const auto a = run(updated, points), b = run(fresh, points);
  int differ = 0;
  for (std::size_t i = 0; i < a.size(); ++i)
    differ += a[i].hit != b[i].hit || a[i].depth != b[i].depth || a[i].normal != b[i].normal ||
              a[i].body_velocity != b[i].body_velocity;
  EXPECT_EQ(differ, 0);
  EXPECT_EQ(updated.stats().updates, 1);
}

// a body that only translates (the moving sphere scenes) keeps its field, shifted: the answers
// agree with brute on the moved body as a fresh field's do, and the body velocity follows
TEST(VdbCollider, ATranslatedBodyKeepsItsFieldShifted) {
  const BodyFrame base = make_sphere_body(Vec3(0, 1, 0), 0.2f, 24, 48);
  BodyFrame moved = base;
  const Vec3 by(0.0123f, -0.031f, 0.2f);
  moved.positions.colwise() += by;
  moved.velocities = (by / 0.1f).replicate(1, moved.vertex_count());
  moved.moving = true;
  VdbCollider shifted(ColliderOptions{});
  shifted.set_body(base);
  shifted.update_body(moved);
  const Points3 points = test::surface_points(moved, 3000, 8);
  const test::ContactDiff d =
      test::compare_contacts(run(shifted, points), brute_answers(moved, points), ColliderOptions{}.tol, 0.002);
  SCOPED_TRACE(test::describe(d));
  expect_close_to_brute(d, true);
  // beyond a thousandth of a voxel from rigid, the field is built again: same answers as fresh
  moved.positions(0, 5) += 0.001f;
  shifted.update_body(moved);
  VdbCollider fresh(ColliderOptions{});
  fresh.set_body(moved);
  const auto a = run(shifted, points), b = run(fresh, points);
  for (std::size_t i = 0; i < a.size(); ++i) ASSERT_EQ(a[i].depth, b[i].depth) << "point " << i;
}

TEST(VdbCollider, BadInputThrowsClearErrors) {
  EXPECT_THROW(VdbCollider(voxel(0)), std::invalid_argument);
  EXPECT_THROW(VdbCollider(voxel(std::numeric_limits<Real>::quiet_NaN())),
               std::invalid_argument);
  VdbCollider c(ColliderOptions{});
  const BodyFrame good = make_sphere_body(Vec3::Zero(), 0.1f, 6, 12);
  EXPECT_THROW(c.update_body(good), std::invalid_argument);  // before set_body
  auto expect_message = [&](const BodyFrame& body, const std::string& part) {
    try {
      c.set_body(body);
      ADD_FAILURE() << "no exception for a body that should give '" << part << "'";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
    }
  };
  expect_message(BodyFrame{}, "no vertices");
  BodyFrame nan = good;
  nan.positions(1, 3) = std::numeric_limits<Real>::quiet_NaN();
  expect_message(nan, "non-finite");
  BodyFrame out_of_range = good;
  out_of_range.triangles(2, 5) = good.vertex_count();
  expect_message(out_of_range, "out of range");
  // a 2 m sphere at 0.1 mm voxels would need billions of band voxels
  VdbCollider fine(voxel(1e-4f));
  EXPECT_THROW(fine.set_body(make_sphere_body(Vec3::Zero(), 1.0f)), std::invalid_argument);
  c.set_body(good);
  EXPECT_THROW(c.update_body(make_sphere_body(Vec3::Zero(), 0.1f, 7, 12)), std::invalid_argument);
}

TEST(VdbCollider, NonFinitePointsAndQueriesBeforeSetBodyAreDegenerate) {
  VdbCollider c(ColliderOptions{});
  Points3 p(3, 4);
  p.col(0) = Vec3(0, 0, 0.099f);
  p.col(1) = Vec3(std::numeric_limits<Real>::quiet_NaN(), 0, 0);
  p.col(2) = Vec3(0, std::numeric_limits<Real>::infinity(), 0);
  p.col(3) = Vec3(0, 0, 0.2f);
  EXPECT_FALSE(run(c, p)[0].hit);  // no body yet
  EXPECT_EQ(c.stats().degenerate, 4);
  c.set_body(make_sphere_body(Vec3::Zero(), 0.1f));
  const auto out = run(c, p);
  EXPECT_TRUE(out[0].hit);
  EXPECT_FALSE(out[1].hit);
  EXPECT_FALSE(out[2].hit);
  EXPECT_FALSE(out[3].hit);
  EXPECT_EQ(c.stats().degenerate, 6);
  EXPECT_EQ(c.stats().hits, 1);
  EXPECT_EQ(c.stats().points, 8);
}

TEST(VdbCollider, BeyondTheBandsFarIsALowerBoundAndDeepIsExact) {
  const BodyFrame body = make_sphere_body(Vec3::Zero(), 0.2f);
  VdbCollider c(ColliderOptions{});
  c.set_body(body);
  Points3 p(3, 3);
  p.col(0) = Vec3(0, 0, 0.5f);           // 30 cm outside: beyond the exterior band and the box
  p.col(1) = Vec3(0.19f, 0.19f, 0.19f);  // 13 cm outside, in the box's corner
  p.col(2) = Vec3(0.01f, 0.02f, 0.05f);  // 15 cm deep: beyond the interior band
  const auto got = run(c, p);
  const auto ref = brute_answers(body, p);
  for (int i = 0; i < 2; ++i) {
    EXPECT_FALSE(got[std::size_t(i)].hit);
    EXPECT_GE(got[std::size_t(i)].depth, ColliderOptions{}.tol);
    EXPECT_LE(got[std::size_t(i)].depth, ref[std::size_t(i)].depth + 1e-4f);
  }
  EXPECT_TRUE(got[2].hit);
  EXPECT_NEAR(got[2].depth, ref[2].depth, 1e-6);
  EXPECT_LE(test::angle_deg(got[2].normal, ref[2].normal), 1e-3);
  EXPECT_EQ(c.deep_points(), 1);
}

TEST(VdbCollider, PartsThinnerThanAVoxelAreReportedWithTheirShare) {
  // a 1 mm thin plate beside a ball, at 1 cm voxels, between two planes of voxel centres: the
  // field cannot hold the plate
  const BodyFrame ball = make_sphere_body(Vec3(0, 1, 0), 0.15f);
  const BodyFrame plate = box_body(Vec3(0.4f, 1.005f, 0), Vec3(0.1f, 0.0005f, 0.1f));
  const BodyFrame body = merged(ball, plate);
  VdbCollider coarse(voxel(0.01f));
  ::testing::internal::CaptureStderr();
  coarse.set_body(body);
  const std::string warning = ::testing::internal::GetCapturedStderr();
  EXPECT_NE(warning.find("misses"), std::string::npos) << warning;
  const double plate_share = area(plate) / area(body);
  EXPECT_NEAR(coarse.uncaptured_share(), plate_share, 0.1 * plate_share);
  // the ball alone: nothing missed, nothing said
  VdbCollider ok(voxel(0.01f));
  ::testing::internal::CaptureStderr();
  ok.set_body(ball);
  EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");
  EXPECT_EQ(ok.uncaptured_share(), 0.0);
}

}  // namespace
}  // namespace clothbench
