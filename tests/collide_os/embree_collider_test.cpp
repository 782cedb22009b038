// Embree specifics: worker threads, and the exact signed distance the oracle uses.
#include "clothbench/collide_os/embree_collider.hpp"
#include "clothbench/collide_os/embree_distance.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <vector>

#include "clothbench/sim/mesh_query.hpp"
#include "contact_compare.hpp"
#include "surface_points.hpp"

namespace clothbench {
namespace {

// brute-force signed distance: closest point over every triangle, pseudo-normal sign
Real brute_signed_distance(const BodyFrame& body, const PseudoNormals& pseudo, const Vec3& p) {
  const ClosestPoint cp = closest_point_brute(body, p);
  const Real dist = std::sqrt(cp.dist2);
  return (p - cp.point).dot(pseudo.at(cp)) < 0 ? -dist : dist;
}

TEST(EmbreeCollider, ThreadCountIsRecordedAndAnswersMatchOneThread) {
  const BodyFrame body = make_capsule_body(Vec3(0, 1, 0), 0.12f, 0.5f);
  const Points3 points = test::surface_points(body, 5000, 3);
  ColliderOptions one, three;
  three.threads = 3;
  const std::unique_ptr<Collider> a = make_embree_collider(one), b = make_embree_collider(three);
  EXPECT_EQ(a->stats().threads, 1);
  EXPECT_EQ(b->stats().threads, 3);
  a->set_body(body);
  b->set_body(body);
  std::vector<Contact> ra(5000), rb(5000);
  a->query(points, {ra.data(), ra.size()});
  b->query(points, {rb.data(), rb.size()});
  const test::ContactDiff d = test::compare_contacts(rb, ra);
  EXPECT_EQ(d.hit_mismatch, 0u) << test::describe(d);
  EXPECT_EQ(d.depth_max, 0.0);
  EXPECT_EQ(a->stats().hits, b->stats().hits);
  EXPECT_EQ(b->stats().points, 5000);
  EXPECT_GT(b->stats().hits, 0);
}

TEST(EmbreeDistance, MatchesBruteAndFollowsTheBody) {
  BodyFrame body = make_capsule_body(Vec3(0, 1, 0), 0.12f, 0.5f);
  EmbreeDistance distance;
  distance.set_body(body);
  const Points3 points = test::surface_points(body, 3000, 5, 0.7, 0.05f, 0.3f);
  // at set-up, then after a refit to a moved body
  for (int frame = 0; frame < 2; ++frame) {
    if (frame == 1) {
      body.positions.colwise() += Vec3(0.03f, 0.01f, -0.02f);
      body.positions.row(0) *= 1.1f;
      distance.update_body(body);
    }
    const PseudoNormals pseudo(body);
    std::vector<Real> got(std::size_t(points.cols()));
    distance.signed_distance(points, got.data());
    for (Eigen::Index i = 0; i < points.cols(); ++i)
      ASSERT_NEAR(got[std::size_t(i)], brute_signed_distance(body, pseudo, points.col(i)), 1e-6)
          << "frame " << frame << ", point " << i;
  }
}

TEST(EmbreeDistance, NonFinitePointsAndNoBodyGiveNaN) {
  Points3 p(3, 2);
  p.col(0) = Vec3(0, 0, 0);
  p.col(1) = Vec3(0, std::numeric_limits<Real>::quiet_NaN(), 0);
  Real out[2];
  EmbreeDistance empty;
  empty.signed_distance(p, out);
  EXPECT_TRUE(std::isnan(out[0]));
  // a moved-from object answers NaN, the moved-to one answers
  EmbreeDistance source;
  source.set_body(make_sphere_body(Vec3::Zero(), 0.1f));
  EmbreeDistance moved(std::move(source));
  moved.signed_distance(p, out);
  EXPECT_NEAR(out[0], -0.1f, 1e-3);
  EXPECT_TRUE(std::isnan(out[1]));
  EXPECT_THROW(empty.set_body(BodyFrame{}), std::invalid_argument);
}

}  // namespace
}  // namespace clothbench
