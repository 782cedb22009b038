// The strain-limiter family (sim/src/limiters/): every member on three cases at the papers' clock (dt 5 ms, equal
// masses, springs as soft as that dt allows, so the limiter alone holds the stretch): a square hanging from its
// top edge, a strip held at both ends with free cloth between (the slow case for a Gauss-Seidel sweep), and a
// sleeve on a swinging arm.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

#include "clothbench/sim/brute_collider.hpp"
#include "clothbench/sim/limiter.hpp"
#include "clothbench/sim/simulator.hpp"

namespace clothbench {
namespace {

constexpr Real kThreshold = 0.10f;

SolverParams papers_clock(const std::string& limit, int passes, Regime regime = Regime::kPapers,
                          Real threshold = kThreshold) {
  Material unused;
  SolverParams p;
  apply_regime(regime, unused, p);
  p.limit = limit;
  p.limit_passes = passes;
  p.threshold = threshold;
  return p;
}

Material papers_material(Regime regime = Regime::kPapers) {
  Material m;
  SolverParams unused;
  apply_regime(regime, m, unused);
  return m;
}

// the largest structural strain over the last half of `seconds`, sampled every 5 steps; nullopt if diverged
std::optional<Real> worst_strain(Simulator& sim, Real seconds) {
  const int steps = static_cast<int>(std::lround(seconds / sim.dt()));
  Real worst = 0;
  for (int i = 0; i < steps && sim.step(); ++i)
    if (2 * i >= steps && i % 5 == 0) worst = std::max(worst, sim.strain().max);
  if (sim.divergence()) return std::nullopt;
  return worst;
}

// binds the attached vertices to a far-away sphere, which never moves: they stay where they are
void pin(Simulator& sim) { sim.attach(make_sphere_body(Vec3(0, 50, 0), 0.1f, 4, 8)); }

// a 0.6 m square of 21 x 21 points hanging in a vertical plane from its top edge
std::optional<Real> hanging_square(const std::string& limit, int passes) {
  const int n = 21;
  ClothMesh c = make_grid_cloth(n, n, 0.6f / Real(n - 1), Vec3(-0.3f, 1, 0), Vec3::UnitX(), -Vec3::UnitY());
  for (int i = 0; i < n; ++i) c.attached.push_back(i);
  Simulator sim(c, papers_material(), papers_clock(limit, passes));
  pin(sim);
  return worst_strain(sim, 2);
}

// a 1 m x 0.2 m strip held at both short ends, sagging between them: the weight of the middle hangs from two
// fronts 40 springs apart
std::optional<Real> held_fronts(const std::string& limit, int passes, Regime regime = Regime::kPapers,
                                Real threshold = kThreshold) {
  const int nx = 41, ny = 9;
  ClothMesh c = make_grid_cloth(nx, ny, 1.0f / Real(nx - 1), Vec3(-0.5f, 1, -0.1f), Vec3::UnitX(), Vec3::UnitZ());
  for (int j = 0; j < ny; ++j) c.attached.push_back(j * nx), c.attached.push_back(j * nx + nx - 1);
  Simulator sim(c, papers_material(regime), papers_clock(limit, passes, regime, threshold));
  pin(sim);
  return worst_strain(sim, 2);
}

// a capsule arm (r 4 cm, 30 cm) hanging from a shoulder pivot and swinging +-30 degrees once a second, in an open
// sleeve (300 degrees round it, 6 cm from its axis) whose top row is attached to it; the worst frame's strain
// over the second swing, 30 frames a second
std::optional<Real> swinging_sleeve(const std::string& limit, int passes) {
  const Vec3 pivot(0, 1.4f, 0);
  const BodyFrame rest = make_capsule_body(pivot - Vec3(0, 0.19f, 0), 0.04f, 0.30f, 8, 24);
  const int nu = 26, nv = 13;  // round the arm, down it
  ClothMesh c = make_grid_cloth(nu, nv, 0.02f, Vec3::Zero(), Vec3::UnitX(), -Vec3::UnitY());
  const Real turn = Real(300.0 / 360.0 * 2 * M_PI), radius = 0.06f;
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const Real a = turn * Real(i) / Real(nu - 1);
      c.positions.col(j * nu + i) = pivot + Vec3(radius * std::sin(a), -0.06f - 0.02f * Real(j), radius * std::cos(a));
    }
  for (int i = 0; i < nu; ++i) c.attached.push_back(i);
  // the rest lengths are the flat grid's; wrapped at 6 cm the rows' springs are chords of 2 cm arcs (0.2 % short)
  SolverParams p = papers_clock(limit, passes);
  Simulator sim(c, papers_material(), p);
  BruteForceCollider arm;
  BodyFrame body = rest;
  const auto pose = [&](double t) {
    const Real angle = Real(0.5 * std::sin(2 * M_PI * t)), omega = Real(0.5 * 2 * M_PI * std::cos(2 * M_PI * t));
    const Eigen::AngleAxis<Real> r(angle, Vec3::UnitZ());
    for (int v = 0; v < rest.vertex_count(); ++v) {
      const Vec3 arm_vector = r * (rest.positions.col(v) - pivot);
      body.positions.col(v) = pivot + arm_vector;
      body.velocities.col(v) = Vec3(0, 0, omega).cross(arm_vector);
    }
    body.normals = angle_weighted_normals(body.positions, body.triangles);
    body.moving = true;
    body.time_s = t;
  };
  pose(0);
  arm.set_body(body);
  sim.set_collider(&arm);
  sim.attach(body);
  const double frame = 1.0 / 30;
  const int per_frame = static_cast<int>(std::ceil(frame / double(sim.dt()) - 1e-9));
  Real worst = 0;
  for (int f = 1; f <= 60 && !sim.divergence(); ++f) {
    pose(f * frame);
    arm.update_body(body);
    sim.follow_attachments(body);
    for (int i = 0; i < per_frame && sim.step(); ++i) {
    }
    if (f > 30) worst = std::max(worst, sim.strain().max);
  }
  if (sim.divergence()) return std::nullopt;
  return worst;
}

std::string show(const std::optional<Real>& s) { return s ? std::to_string(*s) : std::string("diverged"); }

TEST(Limiters, RegistryNamesEveryMemberOnceAndRejectsOthers) {
  const auto names = limiter_names();
  for (const char* name : {"none", "stiff", "position", "velocity-zero", "velocity", "directional",
                           "directional-literal", "tethers", "follow", "projection", "impulses"})
    EXPECT_EQ(std::count(names.begin(), names.end(), name), 1) << name;
  EXPECT_EQ(names.size(), limiter_registry().size());
  try {
    check_limiter("rubber");
    FAIL() << "an unknown limiter was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("tethers"), std::string::npos) << e.what();  // names the accepted ones
  }
  for (const LimiterInfo& l : limiter_registry()) EXPECT_TRUE(make_limiter(l.name, {}) != nullptr) << l.name;
}

// walking section 3.2 as stated, on one over-stretched spring at a time: across v_dir (gravity here) both ends take
// their average (Eq. 5); along it the rear end takes the front one's; only once a step; an attached end never moves
TEST(Limiters, DirectionalLiteralAppliesTheRulesAsStated) {
  ClothMesh c;
  c.positions.resize(3, 2);
  c.springs.resize(2, 1);
  c.springs << 0, 1;
  c.rest_length = Scalars::Constant(1, 1);
  Points3 x(3, 2), v(3, 2);
  const Scalars m = Scalars::Constant(2, 1);
  Scalars inv_m = Scalars::Constant(2, 1);
  const std::vector<Contact> contacts;
  const std::vector<std::vector<int>> merged;
  LimitState s{c, x, v, m, inv_m, contacts, merged, Vec3(0, -9.81f, 0), 0.005f};
  const auto limit = make_limiter("directional-literal", {});
  // horizontal, 1.2 long, ends moving apart along it: both to their mean, the normal parts kept
  x << 0, 1.2f, 0, 0, 0, 0;
  v << -1, 3, 0.5f, 0, 0, 0;
  limit->limit_velocities(s, false);
  EXPECT_FLOAT_EQ(v(0, 0), 1);
  EXPECT_FLOAT_EQ(v(0, 1), 1);
  EXPECT_FLOAT_EQ(v(1, 0), 0.5f);
  // vertical, p2 below p1 (p12 along gravity, cos alpha > 0): the rear point p1 takes p2's velocity along it
  x << 0, 0, 0, -1.2f, 0, 0;
  v << 0, 0, 0, -2, 0, 0;
  limit->limit_velocities(s, true);  // the call after the response: the paper has none
  EXPECT_FLOAT_EQ(v(1, 0), 0);
  limit->limit_velocities(s, false);
  EXPECT_FLOAT_EQ(v(1, 0), -2);
  EXPECT_FLOAT_EQ(v(1, 1), -2);
  // the same with p1 attached: its velocity is the body's, the spring is left to the next step
  v << 0, 0, 0, -2, 0, 0;
  inv_m[0] = 0;
  limit->limit_velocities(s, false);
  EXPECT_FLOAT_EQ(v(1, 0), 0);
  EXPECT_FLOAT_EQ(v(1, 1), -2);
  // within the threshold: nothing changes
  inv_m[0] = 1;
  x << 0, 1.05f, 0, 0, 0, 0;
  v << -1, 3, 0, 0, 0, 0;
  limit->limit_velocities(s, false);
  EXPECT_FLOAT_EQ(v(0, 0), -1);
  EXPECT_FLOAT_EQ(v(0, 1), 3);
}

TEST(Limiters, HangingSquare) {
  const auto none = hanging_square("none", 1);
  std::printf("[ hanging ] none %s\n", show(none).c_str());
  ASSERT_TRUE(none.has_value());
  EXPECT_GT(*none, 0.3f);  // the papers' soft springs alone stretch far past the threshold
  for (const char* limit : {"velocity", "directional", "tethers", "follow", "projection", "impulses"})
    for (int passes : {1, 32}) {
      const auto s = hanging_square(limit, passes);
      std::printf("[ hanging ] %s, %d passes: %s\n", limit, passes, show(s).c_str());
      ASSERT_TRUE(s.has_value()) << limit;
      // a sweep from the held edge with more passes, or a method that carries the weight to the support in one
      // pass (directional's held rear point, the tethers, follow the leader), holds it within threshold + 1 %; so
      // do the projection's Newton iterations, but not its first alone (linearised about a sheet that every
      // spring's stretch has turned)
      // (nor the impulses' first pass: at this clock a pass that stops stretching leaves the step's fall to the next)
      const bool one_pass_holds =
          std::string(limit) != "velocity" && std::string(limit) != "projection" && std::string(limit) != "impulses";
      if (passes > 1 || one_pass_holds) {
        EXPECT_LE(*s, kThreshold + 0.01f) << limit << " " << passes;
      }
    }
  // one pass of Eq. 5 hands half of each correction back: the weight is not carried to the edge
  EXPECT_GT(*hanging_square("velocity", 1), kThreshold + 0.01f);
  EXPECT_GT(*hanging_square("projection", 1), kThreshold + 0.01f);
}

TEST(Limiters, TwoHeldFrontsWithFreeClothBetween) {
  for (const char* limit : {"velocity", "directional", "tethers", "follow", "projection", "impulses"})
    for (int passes : {1, 32}) {
      const auto s = held_fronts(limit, passes);
      std::printf("[ fronts  ] %s, %d passes: %s\n", limit, passes, show(s).c_str());
      ASSERT_TRUE(s.has_value()) << limit;
      // one pass leaves the strip stretched past the limit; 32 of the sweep with Eq. 5 hold it
      if (passes == 1) {
        EXPECT_GT(*s, kThreshold + 0.01f) << limit;
      } else if (std::string(limit) != "follow") {
        EXPECT_LE(*s, kThreshold + 0.01f) << limit;
      }
    }
}

// the projection's passes are Newton iterations over the whole strip: a few hold what the sweeps need 32 passes for
TEST(Limiters, ProjectionHoldsTheHeldFrontsInAFewIterations) {
  const auto eight = held_fronts("projection", 8), sweep = held_fronts("velocity", 8);
  std::printf("[ fronts  ] projection, 8 iterations: %s; velocity, 8 passes: %s\n", show(eight).c_str(),
              show(sweep).c_str());
  ASSERT_TRUE(eight.has_value() && sweep.has_value());
  EXPECT_LE(*eight, kThreshold + 0.01f);
  EXPECT_GT(*sweep, kThreshold + 0.01f);
}

// our stable regime's stiff springs, the strip held taut at a 1 % threshold: the impulses carried over from the last
// step must not wind up against the springs (at full weight they diverged here)
TEST(Limiters, ImpulsesHoldATautStripInTheStableRegime) {
  constexpr Real kTight = 0.01f;
  for (const char* limit : {"velocity", "impulses"})
    for (int passes : {1, 2}) {
      const auto s = held_fronts(limit, passes, Regime::kStable, kTight);
      std::printf("[ taut    ] %s, %d passes: %s\n", limit, passes, show(s).c_str());
      ASSERT_TRUE(s.has_value()) << limit << " " << passes;
      EXPECT_LE(*s, kTight + 0.01f) << limit << " " << passes;
    }
}

// one quad, a square of 0.1 m in the plane y = 0, whose midpoint (not its corners) the body below touches
struct QuadOnTheBody {
  ClothMesh c;
  Points3 x{3, 4}, v{3, 4};
  Scalars m = Scalars::Constant(4, 0.01f), inv_m = Scalars::Constant(4, 100);
  std::vector<Contact> contacts = std::vector<Contact>(5);  // the four vertices, then the quad's midpoint
  QuadOnTheBody() {
    c.positions.resize(3, 4);
    c.springs.resize(2, 4);
    c.springs << 0, 1, 2, 3, 1, 2, 3, 0;
    c.kind.assign(4, SpringKind::kStructural);
    c.rest_length = Scalars::Constant(4, 0.1f);
    c.quads.resize(4, 1);
    c.quads << 0, 1, 2, 3;
    x << 0, 0.1f, 0.1f, 0, 0, 0, 0, 0, 0, 0, 0.1f, 0.1f;
    contacts[4].hit = true;
    contacts[4].normal = Vec3(0, 1, 0);
  }
  LimitState state(const std::vector<std::vector<int>>& merged) {
    return {c, x, v, m, inv_m, contacts, merged, Vec3(0, -9.81f, 0), 0.001f};
  }
};

// with face queries the body's contacts are quad midpoints too (dressing section 6): `impulses` stops a midpoint's
// motion into the body although none of its corners touches, with one push shared by the corners
TEST(Limiters, ImpulsesStopAQuadMidpointMovingIntoTheBody) {
  QuadOnTheBody q;
  Points3& v = q.v;
  const std::vector<std::vector<int>> merged;
  LimitState s = q.state(merged);
  const auto down = [&] {
    v.setZero();
    v.row(1).setConstant(-1);  // every corner down, into the body below the midpoint
    v(0, 0) = -0.5f;           // and one sideways, which the body does not stop
  };
  for (bool after_response : {false, true}) {
    const auto limit = make_limiter("impulses", {0.1f, 4});
    down();
    limit->limit_velocities(s, false);                             // the step's first call gathers the contacts
    if (after_response) down(), limit->limit_velocities(s, true);  // the call after the response goes on with them
    EXPECT_NEAR(v.row(1).mean(), 0, 1e-5f) << after_response;      // the midpoint no longer moves into the body
    EXPECT_FLOAT_EQ(v(0, 0), -0.5f) << after_response;
    for (int k = 1; k < 4; ++k) EXPECT_FLOAT_EQ(v(1, k), v(1, 0)) << after_response;  // one push, a quarter each
  }
  q.contacts[4].hit = false;  // no contact: nothing stops the corners
  v.setZero();
  v.row(1).setConstant(-1);
  make_limiter("impulses", {0.1f, 4})->limit_velocities(s, false);
  EXPECT_FLOAT_EQ(v.row(1).mean(), -1);
}

// the sweeps stop the motion into the body after the response (their second call) of a quad midpoint in contact
// too, as of a vertex: one push, a quarter to each corner, sewn corners moving as one point
TEST(Limiters, SweepsStopAQuadMidpointMovingIntoTheBodyAfterTheResponse) {
  QuadOnTheBody q;
  Points3& v = q.v;
  for (const char* name : {"velocity", "directional", "velocity-zero"})
    for (const std::vector<std::vector<int>>& merged : {std::vector<std::vector<int>>{}, {{0, 3}}}) {
      LimitState s = q.state(merged);
      v.setZero();
      v.row(1) << -1, -2, -1, -1;  // every corner into the body below the midpoint
      v(2, 1) = 0.5f;              // and one along it, which the body does not stop
      make_limiter(name, {0.1f, 4})->limit_velocities(s, true);
      EXPECT_NEAR(v.row(1).mean(), 0, 1e-5f) << name << " sewn " << merged.size();  // the midpoint stopped
      EXPECT_FLOAT_EQ(v(2, 1), 0.5f) << name;
      EXPECT_FLOAT_EQ(v(1, 0), v(1, 3)) << name;          // the sewn corners as one point (and alike when not sewn)
      EXPECT_NEAR(v(1, 1) - v(1, 2), -1, 1e-5f) << name;  // the same push to each corner of equal mass
    }
}

TEST(Limiters, SleeveOnASwingingArm) {
  for (const char* limit : {"velocity", "directional", "tethers", "follow", "projection", "impulses"})
    for (int passes : {1, 32}) {
      const auto s = swinging_sleeve(limit, passes);
      std::printf("[ sleeve  ] %s, %d passes: %s\n", limit, passes, show(s).c_str());
      ASSERT_TRUE(s.has_value()) << limit;
      if (passes == 32 && std::string(limit) != "follow") {
        EXPECT_LE(*s, kThreshold + 0.01f) << limit;
      }
    }
}

}  // namespace
}  // namespace clothbench
