// Conformance: every collider in the registry against `brute` (exact) on analytic bodies, the
// real body at rest and one walking frame (moving: body velocities compared too).
// The brute reference is computed once per process and case (ctest runs each test alone).
// Object-space colliders must agree exactly (hit/no-hit >= 99.99 %, depth 1e-5 m, normal 1 deg,
// velocity 1 % or 1e-4 m/s). Image-space colliders ("is-*") are skipped here: their looser,
// resolution-dependent tolerance test lives in tests/collide_is.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>

#include "clothbench/io/body_loader.hpp"
#include "clothbench/io/data_root.hpp"
#include "clothbench/sim/brute_collider.hpp"
#include "contact_compare.hpp"
#include "registry.hpp"
#include "surface_points.hpp"

namespace clothbench {
namespace {

// query points per case, 80 % within 3 cm of the surface; fewer on the walking frame, since
// brute's reference costs ~0.45 ms per point on the 26,756-triangle body
constexpr int kPoints = 10000;
constexpr int kWalkPoints = 2000;
constexpr unsigned kSeed = 20010613;

// one test body with its query points and brute's answers (computed once, shared by colliders)
struct Case {
  BodyFrame body;                 // what the collider is asked about
  std::optional<BodyFrame> rest;  // moving cases: set_body(rest) first, then update_body(body)
  Points3 points;
  std::vector<Contact> reference;
};

const std::string kWalkBody = "body/mh_female_walk.glb";

std::optional<Case> make_case(const std::string& name) {
  Case c;
  if (name == "sphere") {
    c.body = make_sphere_body(Vec3(0.1f, 1.2f, -0.05f), 0.15f);
  } else if (name == "capsule") {
    c.body = make_capsule_body(Vec3(0, 1.0f, 0), 0.12f, 0.5f);
  } else {
    const std::string path = data_path(kWalkBody);
    if (!std::filesystem::exists(path)) return std::nullopt;
    const BodyModel model = load_body(path);
    if (name == "body_rest") {
      c.body = model.rest();
    } else {
      c.rest = model.rest();
      c.body = model.frame(model.animation_index("walk_07_01"), 2.0);
    }
  }
  c.points = test::surface_points(c.body, name == "body_walk" ? kWalkPoints : kPoints, kSeed);
  BruteForceCollider brute;
  brute.set_body(c.body);
  c.reference.resize(std::size_t(c.points.cols()));
  brute.query(c.points, {c.reference.data(), c.reference.size()});
  return c;
}

// cases are built on first use and kept for every collider
const std::optional<Case>& get_case(const std::string& name) {
  static std::map<std::string, std::optional<Case>> cache;
  auto it = cache.find(name);
  if (it == cache.end()) it = cache.emplace(name, make_case(name)).first;
  return it->second;
}

using Param = std::tuple<std::string, std::string>;  // collider, body case

class Conformance : public ::testing::TestWithParam<Param> {};

TEST_P(Conformance, AgreesWithBrute) {
  const auto& [collider_name, case_name] = GetParam();
  if (collider_name.rfind("is-", 0) == 0)
    GTEST_SKIP() << collider_name << " is image space: its tolerance test (pixel-sized depth error, "
                 << "silhouettes) lives in tests/collide_is";
  if (collider_name == "brute" && case_name.rfind("body", 0) == 0)
    GTEST_SKIP() << "brute is the reference; it is compared with itself on the analytic bodies only";
  const auto& c = get_case(case_name);
  if (!c) GTEST_SKIP() << "data root absent: " << data_path(kWalkBody) << " not found (set CLOTHBENCH_DATA)";

  // set-up, and for the walking frame a refit from the rest pose
  auto collider = make_collider(collider_name, ColliderOptions{});
  collider->set_body(c->rest ? *c->rest : c->body);
  if (c->rest) collider->update_body(c->body);
  std::vector<Contact> got(c->reference.size());
  collider->query(c->points, {got.data(), got.size()});

  const test::ContactDiff d = test::compare_contacts(got, c->reference);
  SCOPED_TRACE(collider_name + " on " + case_name + ": " + test::describe(d));
  EXPECT_GE(d.hit_agreement(), 0.9999);
  EXPECT_LE(d.depth_max, 1e-5);
  EXPECT_LE(d.normal_max, 1.0);
  EXPECT_LE(d.velocity_max, 1.0);
  EXPECT_EQ(collider->stats().points, c->points.cols());
  EXPECT_EQ(collider->stats().degenerate, 0);
}

std::string param_name(const ::testing::TestParamInfo<Param>& info) {
  std::string s = std::get<0>(info.param) + "_" + std::get<1>(info.param);
  for (char& ch : s)
    if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
  return s;
}

INSTANTIATE_TEST_SUITE_P(AllColliders, Conformance,
                         ::testing::Combine(::testing::ValuesIn(available_colliders()),
                                            ::testing::Values("sphere", "capsule", "body_rest", "body_walk")),
                         param_name);

}  // namespace
}  // namespace clothbench
