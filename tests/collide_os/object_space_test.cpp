// Behaviour every object-space collider (fcl, embree) shares: refit equals rebuild, bad input,
// NaN points, degenerate triangles, the search radius.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "clothbench/bench/registry.hpp"
#include "clothbench/sim/brute_collider.hpp"
#include "contact_compare.hpp"
#include "surface_points.hpp"

namespace clothbench {
namespace {

// a non-rigid motion of a body: stretched, sheared, shifted, with a rotating velocity field
BodyFrame deformed(const BodyFrame& base, Real amount) {
  BodyFrame b = base;
  for (int v = 0; v < b.vertex_count(); ++v) {
    const Vec3 p = base.positions.col(v);
    b.positions.col(v) = Vec3(p.x() * (1 + amount) + amount * p.y(), p.y() * (1 - 0.5f * amount), p.z()) +
                         Vec3(0.02f, -0.01f, 0.03f) * amount;
    b.velocities.col(v) = Vec3(-p.z(), 0.1f, p.x()) * amount;
  }
  b.normals = angle_weighted_normals(b.positions, b.triangles);
  b.moving = true;
  return b;
}

using test::run;

std::vector<std::string> object_space_names() {
  std::vector<std::string> names;
  for (const auto& n : available_colliders())
    if (n == "fcl" || n == "embree") names.push_back(n);
  return names;
}

class ObjectSpace : public ::testing::TestWithParam<std::string> {};

TEST_P(ObjectSpace, RefitEqualsRebuild) {
  const BodyFrame base = make_sphere_body(Vec3(0, 1, 0), 0.2f, 24, 48);
  auto refit = make_collider(GetParam());
  refit->set_body(base);
  // two refits: to a deformed frame, then to a second one
  for (const Real amount : {0.3f, -0.2f}) {
    const BodyFrame moved = deformed(base, amount);
    refit->update_body(moved);
    auto rebuilt = make_collider(GetParam());
    rebuilt->set_body(moved);
    const Points3 points = test::surface_points(moved, 3000, 7);
    const test::ContactDiff d = test::compare_contacts(run(*refit, points), run(*rebuilt, points));
    SCOPED_TRACE("amount " + std::to_string(amount) + ": " + test::describe(d));
    EXPECT_EQ(d.hit_mismatch, 0u);
    EXPECT_LE(d.depth_max, 1e-6);
    // exact distance ties between two faces (the sphere is symmetric) may resolve to either
    // face in another tree: same depth, interpolated normal a few hundredths of a degree apart
    EXPECT_LE(d.normal_max, 0.1);
    EXPECT_LE(d.velocity_max, 0.01);
  }
  EXPECT_EQ(refit->stats().updates, 2);
}

TEST_P(ObjectSpace, BadBodiesThrowClearErrors) {
  auto c = make_collider(GetParam());
  const BodyFrame good = make_sphere_body(Vec3::Zero(), 0.1f, 6, 12);
  auto expect_message = [&](const BodyFrame& body, const std::string& part) {
    try {
      c->set_body(body);
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
  // update before set_body, then with another topology
  EXPECT_THROW(c->update_body(good), std::invalid_argument);
  c->set_body(good);
  EXPECT_THROW(c->update_body(make_sphere_body(Vec3::Zero(), 0.1f, 7, 12)), std::invalid_argument);
}

TEST_P(ObjectSpace, NonFinitePointsAreDegenerate) {
  auto c = make_collider(GetParam());
  c->set_body(make_sphere_body(Vec3::Zero(), 0.1f));
  Points3 p(3, 4);
  p.col(0) = Vec3(0, 0, 0.099f);
  p.col(1) = Vec3(std::numeric_limits<Real>::quiet_NaN(), 0, 0);
  p.col(2) = Vec3(0, std::numeric_limits<Real>::infinity(), 0);
  p.col(3) = Vec3(0, 0, 0.2f);
  const auto out = run(*c, p);
  EXPECT_TRUE(out[0].hit);
  EXPECT_FALSE(out[1].hit);
  EXPECT_FALSE(out[2].hit);
  EXPECT_FALSE(out[3].hit);
  EXPECT_EQ(c->stats().degenerate, 2);
  EXPECT_EQ(c->stats().hits, 1);
  EXPECT_EQ(c->stats().points, 4);
}

TEST_P(ObjectSpace, DegenerateTrianglesDoNotBreakAnswers) {
  // zero-area triangles: a repeated vertex and three collinear vertices (an edge's midpoint)
  BodyFrame body = make_sphere_body(Vec3::Zero(), 0.15f, 12, 24);
  const int a = body.triangles(0, 40), b = body.triangles(1, 40), nv = body.vertex_count();
  body.positions.conservativeResize(3, nv + 1);
  body.positions.col(nv) = 0.5f * (body.positions.col(a) + body.positions.col(b));
  const Eigen::Index nt = body.triangles.cols();
  body.triangles.conservativeResize(3, nt + 2);
  body.triangles.col(nt) << a, a, b;
  body.triangles.col(nt + 1) << a, nv, b;
  finish_static_body(body);
  auto c = make_collider(GetParam());
  c->set_body(body);
  BruteForceCollider brute;
  brute.set_body(body);
  const Points3 points = test::surface_points(body, 2000, 11);
  const auto got = run(*c, points);
  for (const Contact& k : got) ASSERT_FALSE(std::isnan(k.depth));
  const test::ContactDiff d = test::compare_contacts(got, run(brute, points));
  EXPECT_GE(d.hit_agreement(), 0.999) << test::describe(d);
  EXPECT_EQ(c->stats().degenerate, 0);
}

TEST_P(ObjectSpace, SearchRadiusBoundsOutsideNotInside) {
  ColliderOptions options;
  options.search_radius = 0.05f;
  options.coherent = false;  // the search from scratch
  auto c = make_collider(GetParam(), options);
  const BodyFrame body = make_sphere_body(Vec3::Zero(), 0.3f);
  c->set_body(body);
  BruteForceCollider brute(options);
  brute.set_body(body);
  // far outside, near outside, inside deeper than the search radius (the centre)
  Points3 p(3, 3);
  p.col(0) = Vec3(1.0f, 0.2f, 0);
  p.col(1) = Vec3(0, 0.31f, 0);
  p.col(2) = Vec3(0.01f, 0, 0.02f);
  const auto got = run(*c, p), ref = run(brute, p);
  EXPECT_FALSE(got[0].hit);
  EXPECT_EQ(got[0].depth, options.search_radius);
  EXPECT_FALSE(got[1].hit);
  EXPECT_NEAR(got[1].depth, ref[1].depth, 1e-6);
  EXPECT_TRUE(got[2].hit);
  EXPECT_LT(got[2].depth, -0.25f);
  EXPECT_NEAR(got[2].depth, ref[2].depth, 1e-6);
}

// Temporal coherence carries bounds, never answers: a cloud moving a few mm per query, some
// points jumping through the body, the body moving every fifth query, answered exactly as a
// search from scratch answers it, with fewer searches.
TEST_P(ObjectSpace, CoherentAnswersEqualSearchesFromScratch) {
  const BodyFrame base = make_sphere_body(Vec3(0, 1, 0), 0.2f, 24, 48);
  ColliderOptions scratch_options;
  scratch_options.coherent = false;
  auto coherent = make_collider(GetParam()), scratch = make_collider(GetParam(), scratch_options);
  coherent->set_body(base);
  scratch->set_body(base);
  Points3 points = test::surface_points(base, 2000, 5);
  std::mt19937 rng(9);
  std::normal_distribution<Real> step(0, 0.002f);
  for (int q = 0; q < 40; ++q) {
    if (q % 5 == 4) {
      const BodyFrame moved = deformed(base, 0.005f * Real(q));
      coherent->update_body(moved);
      scratch->update_body(moved);
    }
    for (Eigen::Index i = 0; i < points.cols(); ++i) points.col(i) += Vec3(step(rng), step(rng), step(rng));
    for (Eigen::Index i = q; i < points.cols(); i += 97) points.col(i) = Vec3(0, 2, 0) - points.col(i);  // through
    const auto got = run(*coherent, points), ref = run(*scratch, points);
    for (std::size_t i = 0; i < got.size(); ++i) {
      ASSERT_EQ(got[i].hit, ref[i].hit) << "query " << q << ", point " << i << " at depth " << ref[i].depth;
      if (got[i].hit) {
        ASSERT_NEAR(got[i].depth, ref[i].depth, 1e-6) << "query " << q << ", point " << i;
        // near-ties between triangles may pick the other one: 0.1 degree
        ASSERT_LT((got[i].normal - ref[i].normal).norm(), 1.75e-3f) << "query " << q << ", point " << i;
      } else {
        ASSERT_GE(got[i].depth, ColliderOptions{}.tol) << "query " << q << ", point " << i;
      }
    }
  }
  EXPECT_LT(coherent->stats().searches, scratch->stats().searches / 2)
      << coherent->stats().searches << " searches against " << scratch->stats().searches;
}

INSTANTIATE_TEST_SUITE_P(Colliders, ObjectSpace, ::testing::ValuesIn(object_space_names()),
                         [](const auto& info) { return info.param; });

}  // namespace
}  // namespace clothbench
