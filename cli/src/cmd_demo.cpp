// clothbench demo: a square cloth falling onto a sphere (the core's smoke scene)
#include <cstdio>
#include <iostream>

#include "clothbench/bench/registry.hpp"
#include "clothbench/io/errors.hpp"
#include "clothbench/sim/simulator.hpp"
#include "clothbench/sim/sphere_collider.hpp"
#include "commands.hpp"

namespace clothbench::cli {

namespace {

struct DemoOptions {
  int side = 30;            // vertices per side
  double seconds = 2.0;     // simulated time
  std::string limit = "velocity";
  std::string collider = "sphere";
};

int run_demo(const DemoOptions& o) {
  if (o.side < 2 || o.side > 1000) throw InputError("--side must be in [2, 1000]");
  if (!(o.seconds > 0) || o.seconds > 60) throw InputError("--seconds must be in (0, 60]");
  const Real size = 0.8f, radius = 0.3f;
  ClothMesh cloth = make_grid_cloth(o.side, o.side, size / Real(o.side - 1), Vec3(-size / 2, radius + 0.05f, -size / 2),
                                    Vec3::UnitX(), Vec3::UnitZ());
  SolverParams params;
  try {
    check_limiter(o.limit);
  } catch (const std::invalid_argument& e) {
    throw InputError(std::string("--") + e.what());
  }
  params.limit = o.limit;
  Simulator sim(cloth, Material{}, params);
  // the analytic sphere, or any registered collider on a meshed sphere
  std::unique_ptr<Collider> collider;
  if (o.collider == "sphere") {
    collider = std::make_unique<SphereCollider>(Vec3::Zero(), radius);
  } else {
    collider = make_collider(o.collider);
    collider->set_body(make_sphere_body(Vec3::Zero(), radius, 48, 96));
  }
  sim.set_collider(collider.get());
  const long steps = static_cast<long>(o.seconds / sim.dt());
  for (long i = 0; i < steps && sim.step(); ++i) {
  }
  Real deepest = 0;
  for (int v = 0; v < sim.positions().cols(); ++v)
    deepest = std::min(deepest, Real(sim.positions().col(v).norm() - radius));
  const auto& t = sim.timings();
  const double n = double(std::max(1L, t.iterations));
  std::printf("demo: %d x %d cloth on a %.2f m sphere, collider %s, limit %s\n", o.side, o.side, radius,
              o.collider.c_str(), o.limit.c_str());
  std::printf("  dt                 %.3f ms (Eq. 4 bound %.3f ms)\n", sim.dt() * 1e3, sim.stable_dt() * 1e3);
  std::printf("  iterations         %ld (%.2f s simulated)\n", t.iterations, t.iterations * double(sim.dt()));
  std::printf("  ms per iteration   %.4f  (CD&R %.4f, CS %.4f)\n", (t.cdr_ms + t.cs_ms) / n, t.cdr_ms / n, t.cs_ms / n);
  std::printf("  max strain         %.2f %%  (p99 %.2f %%)\n", 100 * sim.strain().max, 100 * sim.strain().p99);
  std::printf("  final penetration  %.2f mm  (deepest vertex below the sphere surface, exact)\n", 1e3 * double(-deepest) + 0.0);
  if (sim.divergence()) {
    const auto& d = *sim.divergence();
    std::printf("  DIVERGED at iteration %ld, phase %s, vertex %d: %s\n", d.iteration, to_string(d.phase), d.vertex,
                d.reason.c_str());
    return 3;
  }
  return 0;
}

}  // namespace

void add_demo_command(CLI::App& app, Action& action) {
  auto opts = std::make_shared<DemoOptions>();
  auto* cmd = app.add_subcommand("demo", "Drop a square cloth onto a sphere and print speed and accuracy");
  cmd->add_option("--side", opts->side, "Vertices per side of the square cloth")->capture_default_str();
  cmd->add_option("--seconds", opts->seconds, "Simulated time [s]")->capture_default_str();
  std::string limiters;
  for (const std::string& name : limiter_names()) limiters += (limiters.empty() ? "" : ", ") + name;
  cmd->add_option("--limit", opts->limit, "Strain limiter: " + limiters)->capture_default_str();
  cmd->add_option("--collider", opts->collider, "sphere (analytic) or a registered collider on a meshed sphere")
      ->capture_default_str();
  cmd->callback([opts, &action] { action = [opts] { return run_demo(*opts); }; });
}

}  // namespace clothbench::cli
