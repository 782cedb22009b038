// The dressing paper's own object-space baseline (`bbtree`): where its vertex-face test sees, it
// agrees with brute; where it is blind by design (deep inside), it says so; refit, velocities and
// bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>
#include <vector>

#include "clothbench/collide_os/bbtree_collider.hpp"
#include "clothbench/sim/brute_collider.hpp"
#include "contact_compare.hpp"
#include "surface_points.hpp"

namespace clothbench {
namespace {

using test::run;

// points on a convex body within a shell of tol either side of its surface: the papers' method
// sees them (they lie in some face's box grown by tol, projecting into a face) and answers what
// the exact closest point answers, but for points just outside over an edge, beside both faces
TEST(BbtreeCollider, NearAConvexBodyItAgreesWithBrute) {
  const BodyFrame sphere = make_sphere_body(Vec3(0, 1, 0), 0.2f, 48, 96);
  const Real tol = ColliderOptions{}.tol;
  const std::unique_ptr<Collider> tree = make_bbtree_collider(ColliderOptions{});
  BruteForceCollider brute;
  tree->set_body(sphere);
  brute.set_body(sphere);
  const Points3 points = test::surface_points(sphere, 4000, 3, 1.0, tol);
  const auto got = run(*tree, points), ref = run(brute, points);
  int differ = 0, compared = 0;
  for (std::size_t i = 0; i < got.size(); ++i) {
    differ += got[i].hit != ref[i].hit;
    if (!got[i].hit || !ref[i].hit) continue;
    ++compared;
    EXPECT_NEAR(got[i].depth, ref[i].depth, 1e-4f) << "point " << i;
    EXPECT_GT(got[i].normal.dot(ref[i].normal), std::cos(0.1f)) << "point " << i;  // a facet's normal
  }
  EXPECT_LT(differ, int(got.size()) / 100) << differ << " of " << got.size() << " differ";
  EXPECT_GT(compared, int(got.size()) / 2);
  EXPECT_EQ(tree->stats().searches, std::int64_t(points.cols()));
}

// a point deeper than tol behind every face lies in no face's box grown by tol: the method does
// not see it (the paper's "holes"), where brute does
TEST(BbtreeCollider, DeepInsideIsItsBlindSpot) {
  const BodyFrame sphere = make_sphere_body(Vec3::Zero(), 0.2f, 24, 48);
  const std::unique_ptr<Collider> tree = make_bbtree_collider(ColliderOptions{});
  tree->set_body(sphere);
  Points3 p(3, 2);
  p.col(0) = Vec3(0, 0, 0.19f);   // 1 cm deep
  p.col(1) = Vec3(0, 0, 0.198f);  // 2 mm deep: seen
  const auto got = run(*tree, p);
  EXPECT_FALSE(got[0].hit);
  ASSERT_TRUE(got[1].hit);
  EXPECT_NEAR(got[1].depth, -0.002f, 5e-4f);
}

// refitted boxes answer as a tree built on the moved body; body velocities interpolate
TEST(BbtreeCollider, RefitEqualsRebuildAndVelocitiesFollow) {
  const BodyFrame base = make_sphere_body(Vec3(0, 1, 0), 0.2f, 24, 48);
  BodyFrame moved = base;
  const Vec3 velocity(0.3f, -0.1f, 0.2f);
  for (int v = 0; v < moved.vertex_count(); ++v) {
    const Vec3 p = base.positions.col(v);
    moved.positions.col(v) = Vec3(1.2f * p.x(), 0.9f * p.y() + 0.1f, p.z()) + Vec3(0.02f, 0, 0.03f);
    moved.velocities.col(v) = velocity;
  }
  moved.normals = angle_weighted_normals(moved.positions, moved.triangles);
  moved.moving = true;
  const std::unique_ptr<Collider> refit = make_bbtree_collider(ColliderOptions{}),
                                  rebuilt = make_bbtree_collider(ColliderOptions{});
  refit->set_body(base);
  refit->update_body(moved);
  rebuilt->set_body(moved);
  const Points3 points = test::surface_points(moved, 3000, 9, 1.0, 0.01f);
  const auto a = run(*refit, points), b = run(*rebuilt, points);
  int hits = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    ASSERT_EQ(a[i].hit, b[i].hit) << "point " << i;
    if (!a[i].hit) continue;
    ++hits;
    EXPECT_EQ(a[i].depth, b[i].depth) << "point " << i;
    EXPECT_LT((a[i].body_velocity - velocity).norm(), 1e-5f) << "point " << i;
  }
  EXPECT_GT(hits, 100);
  EXPECT_EQ(refit->stats().updates, 1);
}

TEST(BbtreeCollider, BadInputGivesClearErrorsAndNaNPointsAreDegenerate) {
  const std::unique_ptr<Collider> tree = make_bbtree_collider(ColliderOptions{});
  const BodyFrame sphere = make_sphere_body(Vec3::Zero(), 0.1f, 6, 12);
  EXPECT_THROW(tree->update_body(sphere), std::invalid_argument);  // before set_body
  EXPECT_THROW(tree->set_body(BodyFrame{}), std::invalid_argument);
  BodyFrame broken = sphere;
  broken.positions(1, 3) = std::numeric_limits<Real>::quiet_NaN();
  EXPECT_THROW(tree->set_body(broken), std::invalid_argument);
  Points3 p(3, 1);
  p.col(0) = Vec3::Constant(std::numeric_limits<Real>::quiet_NaN());
  EXPECT_FALSE(run(*tree, p)[0].hit);  // no body yet
  tree->set_body(sphere);
  EXPECT_FALSE(run(*tree, p)[0].hit);
  EXPECT_EQ(tree->stats().degenerate, 2);
}

}  // namespace
}  // namespace clothbench
