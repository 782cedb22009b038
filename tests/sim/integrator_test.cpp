#include "clothbench/sim/integrator.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "clothbench/sim/simulator.hpp"
#include "clothbench/sim/sphere_collider.hpp"
#include "two_particles.hpp"

namespace clothbench {
namespace {

// two free particles of 10 g joined by a 4 N/m spring of rest length 0.1 m, stretched by 1 cm; no gravity,
// damping or limit: the extension oscillates as 0.01 cos(omega t), omega = sqrt(2k/m)
constexpr double kMass = 0.01, kK = 4, kRest = 0.1, kStretch = 0.01;

Simulator two_particles(const std::string& integrator, Real dt, IntegratorParams ip = {}) {
  const ClothMesh c = test::two_particles(Real(kRest), Real(kStretch));
  Material m;
  m.density = Real(kMass);
  m.k_structural = Real(kK);
  m.damping = 0;
  SolverParams p;
  p.gravity = Vec3::Zero();
  p.limit = "none";
  p.dt = dt;
  p.integrator = integrator;
  p.integration = ip;
  return Simulator(c, m, p);
}

double extension(const Simulator& sim) { return (sim.positions().col(1) - sim.positions().col(0)).norm() - kRest; }

// kinetic plus spring energy [J]
double energy(const Simulator& sim) {
  const double e = extension(sim);
  return double(sim.kinetic_energy()) + 0.5 * kK * e * e;
}

double omega() { return std::sqrt(2 * kK / kMass); }

TEST(Integrator, ExplicitEulerRoughlyConservesTheSpringEnergy) {
  Simulator sim = two_particles("explicit-euler", 1e-3f);
  const double e0 = energy(sim);
  double lo = e0, hi = e0;
  for (int i = 0; i < 2000 && sim.step(); ++i) lo = std::min(lo, energy(sim)), hi = std::max(hi, energy(sim));
  // symplectic Euler: the energy oscillates by about (omega dt)/2 and does not drift
  EXPECT_LT((hi - lo) / e0, 0.03) << "lo " << lo << " hi " << hi << " e0 " << e0;
}

// backward Euler (implicit Euler's linearised step, the projective solve's iterations) never gains energy and damps
// the oscillation (omega dt = 0.28)
TEST(Integrator, ImplicitStepsDissipateAndNeverGainEnergy) {
  for (const std::string name : {"implicit-euler", "projective"}) {
    Simulator sim = two_particles(name, 1e-2f);
    const double e0 = energy(sim);
    double prev = e0;
    for (int i = 0; i < 200 && sim.step(); ++i) {
      const double e = energy(sim);
      ASSERT_LE(e, prev * (1 + 1e-4)) << name << " iteration " << i;  // float round-off only
      prev = e;
    }
    EXPECT_LT(prev, 0.5 * e0) << name;
    EXPECT_EQ(std::string(sim.integrator()), name);
  }
  Simulator implicit = two_particles("implicit-euler", 1e-2f);
  for (int i = 0; i < 200 && implicit.step(); ++i) {
  }
  EXPECT_EQ(implicit.integrator_stats().cg_unconverged, 0);
  EXPECT_EQ(implicit.integrator_stats().force_evaluations, 200);  // one per iteration
}

// the projective solve is backward Euler: on a spring that does not turn, its local step's target does not depend
// on the iterate, and one iteration gives the backward-Euler step e1 = (e0 + h v0) / (1 + h^2 omega^2) exactly
TEST(Integrator, ProjectiveGivesTheBackwardEulerStep) {
  for (int iterations : {1, 10}) {
    IntegratorParams ip;
    ip.projective_iterations = iterations;
    Simulator sim = two_particles("projective", 1e-2f, ip);
    ASSERT_TRUE(sim.step());
    const double h = 1e-2, expected = kStretch / (1 + h * h * omega() * omega());
    EXPECT_NEAR(extension(sim), expected, 1e-4 * kStretch) << iterations << " iterations";
    EXPECT_EQ(sim.integrator_stats().cg_iterations, iterations);  // its local/global iterations
  }
}

// |extension - analytic| at t = 1 s, with the sub-steps rk45 took
std::pair<double, long> rk45_error(Real tol_x) {
  IntegratorParams ip;
  ip.rk_tol_x = tol_x;
  ip.rk_tol_v = tol_x * Real(omega());  // the same relative accuracy on velocities
  Simulator sim = two_particles("rk45", 0.1f, ip);  // 0.45 omega^-1 per iteration: the sub-steps decide
  for (int i = 0; i < 10 && sim.step(); ++i) {
  }
  const double t = 10 * double(sim.dt());
  return {std::abs(extension(sim) - kStretch * std::cos(omega() * t)), sim.integrator_stats().force_evaluations};
}

TEST(Integrator, Rk45FollowsTheAnalyticOscillationBetterAtTighterTolerances) {
  const auto loose = rk45_error(1e-3f), mid = rk45_error(1e-5f), tight = rk45_error(1e-7f);
  std::printf("[ rk45    ] error at 1 s: tol 1e-3 %.3g m (%ld evals), 1e-5 %.3g m (%ld), 1e-7 %.3g m (%ld)\n",
              loose.first, loose.second, mid.first, mid.second, tight.first, tight.second);
  EXPECT_LT(mid.first, 1e-4);    // 1 % of the amplitude
  EXPECT_LT(tight.first, 1e-5);  // 0.1 %
  EXPECT_LT(mid.first, loose.first);
  EXPECT_LT(tight.first, mid.first);
  EXPECT_LT(loose.second, mid.second);  // tighter tolerances cost more evaluations
  EXPECT_LT(mid.second, tight.second);
}

TEST(Integrator, UnknownNameIsRejectedNamingTheAcceptedValues) {
  try {
    two_particles("verlet", 1e-3f);
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("'verlet' (explicit-euler, implicit-euler, rk45, projective)"),
              std::string::npos)
        << e.what();
  }
  EXPECT_THROW(check_integrator("rk4"), std::invalid_argument);
  EXPECT_NO_THROW(check_integrator("rk45"));
}

// the hanging square: 21 x 21 vertices, 0.6 m, the stable regime's 60/20/10 N/m springs and equal masses,
// pinned at its two top corners, run for `seconds`
struct Hanging {
  bool diverged = false;
  Real strain = 0, speed = 0, dt = 0, eq4 = 0;
  Points3 x;
};

Hanging hang(const std::string& integrator, Real dt, Real seconds) {
  const int n = 21;
  const Real size = 0.6f;
  ClothMesh c = make_grid_cloth(n, n, size / Real(n - 1), Vec3(-size / 2, 1, 0), Vec3::UnitX(), -Vec3::UnitY());
  c.attached = {0, n - 1};
  SolverParams p;
  p.dt = dt;
  p.integrator = integrator;
  Simulator sim(c, Material{}, p);
  sim.attach(make_sphere_body(Vec3(0, 50, 0), 0.1f, 4, 8));
  const long steps = std::lround(seconds / sim.dt());
  for (long i = 0; i < steps && sim.step(); ++i) {
  }
  Hanging h;
  h.diverged = sim.divergence().has_value();
  h.strain = sim.strain().max;
  h.speed = sim.max_speed();
  h.dt = sim.dt();
  h.eq4 = sim.stable_dt();
  h.x = sim.positions();
  return h;
}

TEST(Integrator, EverySettlesTheHangingSquare) {
  for (const std::string& name : integrator_names()) {
    const Hanging h = hang(name, 0, 4);
    std::printf("[ hanging ] %-14s dt %.3f ms: strain max %.4f, speed %.2g m/s\n", name.c_str(), 1e3 * h.dt, h.strain,
                h.speed);
    ASSERT_FALSE(h.diverged) << name;
    EXPECT_LT(h.speed, 0.05f) << name;   // at rest
    EXPECT_GT(h.strain, 0.0f) << name;   // the cloth carries its weight
    EXPECT_LT(h.strain, 0.11f) << name;  // the velocity limit's threshold + 1 %
  }
}

TEST(Integrator, ImplicitEulerIsStableAtTenTimesTheExplicitBound) {
  const Hanging h = hang("implicit-euler", 0.02f, 6);
  std::printf("[ implicit] dt 20 ms = %.1f x the Eq. 4 bound: strain max %.4f, speed %.2g m/s\n", h.dt / h.eq4,
              h.strain, h.speed);
  EXPECT_GE(h.dt, 10 * h.eq4);
  ASSERT_FALSE(h.diverged);
  EXPECT_LT(h.speed, 0.05f);
  EXPECT_LT(h.strain, 0.11f);
  // explicit Euler refuses that step (dressing Eq. 4)
  EXPECT_THROW(hang("explicit-euler", 0.02f, 0.1f), std::invalid_argument);
  EXPECT_FLOAT_EQ(hang("implicit-euler", 0, 0).dt, 0.01f);  // its automatic step
}

TEST(Integrator, ProjectiveIsStableAtTenTimesTheExplicitBound) {
  const Hanging h = hang("projective", 0.02f, 6);
  std::printf("[ project ] dt 20 ms = %.1f x the Eq. 4 bound: strain max %.4f, speed %.2g m/s\n", h.dt / h.eq4,
              h.strain, h.speed);
  EXPECT_FLOAT_EQ(hang("projective", 0, 0).dt, 0.005f);  // its automatic step: the papers' clock
  EXPECT_GE(h.dt, 10 * h.eq4);
  ASSERT_FALSE(h.diverged);
  EXPECT_LT(h.speed, 0.05f);
  EXPECT_LT(h.strain, 0.11f);
}

TEST(Integrator, IdenticalRunsAreBitIdentical) {
  for (const std::string& name : integrator_names()) {
    const Real dt = name == "explicit-euler" ? Real(0) : Real(0.005);
    const Hanging a = hang(name, dt, 0.5f), b = hang(name, dt, 0.5f);
    EXPECT_TRUE(a.x == b.x) << name;  // exact, not approximate
  }
}

}  // namespace
}  // namespace clothbench
