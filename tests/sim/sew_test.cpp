#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "clothbench/sim/garment.hpp"
#include "clothbench/sim/simulator.hpp"
#include "clothbench/sim/sphere_collider.hpp"

namespace clothbench {
namespace {

Panel rect(const std::string& name, double w, double h, const Placement& pl) {
  Panel p;
  p.name = name;
  p.outline = {Vec2d(0, 0), Vec2d(w, 0), Vec2d(w, h), Vec2d(0, h)};
  p.edge_begin = {0, 1, 2, 3};
  p.placement = pl;
  return p;
}

// Front panel 10 cm in front of a 15 cm sphere, back panel behind it (yaw 180), sewn at both sides.
Pattern tube() {
  Placement front, back;
  front.anchor = Vec3(0.5f, 0.5f, 1.f);
  front.offset_cm = Vec3(-30, -15, 10);
  back.anchor = Vec3(0.5f, 0.5f, 0.f);
  back.offset_cm = Vec3(30, -15, -10);
  back.yaw_deg = 180;
  Pattern pat;
  pat.name = "tube";
  pat.panels = {rect("front", 60, 30, front), rect("back", 60, 30, back)};
  pat.seams = {{0, 1, 1, 3, true}, {0, 3, 1, 1, true}};
  return pat;
}

void sew(SeamMethod method) {
  const BodyFrame sphere_body = make_sphere_body(Vec3::Zero(), 0.15f);
  MeshingOptions o;
  o.spacing_cm = 3;
  const ClothMesh cloth = build_garment(tube(), o, sphere_body);
  const Real gap0 = (cloth.positions.col(cloth.seam_pairs(0, 0)) - cloth.positions.col(cloth.seam_pairs(1, 0))).norm();
  EXPECT_LT(gap0, 0.55f);  // the sides start 50 cm apart (z), not crossed
  SolverParams p;
  p.seam_method = method;
  p.seam_stiffness = 1.0f;  // [N/m]: soft, so a 50 cm gap does not fling 0.1 g vertices past max_speed
  Simulator sim(cloth, Material{}, p);
  SphereCollider sphere(Vec3::Zero(), 0.15f, ColliderOptions{});
  sim.set_collider(&sphere);
  sim.set_phase(Phase::kSew);
  int it = 0;
  while (it < 20000 && sim.seam_gap_max() >= 0.002f && sim.step()) ++it;
  std::printf("%s: %d vertices, %d seam pairs, gap %.4f m after %d iterations\n", to_string(method),
              cloth.vertex_count(), static_cast<int>(cloth.seam_pairs.cols()), double(sim.seam_gap_max()), it);
  EXPECT_FALSE(sim.divergence().has_value()) << sim.divergence()->reason;
  EXPECT_LT(sim.seam_gap_max(), 0.002f);
}

TEST(GarmentSewing, TubeAroundSphereClosesElastic) { sew(SeamMethod::kElastic); }
TEST(GarmentSewing, TubeAroundSphereClosesAttraction) { sew(SeamMethod::kAttraction); }

// a strap over a shoulder: two 20 x 30 cm panels in front of and behind a 15 cm sphere, sewn along their top
// edges 5 cm above it, then left to hang from that seam
Pattern strap() {
  Placement front, back;
  front.anchor = Vec3(0.5f, 1.f, 1.f);
  front.offset_cm = Vec3(-10, -25, 3);
  back.anchor = Vec3(0.5f, 1.f, 0.f);
  back.offset_cm = Vec3(10, -25, -3);
  back.yaw_deg = 180;
  Pattern pat;
  pat.name = "strap";
  pat.panels = {rect("front", 20, 30, front), rect("back", 20, 30, back)};
  pat.seams = {{0, 2, 1, 2, true}};
  return pat;
}

// sewn and hung by implicit Euler at 10 ms, and by the projective solve at 5 ms, with the stable regime's
// springs: the sewn partners move as one point in the solve too (and the body holds the seam inside it), so the
// seam carries both panels without stretching the springs beside it
void hang_strap(const std::string& integrator) {
  SCOPED_TRACE(integrator);
  const BodyFrame sphere_body = make_sphere_body(Vec3::Zero(), 0.15f);
  MeshingOptions o;
  o.spacing_cm = 2;
  SolverParams p;
  p.integrator = integrator;
  Simulator sim(build_garment(strap(), o, sphere_body), Material{}, p);
  SphereCollider sphere(Vec3::Zero(), 0.15f, ColliderOptions{});
  sim.set_collider(&sphere);
  sim.set_phase(Phase::kSew);
  int it = 0;
  while (it < 300 && sim.seam_gap_max() >= 0.002f && sim.step()) ++it;
  sim.set_phase(Phase::kDrape);
  for (int i = 0; i < std::lround(1 / sim.dt()) && sim.step(); ++i) {
  }
  std::printf("%s: sewn after %d iterations; after 1 s hanging: strain %.3f, gap %.4f m, speed %.3f m/s\n",
              integrator.c_str(), it, sim.strain().max, sim.seam_gap_max(), sim.max_speed());
  ASSERT_FALSE(sim.divergence().has_value()) << sim.divergence()->reason;
  EXPECT_LT(it, 300);
  EXPECT_LT(sim.seam_gap_max(), 0.002f);
  EXPECT_LT(sim.strain().max, 0.11f);  // threshold + 1 %
}

TEST(GarmentSewing, ImplicitSolvesHangAStrapFromItsSeamWithoutStretchingIt) {
  hang_strap("implicit-euler");
  hang_strap("projective");
}

TEST(GarmentSewing, ASewnPointIsItsGroupsFirstMemberAndOutOfRangeMembersAreSkipped) {
  const std::vector<int> point = sewn_point_of(6, {{1, 4}, {5, 2, 9}});
  EXPECT_EQ(point, (std::vector<int>{0, 1, 5, 3, 1, 5}));
}

}  // namespace
}  // namespace clothbench
