#include "clothbench/sim/simulator.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

#include "clothbench/sim/sphere_collider.hpp"
#include "test_support.hpp"
#include "two_particles.hpp"

namespace clothbench {
namespace {


// a horizontal square cloth of n x n vertices, `size` metres wide, pinned at its two far corners
ClothMesh pinned_square(int n, Real size) {
  ClothMesh c = make_grid_cloth(n, n, size / Real(n - 1), Vec3(-size / 2, 1, -size / 2), Vec3::UnitX(), Vec3::UnitZ());
  c.attached = {0, n - 1};
  return c;
}

// pins the cloth's `attached` vertices where they are (bound to a small body far away that never moves)
void pin(Simulator& sim) { sim.attach(make_sphere_body(Vec3(0, 50, 0), 0.1f, 4, 8)); }

// damping per unit mass: 7.41/s is the 0.001 N s/m these tests used per vertex, at the 0.135 g vertex of the
// hanging square (3 cm cells)
Material soft_material() {
  Material m;
  m.damping = 7.41f;
  return m;
}

// the cloth's surface: a quad as two triangles, a triangle cell (corner 2 repeated as 3) as one
TEST(ClothMesh, SurfaceTrianglesSplitQuadsAndKeepTriangleCellsWhole) {
  ClothMesh c = make_grid_cloth(2, 2, 0.1f, Vec3::Zero(), Vec3::UnitX(), Vec3::UnitY());
  ASSERT_EQ(c.quads.cols(), 1);
  c.quads.conservativeResize(4, 2);
  c.quads.col(1) << 0, 1, 3, 3;
  const Tris t = c.surface_triangles();
  ASSERT_EQ(t.cols(), 3);
  EXPECT_EQ(t.col(0), c.quads.col(0).head<3>());
  EXPECT_EQ(t.col(1), Eigen::Vector3i(c.quads(0, 0), c.quads(2, 0), c.quads(3, 0)).cast<std::int32_t>());
  EXPECT_EQ(t.col(2), Eigen::Vector3i(0, 1, 3).cast<std::int32_t>());
}

TEST(Simulator, TwoParticleSpringPeriodMatchesTheory) {
  Material mat;
  mat.density = 0.01f;  // 10 g per particle
  mat.k_structural = 4;
  mat.damping = 0;
  SolverParams p;
  p.gravity = Vec3::Zero();
  p.limit = "none";
  p.dt = 1e-4f;
  Simulator sim(test::two_particles(0.1f, 0.01f), mat, p);
  // relative coordinate oscillates with omega = sqrt(2k/m)
  const double omega = std::sqrt(2 * 4 / 0.01), period = 2 * M_PI / omega;
  std::vector<double> up_crossings;
  double prev = 0.01;
  for (int i = 0; i < 20000; ++i) {
    sim.step();
    const double ext = (sim.positions().col(1) - sim.positions().col(0)).norm() - 0.1;
    if (prev < 0 && ext >= 0) up_crossings.push_back(i * 1e-4);
    prev = ext;
  }
  ASSERT_GE(up_crossings.size(), 3u);
  const double measured = (up_crossings.back() - up_crossings.front()) / double(up_crossings.size() - 1);
  EXPECT_NEAR(measured, period, 0.01 * period) << "theory " << period << " s";
}

// explicit Euler on the pinned square under gravity at `dt_multiple` x the smaller of Eq. 4's and Gershgorin's
// bounds; true when it did not diverge
bool runs_stably(Real dt_multiple, int steps) {
  SolverParams p;
  p.limit = "none";
  p.allow_unstable_dt = true;
  Simulator probe(pinned_square(15, 0.5f), soft_material(), p);
  p.dt = dt_multiple * std::min(probe.stable_dt(), probe.spectral_dt());
  Simulator sim(pinned_square(15, 0.5f), soft_material(), p);
  pin(sim);
  for (int i = 0; i < steps && sim.step();) ++i;
  return !sim.divergence().has_value();
}

// two free particles, the second `ratio` times lighter, sewn together across `gap` [m]
ClothMesh seam_pair(Real gap, Real ratio) {
  ClothMesh c = test::two_particles(gap, 0);
  c.vertex_area << 1, 1 / ratio;
  c.springs.resize(2, 0);
  c.rest_length.resize(0);
  c.kind.clear();
  c.seam_pairs.resize(2, 1);
  c.seam_pairs << 0, 1;
  return c;
}

SolverParams seam_params() {
  SolverParams p;
  p.limit = "none";
  p.seam_reach = 0.05f;
  p.seam_speed = 100;  // no speed cap here
  p.merge_distance = 1e-7f;
  p.dt = 1e-5f;  // a fine step, so the measured closing time is the seam's, not the integrator's
  p.masses = MassModel::kArea;  // the partners' masses as their areas: unequal
  return p;
}

double reduced_mass(double a, double b) { return a * b / (a + b); }

TEST(Simulator, AutomaticSeamIsAsStiffAsTheStructuralSprings) {
  // a zero-length spring of k = k_structural closes a pair from rest in a quarter period,
  // (pi / 2) sqrt(mu / k), whatever the partners' masses
  Material mat;
  mat.damping = 0;
  for (Real ratio : {1.f, 100.f}) {
    Simulator sim(seam_pair(0.01f, ratio), mat, seam_params());
    sim.set_phase(Phase::kSew);
    long it = 0;
    while ((sim.positions().col(1) - sim.positions().col(0)).x() > 0 && it < 1000000 && sim.step()) ++it;
    const double quarter =
        M_PI / 2 * std::sqrt(reduced_mass(sim.masses()[0], sim.masses()[1]) / double(mat.k_structural));
    EXPECT_NEAR(double(it) * sim.dt(), quarter, 0.02 * quarter) << "mass ratio " << ratio;
  }
}

TEST(Simulator, SeamsBeyondTheirReachPullNoHarder) {
  // 50 cm apart: the light end's speed after one step is k seam_reach dt / m, not 10 times that
  Material mat;
  mat.damping = 0;
  const SolverParams p = seam_params();
  Simulator sim(seam_pair(0.5f, 100), mat, p);
  sim.set_phase(Phase::kSew);
  ASSERT_TRUE(sim.step());
  const double expected = mat.k_structural * p.seam_reach * sim.dt() / sim.masses()[1];
  EXPECT_NEAR(sim.velocities().col(1).norm(), expected, 1e-3 * expected);
}

TEST(Simulator, SeamsCloseNoFasterThanTheirSpeed) {
  // 30 cm apart with the default seam, one end 100 times lighter: the partners approach at
  // seam_speed (2 m/s), not at the sqrt(2 k reach d / mu) ~ 11 m/s an uncapped pull would reach, and meet
  Material mat;
  mat.damping = 0;
  SolverParams p;
  p.limit = "none";
  p.merge_distance = 1e-4f;
  Simulator sim(seam_pair(0.3f, 100), mat, p);
  sim.set_phase(Phase::kSew);
  double fastest = 0;
  for (int i = 0; i < 20000 && sim.seam_gap_max() > 1e-3f && sim.step(); ++i)
    fastest = std::max(fastest, double((sim.velocities().col(1) - sim.velocities().col(0)).norm()));
  EXPECT_LT(sim.seam_gap_max(), 1e-3f);
  EXPECT_LT(fastest, 1.1 * p.seam_speed);
  EXPECT_GT(fastest, 0.9 * p.seam_speed);
}

TEST(Simulator, TheSeamGapSeesAVertexWithoutAPartnerOffItsPartnerEdge) {
  // panel A's edge 0-1-2 sewn to panel B's edge 3-4: pairs (0, 3) and (2, 4), vertex 1 without a partner, its
  // stretch of partner edge 3-4; the pairs closed and vertex 1 bulging 5 mm off that stretch
  ClothMesh c = test::two_particles(0.01f, 0);
  c.positions.resize(3, 5);
  c.positions << 0, 0.01f, 0.02f, 0, 0.02f,  //
      0, 0.005f, 0, 0, 0,                    //
      0, 0, 0, 0, 0;
  c.vertex_area = Scalars::Constant(5, 1e-4f);
  c.springs.resize(2, 0);
  c.rest_length.resize(0);
  c.kind.clear();
  c.panel = {0, 0, 0, 1, 1};
  c.panel_names = {"a", "b"};
  c.seam_pairs.resize(2, 2);
  c.seam_pairs << 0, 2, 3, 4;
  c.seam_loose.resize(3, 1);
  c.seam_loose << 1, 3, 4;
  Simulator sim(c, Material{}, SolverParams{});
  EXPECT_NEAR(sim.seam_pair_gap_max(), 0, 1e-7);
  EXPECT_NEAR(sim.seam_gap_max(), 0.005, 1e-6);
  const SeamGap w = sim.widest_seam_gap();
  EXPECT_TRUE(w.loose);
  EXPECT_EQ(w.vertex, 1);
  EXPECT_TRUE(w.partner == 3 || w.partner == 4);
  // on its stretch of partner edge, anywhere along it, the seam is closed
  sim.positions().col(1) = Vec3(0.013f, 0, 0);
  EXPECT_NEAR(sim.seam_gap_max(), 0, 1e-7);
  // a pair apart by more is the widest
  sim.positions().col(4) = Vec3(0.02f, 0, 0.008f);
  EXPECT_FALSE(sim.widest_seam_gap().loose);
  EXPECT_NEAR(sim.seam_gap_max(), 0.008, 1e-6);
}

TEST(ClothMesh, RejectsASeamVertexWithoutAPartnerOutOfRange) {
  ClothMesh c = test::two_particles(0.01f, 0);
  c.seam_loose.resize(3, 1);
  c.seam_loose << 0, 1, 2;
  EXPECT_THROW(c.validate("test"), std::invalid_argument);
}

TEST(Simulator, SeamsMeetingAtOnePointMoveAsOne) {
  // a sleeve, a front and a back meet at the armpit: pairs (0, 1) and (2, 1) chain, and once merged the
  // three vertices are one point with the mass-weighted mean velocity (momentum kept). Merging the pairs
  // one after the other left vertex 0 behind, pulled apart again every step, at metres per second
  ClothMesh c = test::two_particles(0.001f, 0);
  c.positions.conservativeResize(3, 3);
  c.positions.col(2) = Vec3(0.0015f, 0, 0);
  c.vertex_area.resize(3);
  c.vertex_area << 1, 0.25f, 2;
  c.springs.resize(2, 0);
  c.rest_length.resize(0);
  c.kind.clear();
  c.seam_pairs.resize(2, 2);
  c.seam_pairs << 0, 2, 1, 1;
  c.panel = {0, 1, 2};
  Material mat;
  mat.damping = 0;
  SolverParams p = seam_params();
  p.gravity = Vec3::Zero();
  p.merge_distance = 0.002f;
  Simulator merging(c, mat, p);
  merging.velocities().col(0) = Vec3(1, 0, 0);
  merging.velocities().col(2) = Vec3(0, -2, 0);
  const Vec3 momentum = merging.velocities() * merging.masses();
  for (int i = 0; i < 3; ++i) ASSERT_TRUE(merging.step());
  EXPECT_EQ(merging.sewn_fraction(), 1);
  for (int v : {0, 2}) {
    EXPECT_LT((merging.positions().col(v) - merging.positions().col(1)).norm(), 1e-7f) << "vertex " << v;
    EXPECT_LT((merging.velocities().col(v) - merging.velocities().col(1)).norm(), 1e-6f) << "vertex " << v;
  }
  EXPECT_LT((merging.velocities() * merging.masses() - momentum).norm(), 1e-6f * momentum.norm());
}

TEST(Simulator, LimitsShortenAnOverStretchedSpringAtLimitSpeed) {
  // a spring already 50 % long (pinched by the body, or a seam merged across it) is shortened at
  // limit_speed, not by all of its excess in one step (0.04 m / dt = 400 m/s, a speed that outlives the
  // step and diverged a walking dress); with limit_speed 0 only its own force shortens it
  for (const char* limit : {"velocity", "directional"}) {
    for (Real limit_speed : {0.f, 2.f}) {
      Material mat;
      mat.damping = 0;
      SolverParams p;
      p.gravity = Vec3::Zero();
      p.limit = limit;
      p.limit_speed = limit_speed;
      p.dt = 1e-4f;
      Simulator sim(test::two_particles(0.1f, 0.05f), mat, p);
      ASSERT_TRUE(sim.step());
      const double spring_only = mat.k_structural * 0.05 * sim.dt() * 2 / sim.masses()[0];
      const double closing = (sim.velocities().col(0) - sim.velocities().col(1)).x();
      const double expected = std::max(spring_only, double(limit_speed));
      EXPECT_NEAR(closing, expected, 1e-3 * expected) << limit << ", limit_speed " << limit_speed;
    }
  }
}

TEST(Simulator, TheDirectionalLimitSeesGravityOnlyWhenItActs) {
  // walking Eq. 6's v_grav = g dt is the velocity gravity adds in the step: none while sewing (gravity off),
  // where, against a static body, the directional rule has no direction and averages as Eq. 5 does
  // (taking the scene's g there made the papers' dress pull one panel across the body and never sew)
  const auto after_one_step = [](const char* limit, Phase phase) {
    Material mat;
    mat.damping = 0;
    mat.k_structural = 1e-3f;  // the limit, not the spring, decides
    SolverParams p;
    p.limit = limit;
    p.dt = 0.01f;
    ClothMesh c = test::two_particles(0.1f, 0);
    c.positions.col(1) = Vec3(0, -0.1f, 0);  // b hangs below a
    Simulator sim(c, mat, p);
    sim.set_phase(phase);
    sim.velocities().col(0) = Vec3(0, 0.5f, 0);  // a rises, b falls: the spring would end 25 % long
    sim.velocities().col(1) = Vec3(0, -1.0f, 0);
    EXPECT_TRUE(sim.step());
    return Points3(sim.velocities());
  };
  const Points3 averaged = after_one_step("velocity", Phase::kSew);
  EXPECT_LT((after_one_step("directional", Phase::kSew) - averaged).norm(), 1e-5f);
  // with gravity on the rear (upper) point catches up with the front one instead
  const Points3 falling = after_one_step("directional", Phase::kDrape);
  EXPECT_GT((falling - after_one_step("velocity", Phase::kDrape)).norm(), 0.1f);
  EXPECT_LT(falling(1, 0), 0.f);  // the upper point now moves down with the lower one
}

// with equal masses a vertex's many springs make Gershgorin's bound the smaller one: Eq. 4 takes a single spring
TEST(Simulator, EulerStableBelowTheBoundAndUnstableWellAbove) {
  EXPECT_TRUE(runs_stably(0.95f, 3000));
  EXPECT_FALSE(runs_stably(3.0f, 3000));
}

// a chain of `n` equal masses along x joined by structural springs, each stretched by 1 %
ClothMesh chain(int n) {
  ClothMesh c;
  c.positions.resize(3, n);
  for (int i = 0; i < n; ++i) c.positions.col(i) = Vec3(0.0101f * Real(i), 0, 0);
  c.vertex_area = Scalars::Constant(n, 1e-4f);
  c.springs.resize(2, n - 1);
  for (int i = 0; i + 1 < n; ++i) c.springs.col(i) << i, i + 1;
  c.rest_length = Scalars::Constant(n - 1, 0.01f);
  c.kind.assign(std::size_t(n - 1), SpringKind::kStructural);
  c.quads.resize(4, 0);
  c.seam_pairs.resize(2, 0);
  c.panel.assign(std::size_t(n), 0);
  c.panel_names = {"chain"};
  return c;
}

// Eq. 4 looks at one spring; a mass between two springs needs about half of it (found on this
// chain), so the automatic dt also respects the Gershgorin bound and stays stable
TEST(Simulator, AutomaticDtRespectsTheGershgorinBound) {
  SolverParams p;
  p.limit = "none";
  p.gravity = Vec3::Zero();
  Simulator sim(chain(6), soft_material(), p);
  EXPECT_LT(sim.spectral_dt(), sim.stable_dt());
  EXPECT_LE(sim.dt(), 0.9f * sim.spectral_dt() * 1.0001f);
  for (int i = 0; i < 20000 && sim.step(); ++i) {
  }
  EXPECT_FALSE(sim.divergence().has_value());
  // and at 0.9 x the Eq. 4 bound alone the same chain diverges
  SolverParams q = p;
  q.dt = 0.9f * sim.stable_dt();
  Simulator eq4(chain(6), soft_material(), q);
  for (int i = 0; i < 20000 && eq4.step(); ++i) {
  }
  EXPECT_TRUE(eq4.divergence().has_value());
}

TEST(Simulator, DtAboveTheBoundIsRejectedUnlessAllowed) {
  SolverParams p;
  Simulator probe(pinned_square(5, 0.2f), soft_material(), p);
  p.dt = 2 * probe.stable_dt();
  EXPECT_THROW(Simulator(pinned_square(5, 0.2f), soft_material(), p), std::invalid_argument);
  p.allow_unstable_dt = true;
  EXPECT_NO_THROW(Simulator(pinned_square(5, 0.2f), soft_material(), p));
}

TEST(Simulator, InvalidParametersNameTheParameter) {
  auto message = [](auto mutate) {
    Material m;
    SolverParams p;
    mutate(m, p);
    try {
      Simulator(pinned_square(5, 0.2f), m, p);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message([](Material& m, SolverParams&) { m.density = -1; }).find("density"), std::string::npos);
  EXPECT_NE(message([](Material& m, SolverParams&) { m.k_shear = -1; }).find("k_shear"), std::string::npos);
  EXPECT_NE(message([](Material& m, SolverParams&) { m.k_shear = 0; }).find("dt"), std::string::npos);  // automatic
  EXPECT_NE(message([](Material& m, SolverParams&) { m.damping = std::nanf(""); }).find("damping"), std::string::npos);
  EXPECT_NE(message([](Material&, SolverParams& p) { p.threshold = 1.5f; }).find("threshold"), std::string::npos);
  EXPECT_NE(message([](Material&, SolverParams& p) { p.threshold = -0.1f; }).find("threshold"), std::string::npos);
  EXPECT_THROW(check_limiter("rubber"), std::invalid_argument);
  EXPECT_THROW(parse_seam_method("glue"), std::invalid_argument);
}

// max structural strain of a soft square hanging in a vertical plane from its two top corners
// (a global stretch: the whole weight hangs from two points), the largest over the second half of
// `seconds` (after the first swing), sampled every 10 iterations; nullopt if diverged
std::optional<Real> hanging_strain(const std::string& limit, int passes, Real seconds = 2.0f) {
  const int n = 21;
  const Real size = 0.6f;
  ClothMesh c = make_grid_cloth(n, n, size / Real(n - 1), Vec3(-size / 2, 1, 0), Vec3::UnitX(), -Vec3::UnitY());
  c.attached = {0, n - 1};
  Material m = soft_material();
  m.k_structural = 5;  // soft springs: the plain model visibly stretches under its own weight
  m.k_shear = 2;
  m.k_flexion = 1;
  SolverParams p;
  p.limit = limit;
  p.threshold = 0.10f;
  p.limit_passes = passes;
  p.dt_fraction = 0.5f;
  Simulator sim(c, m, p);
  pin(sim);
  const int steps = static_cast<int>(seconds / sim.dt());
  Real strain = 0;
  for (int i = 0; i < steps && sim.step(); ++i)
    if (2 * i >= steps && i % 10 == 0) strain = std::max(strain, sim.strain().max);  // sampled: strain() sorts
  if (sim.divergence()) return std::nullopt;
  return strain;
}

std::string show(const std::optional<Real>& s) { return s ? std::to_string(*s) : std::string("diverged"); }

TEST(Simulator, VelocityLimitsHoldStrainWhereNoneStretches) {
  const auto none = hanging_strain("none", 1);
  const auto velocity = hanging_strain("velocity", 100);
  const auto zero = hanging_strain("velocity-zero", 100);
  const auto directional = hanging_strain("directional", 100);
  // the papers' single pass per iteration, reported (see the issue note: it leaks under a sustained load)
  const auto velocity1 = hanging_strain("velocity", 1);
  const auto zero1 = hanging_strain("velocity-zero", 1);
  const auto directional1 = hanging_strain("directional", 1);
  std::printf(
      "[ strain  ] threshold 0.10: none %s | 100 passes: velocity %s velocity-zero %s directional %s | "
      "1 pass: velocity %s velocity-zero %s directional %s\n",
      show(none).c_str(), show(velocity).c_str(), show(zero).c_str(), show(directional).c_str(),
      show(velocity1).c_str(), show(zero1).c_str(), show(directional1).c_str());
  ASSERT_TRUE(none && velocity && zero && directional && directional1);
  EXPECT_GT(*none, 0.5f);  // far beyond the 10 % threshold
  // within threshold + 1 %
  EXPECT_LE(*velocity, 0.11f);
  EXPECT_LE(*zero, 0.11f);
  EXPECT_LE(*directional, 0.11f);
}

// a 15 x 15 tablecloth, 1 m a side, dropped 5 cm above a sphere (r 0.25 m) that after 1 s moves along +x at
// 1 m/s for 1 s (walking Fig. 8, small); max structural strain at the end, nullopt if diverged
std::optional<Real> moving_sphere_strain(const std::string& limit) {
  ClothMesh cloth = make_grid_cloth(15, 15, 1.0f / 14, Vec3(-0.5f, 0.8f, -0.5f), Vec3::UnitX(), Vec3::UnitZ());
  SolverParams p;
  p.limit = limit;
  p.threshold = 0.05f;
  Material m = soft_material();
  m.k_structural = 5;
  m.k_shear = 2;
  m.k_flexion = 1;
  m.damping = 2.61f;  // per unit mass: 0.002 N s/m at the 0.77 g vertex of this cloth
  Simulator sim(cloth, m, p);
  SphereCollider sphere(Vec3(0, 0.5f, 0), 0.25f);
  sim.set_collider(&sphere);
  const int drape = static_cast<int>(1.0f / sim.dt());
  for (int i = 0; i < drape && sim.step(); ++i) {
  }
  // 60 frames per second, the sphere moved once per frame as the scene runner does
  const Real frame_dt = 1.0f / 60;
  const int per_frame = static_cast<int>(std::ceil(frame_dt / sim.dt()));
  for (int f = 1; f <= 60 && !sim.divergence(); ++f) {
    sphere.set_sphere(Vec3(Real(f) * frame_dt, 0.5f, 0), Vec3::UnitX());
    for (int i = 0; i < per_frame && sim.step(); ++i) {
    }
  }
  if (sim.divergence()) return std::nullopt;
  return sim.strain().max;
}

TEST(Simulator, DirectionalLimitHoldsOnAMovingSphere) {
  // the literal rear-takes-front rule diverged here during the drape; the energy guard keeps it stable
  const auto none = moving_sphere_strain("none");
  const auto velocity = moving_sphere_strain("velocity");
  const auto directional = moving_sphere_strain("directional");
  std::printf("[ strain  ] moving sphere, threshold 0.05: none %s velocity %s directional %s\n", show(none).c_str(),
              show(velocity).c_str(), show(directional).c_str());
  ASSERT_TRUE(none && directional);
  EXPECT_LT(*directional, *none);
  EXPECT_LT(*directional, 0.10f);  // within twice the threshold (one pass per iteration)
}

TEST(Simulator, PositionVersusVelocityOnGlobalStretch) {
  // dressing 4.2-4.3 claim velocity modification beats Provot on a global stretch; both are
  // measured here with the same number of passes and reported (the claims experiment reads them)
  for (int passes : {1, 30}) {
    const auto position = hanging_strain("position", passes);
    const auto velocity = hanging_strain("velocity", passes);
    std::printf("[ strain  ] global stretch, %d passes: position (Provot) %s, velocity %s\n", passes,
                show(position).c_str(), show(velocity).c_str());
    ASSERT_TRUE(position.has_value());
    EXPECT_LT(*position, *hanging_strain("none", 1));  // Provot limits the stretch
  }
}

TEST(Simulator, StiffLimitShrinksTheTimeStep) {
  SolverParams p;
  Simulator plain(pinned_square(5, 0.2f), soft_material(), p);
  p.limit = "stiff";
  p.stiff_factor = 16;
  Simulator stiff(pinned_square(5, 0.2f), soft_material(), p);
  EXPECT_NEAR(stiff.dt() / plain.dt(), 0.25, 1e-5);  // Eq. 4: dt ~ 1/sqrt(K)
}

TEST(CollisionResponse, HandComputedEq15) {
  Contact c;
  c.hit = true;
  c.normal = Vec3(0, 1, 0);
  // static body: v = (2, -3, 0) -> v_t = (2, 0, 0), v_n = (0, -3, 0)
  EXPECT_TRUE(test::near_vec(collision_response(Vec3(2, -3, 0), c, 0.5f, 0.2f), Vec3(1, 0.6f, 0), 1e-6));
  // moving body (walking Eq. 15): relative to v_object = (0, 1, 1)
  c.body_velocity = Vec3(0, 1, 1);
  // v_rel = (2, -4, -1): v_t = (2, 0, -1), v_n = (0, -4, 0) -> 0.5 v_t + 0.8 + v_obj
  EXPECT_TRUE(test::near_vec(collision_response(Vec3(2, -3, 0), c, 0.5f, 0.2f), Vec3(1, 1.8f, 0.5f), 1e-6));
  // a point leaving the body keeps its normal component
  c.body_velocity = Vec3::Zero();
  EXPECT_TRUE(test::near_vec(collision_response(Vec3(0, 2, 0), c, 0.5f, 0.2f), Vec3(0, 2, 0), 1e-6));
}

TEST(StretchRules, DirectionalRulePicksRearPointBySignOfCos) {
  // cos > 0: p1 is the rear point and takes p2's component
  auto [a1, b1] = directional_stretch(-3, 1, 0.9f, 1, 1, 0, false);
  EXPECT_FLOAT_EQ(a1, 1);
  EXPECT_FLOAT_EQ(b1, 1);
  // cos < 0: p2 is the rear point
  auto [a2, b2] = directional_stretch(-1, 3, -0.9f, 1, 1, 0, false);
  EXPECT_FLOAT_EQ(a2, -1);
  EXPECT_FLOAT_EQ(b2, -1);
  auto [a3, b3] = directional_stretch(-1, 3, 0.2f, 1, 1, 0, false);  // perpendicular: Eq. 5
  EXPECT_FLOAT_EQ(a3, 1);
  EXPECT_FLOAT_EQ(b3, 1);
}

TEST(StretchRules, TheLiteralDirectionalRuleCatchesUpWhateverTheEnergy) {
  // walking Eq. 6 as stated: p1 (rear) takes p2's 3, where ours averages to 1
  auto [a1, b1] = directional_stretch(-1, 3, 0.9f, 1, 1, 0, true);
  EXPECT_FLOAT_EQ(a1, 3);
  EXPECT_FLOAT_EQ(b1, 3);
  auto [a2, b2] = directional_stretch(-1, 3, 0.2f, 1, 1, 0, true);  // perpendicular: Eq. 5
  EXPECT_FLOAT_EQ(a2, 1);
  EXPECT_FLOAT_EQ(b2, 1);
  EXPECT_NO_THROW(check_limiter("directional-literal"));
}

TEST(StretchRules, CatchingUpNeverAddsKineticEnergy) {
  // p1 catching up with p2 (3) would raise 1 + 9 to 9 + 9: Eq. 5 instead
  auto [a1, b1] = directional_stretch(-1, 3, 0.9f, 1, 1, 0, false);
  EXPECT_FLOAT_EQ(a1, 1);
  EXPECT_FLOAT_EQ(b1, 1);
  // a target relative velocity is kept by both rules: the rear point ends `target` behind the front
  auto [a2, b2] = directional_stretch(-3, 1, 0.9f, 1, 1, -0.5f, false);
  EXPECT_FLOAT_EQ(a2, 1.5f);
  EXPECT_FLOAT_EQ(b2, 1);
  // mass-weighted Eq. 5 keeps momentum with the target: 2 (-1) + 1 (3) = 1 = 2 a + b, b - a = 0.3
  auto [a3, b3] = average_stretch(-1, 3, 2, 1, 0.3f);
  EXPECT_NEAR(2 * a3 + b3, 1, 1e-6);
  EXPECT_NEAR(b3 - a3, 0.3f, 1e-6);
}

TEST(Simulator, VelocityLimitEndsATurningSpringAtItsLimit) {
  // a spring turning so fast that its perpendicular motion alone would stretch it past the limit in one step:
  // split along its end-of-step line, the limit ends the step at exactly (1 + threshold) l0, with no more
  // closing speed than that needs (along the start line no speed could, and the old split asked for 20 m/s)
  for (const char* limit : {"velocity", "directional"}) {
    Material mat;
    mat.damping = 0;
    mat.k_structural = mat.k_shear = mat.k_flexion = 1e-6f;
    SolverParams p;
    p.gravity = Vec3::Zero();
    p.limit = limit;
    p.dt = 0.005f;
    Simulator sim(test::two_particles(0.1f, 0), mat, p);
    sim.velocities().col(1) = Vec3(0, 30, 0);  // 15 cm sideways in one step
    ASSERT_TRUE(sim.step());
    const Vec3 d = sim.positions().col(1) - sim.positions().col(0);
    EXPECT_NEAR(d.norm(), 0.11, 1e-4) << limit;
    EXPECT_LT(sim.velocities().norm(), 30.0f) << limit << ": the limit added speed";
  }
}

TEST(Simulator, OnePassOfTheLimitHoldsAChainFromItsSupport) {
  // a hanging chain of 30 soft springs listed from the bottom up (the worst order for one sweep): the limit
  // sweeps from the held top down, so one pass per iteration of the directional limit (walking Eq. 6: the rear
  // point follows a held one) holds it within threshold + 1 %; averaging (Eq. 5) gives half back at each link
  const int n = 31;
  ClothMesh c;
  c.positions.resize(3, n);
  c.springs.resize(2, n - 1);
  for (int i = 0; i < n; ++i) c.positions.col(i) = Vec3(0, 1 - 0.02f * Real(i), 0);
  for (int s = 0; s < n - 1; ++s) c.springs.col(s) << n - 2 - s, n - 1 - s;
  c.vertex_area = Scalars::Constant(n, 1e-4f);
  c.rest_length = Scalars::Constant(n - 1, 0.02f);
  c.kind.assign(static_cast<std::size_t>(n - 1), SpringKind::kStructural);
  c.quads.resize(4, 0);
  c.seam_pairs.resize(2, 0);
  c.panel.assign(static_cast<std::size_t>(n), 0);
  c.panel_names = {"chain"};
  c.attached = {0};
  Real strain[2] = {};
  for (const char* limit : {"velocity", "directional"}) {
    Material m;
    m.k_structural = 0.01f;  // 30 springs of this would stretch 150 % under the chain's weight
    SolverParams p;
    p.limit = limit;
    p.limit_passes = 1;
    p.dt = 0.005f;
    Simulator sim(c, m, p);
    pin(sim);
    for (int i = 0; i < 400 && sim.step(); ++i) {
    }
    ASSERT_FALSE(sim.divergence().has_value()) << sim.divergence()->reason;
    strain[std::string(limit) == "directional"] = sim.strain().max;
  }
  std::printf("[ chain   ] one pass: velocity %.3f, directional %.4f\n", strain[0], strain[1]);
  EXPECT_LE(strain[1], 0.11f);
  EXPECT_GT(strain[0], 0.2f);
}

// a sphere's centre and radius [m], and two attached points 2 mm and 40 mm off it
const Vec3 kCentre(0, 1, 0);
const Real kRadius = 0.1f;
ClothMesh two_points_off_a_sphere() {
  ClothMesh c = test::two_particles(0.05f, 0);
  c.positions.col(0) = kCentre + Vec3(kRadius + 0.002f, 0, 0);
  c.positions.col(1) = kCentre + Vec3(0, 0, kRadius + 0.04f);
  c.attached = {0, 1};
  return c;
}

TEST(Simulator, AttachedPointsTurnWithTheBody) {
  // Durupinar 3.2: two attached points, one 2 mm and one 40 mm off a sphere, bound to it; the sphere turned a
  // quarter turn about its centre and moved: each point is where the same rigid motion takes it, so the
  // cloth between them is neither stretched nor shortened (an offset that kept its direction in the world
  // would leave the far point behind and the spring 40 mm x sqrt(2) longer or shorter)
  const ClothMesh c = two_points_off_a_sphere();
  Simulator sim(c, Material{}, SolverParams{});
  const BodyFrame body = make_sphere_body(kCentre, kRadius, 16, 32);
  sim.attach(body);
  const Eigen::AngleAxis<Real> turn(Real(M_PI / 2), Vec3::UnitY());
  const Vec3 shift(0.3f, 0, 0);
  BodyFrame turned = body;
  for (int v = 0; v < body.vertex_count(); ++v)
    turned.positions.col(v) = kCentre + shift + turn * (body.positions.col(v) - kCentre);
  sim.follow_attachments(turned);
  for (int k = 0; k < 2; ++k) {
    const Vec3 expected = kCentre + shift + turn * (c.positions.col(k) - kCentre);
    EXPECT_LT((sim.positions().col(k) - expected).norm(), 1e-5f) << "attached point " << k;
  }
}

TEST(Simulator, AnAttachedPointBeyondReachIsLeftFree) {
  // of two attached points, 2 mm and 40 mm off a sphere, with a reach of 10 mm only the near one is bound: it stays
  // put under gravity while the far one falls (bound, it would hold the cloth in mid-air)
  const ClothMesh c = two_points_off_a_sphere();
  Material m;
  m.k_structural = m.k_shear = m.k_flexion = 1e-6f;
  SolverParams p;
  p.limit = "none";
  p.dt = 0.005f;
  Simulator sim(c, m, p);
  EXPECT_EQ(sim.attach(make_sphere_body(kCentre, kRadius, 16, 32), 0.01f), 1);
  EXPECT_EQ(sim.attachment_offsets().cols(), 1);
  for (int i = 0; i < 20; ++i) ASSERT_TRUE(sim.step());
  EXPECT_LT((sim.positions().col(0) - c.positions.col(0)).norm(), 1e-6f);
  EXPECT_LT(sim.positions()(1, 1), c.positions(1, 1) - 0.01f);
}

TEST(Simulator, AStalledSewingMergesPairsWithinTwiceTheMergeDistance) {
  // a seam pair 4 mm apart, beyond merge_distance (3 mm), with nothing pulling it: a step leaves it open; a stalled
  // sewing's merge joins it into one point at its middle, but not at 6.5 mm, beyond twice merge_distance
  for (const Real gap : {0.004f, 0.0065f}) {
    ClothMesh c = test::two_particles(gap, 0);
    c.seam_pairs.resize(2, 1);
    c.seam_pairs << 0, 1;
    Material m;
    m.k_structural = m.k_shear = m.k_flexion = 1e-6f;
    SolverParams p;
    p.limit = "none";
    p.gravity = Vec3::Zero();
    p.seam_stiffness = 1e-6f;
    p.dt = 0.001f;
    Simulator sim(c, m, p);
    ASSERT_TRUE(sim.step());
    EXPECT_EQ(sim.sewn_fraction(), 0) << gap;
    const bool near = gap < 2 * p.merge_distance;
    EXPECT_EQ(sim.merge_stalled_seams(), near ? 1 : 0) << gap;
    EXPECT_NEAR((sim.positions().col(0) - sim.positions().col(1)).norm(), near ? 0 : gap, 1e-6f) << gap;
  }
}

TEST(Simulator, APointInsideTheBodyIsBroughtToItsSurface) {
  // Durupinar Eq. 3: a vertex 2 cm inside a sphere is moved out along the normal at push_speed (2 m/s: 1 cm per
  // 5 ms step), and is on the surface after the second step; without push_out it stays inside
  for (bool push_out : {true, false}) {
    Material m;
    m.damping = 0;
    m.k_structural = m.k_shear = m.k_flexion = 1e-6f;
    SolverParams p;
    p.limit = "none";
    p.push_out = push_out;
    p.dt = 0.005f;
    ClothMesh c = test::two_particles(0.1f, 0);
    c.positions.col(0) = Vec3(0, 0.98f, 0);
    c.positions.col(1) = Vec3(0.1f, 1.5f, 0);
    c.rest_length[0] = (c.positions.col(1) - c.positions.col(0)).norm();
    Simulator sim(c, m, p);
    SphereCollider sphere(Vec3::Zero(), 1.0f);
    sim.set_collider(&sphere);
    sim.set_phase(Phase::kSew);  // no gravity
    ASSERT_TRUE(sim.step());
    const Real first = sim.positions().col(0).norm() - 1;
    ASSERT_TRUE(sim.step());
    const Real second = sim.positions().col(0).norm() - 1;
    if (push_out) {
      EXPECT_NEAR(first, -0.01, 1e-4);
      EXPECT_NEAR(second, 0, 1e-4);
    } else {
      EXPECT_LT(second, -0.019f);
    }
  }
}

TEST(Simulator, SewnPointsMoveAsOneThroughTheLimit) {
  // two panels sewn at one pair: the merged point keeps one velocity through the limit's passes, so the limit
  // acting on one panel's spring is not undone by the averaging at the seam
  ClothMesh c;
  c.positions.resize(3, 4);
  c.positions << 0, 0.1f, 0.1f, 0.2f, 0, 0, 0, 0, 0, 0, 0, 0;
  c.vertex_area = Scalars::Constant(4, 1);
  c.springs.resize(2, 2);
  c.springs << 0, 2, 1, 3;
  c.rest_length = Scalars::Constant(2, 0.1f);
  c.kind = {SpringKind::kStructural, SpringKind::kStructural};
  c.quads.resize(4, 0);
  c.seam_pairs.resize(2, 1);
  c.seam_pairs << 1, 2;
  c.panel = {0, 0, 1, 1};
  c.panel_names = {"left", "right"};
  Material m;
  m.damping = 0;
  m.k_structural = m.k_shear = m.k_flexion = 1e-6f;
  SolverParams p;
  p.gravity = Vec3::Zero();
  p.limit_passes = 4;
  p.dt = 0.005f;
  Simulator sim(c, m, p);
  ASSERT_TRUE(sim.step());  // the pair (coincident) merges
  ASSERT_EQ(sim.sewn_fraction(), 1);
  sim.velocities().col(0) = Vec3(-2, 0, 0);  // the left end pulls away
  sim.velocities().col(3) = Vec3(2, 0, 0);   // and the right one
  for (int i = 0; i < 3; ++i) ASSERT_TRUE(sim.step());
  EXPECT_EQ(sim.velocities().col(1), sim.velocities().col(2));
  EXPECT_LE(sim.strain().max, 0.101f);
}

TEST(Simulator, FaceQueryResponseKeepsTheVerticesRelativeMotion) {
  // one 20 cm quad over the top of a 1 m sphere: its midpoint is 1 mm above the surface (a contact),
  // its corners 2 cm (none). The midpoint's response changes the quad's common motion only: two
  // corners sliding towards each other keep closing.
  Material m;
  m.k_structural = m.k_shear = m.k_flexion = 1e-6f;
  m.damping = 0;
  ClothMesh quad = make_grid_cloth(2, 2, 0.2f, Vec3(-0.1f, 1.001f, -0.1f), Vec3::UnitX(), Vec3::UnitZ());
  SolverParams p;
  p.limit = "none";
  p.face_queries = true;
  p.dt = 1e-5f;
  Simulator sim(quad, m, p);
  SphereCollider sphere(Vec3::Zero(), 1.0f);
  sim.set_collider(&sphere);
  sim.set_phase(Phase::kSew);  // no gravity
  sim.velocities().col(0) = Vec3(1, -0.1f, 0);
  sim.velocities().col(1) = Vec3(-1, -0.1f, 0);
  sim.velocities().col(2) = Vec3(0, -0.1f, 0);
  sim.velocities().col(3) = Vec3(0, -0.1f, 0);
  ASSERT_TRUE(sim.step());
  EXPECT_NEAR(sim.velocities()(0, 1) - sim.velocities()(0, 0), -2.0, 1e-4);  // still closing at 2 m/s
  for (int v = 0; v < 4; ++v) EXPECT_GE(sim.velocities()(1, v), -1e-6) << "vertex " << v << " still heading in";
}

TEST(Simulator, ClothDroppedOnSphereRestsOutsideIt) {
  ClothMesh cloth = make_grid_cloth(25, 25, 0.03f, Vec3(-0.36f, 0.45f, -0.36f), Vec3::UnitX(), Vec3::UnitZ());
  SolverParams p;
  Material m = soft_material();
  m.damping = 37.f;  // per unit mass: 0.005 N s/m at the 0.135 g vertex of this cloth
  Simulator sim(cloth, m, p);
  ColliderOptions opt;
  SphereCollider sphere(Vec3(0, 0, 0), 0.3f, opt);
  sim.set_collider(&sphere);
  const int steps = static_cast<int>(3.0f / sim.dt());
  for (int i = 0; i < steps && sim.step(); ++i) {
  }
  ASSERT_FALSE(sim.divergence().has_value()) << sim.divergence()->reason;
  Real deepest = 0;
  for (int v = 0; v < sim.positions().cols(); ++v)
    deepest = std::min(deepest, Real(sim.positions().col(v).norm() - 0.3f));
  EXPECT_GT(deepest, -opt.tol) << "a vertex is deeper than tol";
  EXPECT_GT(sphere.stats().hits, 0);  // it did land on the sphere
}

TEST(Simulator, DivergenceIsReportedWithIterationPhaseAndVertex) {
  SolverParams p;
  Simulator sim(pinned_square(5, 0.2f), soft_material(), p);
  sim.velocities()(1, 7) = std::nanf("");
  EXPECT_FALSE(sim.step());
  ASSERT_TRUE(sim.divergence().has_value());
  EXPECT_EQ(sim.divergence()->iteration, 1);
  EXPECT_GE(sim.divergence()->vertex, 0);
  EXPECT_FALSE(sim.step());  // stays stopped
}

// two free particles without springs, the second `ratio` times lighter
ClothMesh free_pair(Real ratio) {
  ClothMesh c = seam_pair(0.1f, ratio);
  c.seam_pairs.resize(2, 0);
  return c;
}

TEST(Simulator, DampingPerUnitMassGivesLightAndHeavyOneTerminalVelocity) {
  Material m;
  m.damping = 5;  // [1/s]: terminal speed g / c
  SolverParams p;
  p.limit = "none";
  p.dt = 1e-3f;
  p.masses = MassModel::kArea;
  Simulator sim(free_pair(100), m, p);
  ASSERT_NEAR(sim.masses()[0] / sim.masses()[1], 100, 1e-3);
  for (int i = 0; i < 4000 && sim.step(); ++i) {
  }
  const Real terminal = -kGravity / m.damping;
  EXPECT_NEAR(sim.velocities()(1, 0), terminal, 1e-4 * std::abs(terminal));  // heavy
  EXPECT_NEAR(sim.velocities()(1, 1), terminal, 1e-4 * std::abs(terminal));  // 100 x lighter
}

TEST(Simulator, EqualMassesSumToTheTotalMass) {
  Material m;
  m.density = 0.2f;
  ClothMesh cloth = pinned_square(7, 0.3f);
  cloth.attached.clear();
  const Real total = m.density * cloth.vertex_area.sum();
  ASSERT_GT(cloth.vertex_area.maxCoeff(), 3 * cloth.vertex_area.minCoeff());  // corners carry a quarter cell
  SolverParams p;
  p.masses = MassModel::kArea;
  Simulator area(cloth, m, p);
  for (int v = 0; v < cloth.vertex_area.size(); ++v) EXPECT_FLOAT_EQ(area.masses()[v], m.density * cloth.vertex_area[v]);
  p.masses = MassModel::kEqual;
  Simulator equal(cloth, m, p);
  EXPECT_NEAR(equal.masses().sum(), total, 1e-5 * total);
  EXPECT_FLOAT_EQ(equal.masses().minCoeff(), equal.masses().maxCoeff());
  // Eq. 4 takes the lightest point: equal masses admit a larger step than area masses
  EXPECT_GT(equal.stable_dt(), area.stable_dt());
}

TEST(Simulator, StableRegimeIsTheDefaults) {
  Material m, defaults;
  SolverParams p, solver_defaults;
  apply_regime(Regime::kPapers, m, p);
  apply_regime(Regime::kStable, m, p);
  EXPECT_EQ(p.regime, Regime::kStable);
  EXPECT_EQ(p.masses, solver_defaults.masses);
  EXPECT_EQ(p.dt, solver_defaults.dt);
  EXPECT_EQ(m.k_structural, defaults.k_structural);
  EXPECT_EQ(m.k_shear, defaults.k_shear);
  EXPECT_EQ(m.k_flexion, defaults.k_flexion);
  EXPECT_EQ(parse_regime("papers"), Regime::kPapers);
  EXPECT_THROW(parse_regime("fast"), std::invalid_argument);
  EXPECT_THROW(parse_mass_model("heavy"), std::invalid_argument);
}

// the papers' regime on the hanging square of VelocityLimitsHoldStrainWhereNoneStretches: dt 5 ms, soft automatic
// springs that Eq. 4 and Gershgorin admit, the directional limit (four passes, from the pinned corners out) holding
// the stretch
// limit_tolerance: a pass's change that moves a point less than it over the step wakes no spring, so the passes stop
// sooner; the hanging square at the papers' clock keeps its strain within threshold + 1 % either way
TEST(Simulator, LimitToleranceEndsThePassesSooner) {
  const int n = 21;
  const Real size = 0.6f;
  const auto run = [&](Real tolerance) {
    ClothMesh c = make_grid_cloth(n, n, size / Real(n - 1), Vec3(-size / 2, 1, 0), Vec3::UnitX(), -Vec3::UnitY());
    c.attached = {0, n - 1};
    Material m;
    SolverParams p;
    apply_regime(Regime::kPapers, m, p);
    p.limit_tolerance = tolerance;
    Simulator sim(c, m, p);
    pin(sim);
    Real strain = 0;
    for (int i = 0; i < 400 && sim.step(); ++i)
      if (i >= 200 && i % 10 == 0) strain = std::max(strain, sim.strain().max);
    EXPECT_FALSE(sim.divergence());
    return std::pair{sim.timings().limit_passes, strain};
  };
  const auto [exact_passes, exact_strain] = run(0);
  const auto [passes, strain] = run(Real(5e-5));
  std::printf(
      "[ passes  ] hanging square, papers' clock: %ld limit passes (strain %.4f) exact, %ld (strain %.4f) "
      "with 0.05 mm\n",
      exact_passes, double(exact_strain), passes, double(strain));
  EXPECT_LT(double(passes), 0.9 * double(exact_passes));
  EXPECT_LE(exact_strain, 0.11f);
  EXPECT_LE(strain, 0.11f);
}

TEST(Simulator, PapersRegimeIsStableAtItsDtOnTheHangingSquare) {
  const int n = 21;
  const Real size = 0.6f;
  ClothMesh c = make_grid_cloth(n, n, size / Real(n - 1), Vec3(-size / 2, 1, 0), Vec3::UnitX(), -Vec3::UnitY());
  c.attached = {0, n - 1};
  Material m;
  SolverParams p;
  apply_regime(Regime::kPapers, m, p);
  Simulator sim(c, m, p);
  pin(sim);
  EXPECT_FLOAT_EQ(sim.dt(), 0.005f);
  EXPECT_GE(sim.stable_dt(), sim.dt());    // dressing Eq. 4 alone admits it
  EXPECT_GE(sim.spectral_dt(), sim.dt());  // and so does Gershgorin: no shrink needed
  EXPECT_NEAR(sim.stiffness(SpringKind::kShear), sim.stiffness(SpringKind::kStructural) / 3, 1e-5);
  Real strain = 0;
  const int steps = static_cast<int>(4.0f / sim.dt());
  for (int i = 0; i < steps && sim.step(); ++i)
    if (2 * i >= steps) strain = std::max(strain, sim.strain().max);
  ASSERT_FALSE(sim.divergence().has_value()) << sim.divergence()->reason;
  std::printf("[ papers  ] hanging square at dt 5 ms: k %.3f/%.3f/%.3f N/m, strain max %.4f, speed %.4f m/s\n",
              sim.stiffness(SpringKind::kStructural), sim.stiffness(SpringKind::kShear),
              sim.stiffness(SpringKind::kFlexion), strain, sim.max_speed());
  EXPECT_LE(strain, 0.11f);           // the preset's limit carries the stretch: threshold + 1 %
  EXPECT_LT(sim.max_speed(), 0.05f);  // and it comes to rest
  // automatic stiffness scales with the mass per point: 4 x the vertices, about 1/4 the stiffness
  ClothMesh fine = make_grid_cloth(2 * n - 1, 2 * n - 1, size / Real(2 * n - 2), Vec3(-size / 2, 1, 0), Vec3::UnitX(),
                                   -Vec3::UnitY());
  Simulator finer(fine, m, p);
  EXPECT_NEAR(finer.stiffness(SpringKind::kStructural) / sim.stiffness(SpringKind::kStructural),
              Real(n * n) / Real((2 * n - 1) * (2 * n - 1)), 0.02);
  // a key given explicitly overrides the preset's automatic value
  m.k_structural = 0.5f;
  Simulator given(c, m, p);
  EXPECT_FLOAT_EQ(given.stiffness(SpringKind::kStructural), 0.5f);
}

TEST(Simulator, AutomaticStiffnessNeedsAGivenDt) {
  Material m;
  m.k_structural = 0;
  SolverParams p;
  EXPECT_THROW(Simulator(pinned_square(5, 0.2f), m, p), std::invalid_argument);
}

}  // namespace
}  // namespace clothbench
