// clothbench_perf_workloads --workload NAME: one small, deterministic workload per run, for the CI
// instruction-count gate (perf/measure.py runs it under callgrind with instrumentation and collection
// off at start). Only the measured part runs between the callgrind client requests, so loading the
// body, meshing and building maps or BVHs are not counted unless they are what is measured. Outside
// valgrind the requests are no-ops: the program simply runs and prints what it did.
#include <cstdio>
#include <ctime>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#if __has_include(<valgrind/callgrind.h>)
#include <valgrind/callgrind.h>
#else  // a build without valgrind's headers: the workloads still run, nothing is counted
#define CALLGRIND_START_INSTRUMENTATION
#define CALLGRIND_STOP_INSTRUMENTATION
#define CALLGRIND_TOGGLE_COLLECT
#endif

#include "clothbench/bench/registry.hpp"
#include "clothbench/bench/runner.hpp"
#include "clothbench/bench/scene.hpp"
#include "clothbench/config.h"
#include "clothbench/io/body_loader.hpp"
#include "clothbench/io/pattern_file.hpp"
#include "clothbench/io/pattern_loader.hpp"
#include "clothbench/sim/garment.hpp"
#include "clothbench/sim/timer.hpp"

namespace clothbench::perf {
namespace {

constexpr int kClothSteps = 8;           // cloth-step: simulator steps measured
constexpr int kQueryPoints = 4000;       // is-query / embree-query: points in the batch
constexpr int kDressingIterations = 40;  // dressing-short: stop.max_iterations (per phase)

// wall and process CPU time of the measured region [ms] (under callgrind: valgrind's time, not native)
struct RegionTimes {
  double wall_ms = 0, cpu_ms = 0;
};

double process_cpu_ms() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) * 1e3 + double(t.tv_nsec) / 1e6;
}

// runs `work` with callgrind's instrumentation and collection on (measure.py starts with both off)
RegionTimes measured(const std::function<void()>& work) {
  const double cpu0 = process_cpu_ms();
  Stopwatch wall;
  CALLGRIND_START_INSTRUMENTATION;
  CALLGRIND_TOGGLE_COLLECT;
  work();
  CALLGRIND_TOGGLE_COLLECT;
  CALLGRIND_STOP_INSTRUMENTATION;
  return {wall.ms(), process_cpu_ms() - cpu0};
}

std::string scene_file(const std::string& relative) { return std::string(CLOTHBENCH_SOURCE_DIR) + "/scenes/" + relative; }

// Debian's static body (scene body "debian:human"), read in this process (a trusted file: no child reader)
BodyFrame static_body() {
  BodyLoadOptions options;
  options.isolate_timeout_s = 0;
  return load_body("debian:human", options).rest();
}

// the scene's garments meshed and placed on `body`, as the runner does (library API only)
ClothMesh scene_cloth(const Scene& scene, const BodyFrame& body) {
  ClothMesh cloth;
  for (const GarmentSpec& g : scene.garments) {
    MeshingOptions options;
    options.target_vertices = g.vertices;
    options.spacing_cm = g.vertices > 0 ? 0 : g.spacing_cm;
    options.attach = g.attach;
    cloth.append(build_garment(load_pattern(resolve_scene_path(scene, g.file)), options, body));
  }
  return cloth;
}

// `count` points near the body: vertices spread over the mesh, moved along their normal by -2..+3 cm in a
// fixed pattern (no random numbers: the same points on every standard library)
Points3 near_body_points(const BodyFrame& body, int count) {
  Points3 p(3, count);
  const int n = body.vertex_count();
  for (int i = 0; i < count; ++i) {
    const int v = int((long(i) * 7919) % n);
    const Real offset = Real(-0.02 + 0.05 * double((i * 37) % 101) / 100.0);
    p.col(i) = body.positions.col(v) + offset * body.normals.col(v);
  }
  return p;
}

double checksum(const Points3& p) { return double(p.cast<double>().sum()); }

// (a) a few explicit-Euler steps (sew phase, is-cpu) of the dress at ~2,000 vertices on the static body
RegionTimes cloth_step() {
  const Scene scene = load_scene(scene_file("dressing/dress.toml"), {"garment.vertices=2000"});
  const BodyFrame body = static_body();
  std::unique_ptr<Collider> collider = make_collider(scene.collider, scene.collider_options);
  collider->set_body(body);
  Simulator sim(scene_cloth(scene, body), scene.material, scene.solver);
  sim.set_collider(collider.get());
  sim.set_phase(Phase::kSew);
  const RegionTimes t = measured([&] {
    for (int i = 0; i < kClothSteps; ++i) sim.step();
  });
  std::printf("cloth-step: %d vertices, %d steps, seam gap %.2f mm, checksum %.6f\n", sim.mesh().vertex_count(),
              kClothSteps, 1e3 * double(sim.seam_gap_max()), checksum(sim.positions()));
  return t;
}

// (b), (c) one batch of points near the body through a collider built beforehand
RegionTimes query(const std::string& collider_name) {
  const BodyFrame body = static_body();
  ColliderOptions options;
  options.threads = 1;  // callgrind collects the calling thread only
  std::unique_ptr<Collider> collider = make_collider(collider_name, options);
  collider->set_body(body);
  const Points3 points = near_body_points(body, kQueryPoints);
  std::vector<Contact> contacts(kQueryPoints);
  const RegionTimes t = measured([&] { collider->query(points, {contacts.data(), contacts.size()}); });
  std::printf("%s query: %d points, %lld hits\n", collider_name.c_str(), kQueryPoints,
              static_cast<long long>(collider->stats().hits));
  return t;
}

// (d) one re-render of the CPU image-space maps at 320^2 (depth, normal, velocity, side layer), as
// update_body draws them every animation frame; the first render (set_body) is set-up
RegionTimes map_render() {
  BodyFrame body = static_body();
  body.moving = true;  // zero velocities, but a moving body is drawn again on every update
  ColliderOptions options;
  options.map_size = 320;
  std::unique_ptr<Collider> collider = make_collider("is-cpu", options);
  collider->set_body(body);
  const RegionTimes t = measured([&] { collider->update_body(body); });
  std::printf("map-render: %d triangles, 320^2 maps, %lld updates\n", body.triangle_count(),
              static_cast<long long>(collider->stats().updates));
  return t;
}

// (e) a short dressing run end to end (run_scene: meshing, maps, sew, drape with its attachments, the oracle's accuracy);
// measure.py leaves load_body out of the count (Workload::uncounted)
RegionTimes dressing_short() {
  const Scene scene =
      load_scene(scene_file("dressing/skirt.toml"), {"stop.max_iterations=" + std::to_string(kDressingIterations)});
  RunOptions options;
  options.progress = false;
  RunResult r;
  const RegionTimes t = measured([&] { r = run_scene(scene, options); });
  std::printf("dressing-short: skirt %d vertices, %ld iterations, inside %.2f %%\n", r.vertices, r.iterations(),
              r.accuracy.inside_pct);
  return t;
}

struct Workload {
  const char* name;
  const char* what;
  std::function<RegionTimes()> run;
  const char* uncounted = "";  // functions inside the region that measure.py leaves out (callgrind --toggle-collect)
};

std::vector<Workload> workloads() {
  std::vector<Workload> w = {
      {"cloth-step", "8 simulator steps of the dress at ~2,000 vertices on the static body (is-cpu)", cloth_step},
      {"is-query", "4,000 points near the body through the is-cpu collider (one batch)", [] { return query("is-cpu"); }},
  };
#ifdef CLOTHBENCH_WITH_EMBREE
  w.push_back({"embree-query", "the same 4,000 points through the embree collider (one thread, from scratch)",
               [] { return query("embree"); }});
#endif
  w.push_back({"map-render", "one CPU render of the image-space maps at 320^2 (is-cpu update_body)", map_render});
  // reading the body file is assimp's work (and a child process): not counted
  w.push_back({"dressing-short", "the skirt scene, sew and drape capped at 40 iterations each, end to end (run_scene)",
               dressing_short, "clothbench::load_body(*"});
  return w;
}

int usage(const std::vector<Workload>& all, const char* why) {
  std::fprintf(stderr, "clothbench_perf_workloads: %s\nusage: clothbench_perf_workloads --workload NAME | --list | --toolchain\n"
               "known workloads:\n", why);
  for (const Workload& w : all) std::fprintf(stderr, "  %-16s %s\n", w.name, w.what);
  return 2;
}

int run(int argc, char** argv) {
  const std::vector<Workload> all = workloads();
  const std::string arg = argc > 1 ? argv[1] : "";
  if (argc == 2 && arg == "--list") {
    for (const Workload& w : all) std::printf("%s\t%s\t%s\n", w.name, w.what, w.uncounted);
    return 0;
  }
  if (argc == 2 && arg == "--toolchain") {  // one line per key, for the JSON's context
    std::printf("compiler\t%s\nbuild_type\t%s\ncxx_flags\t%s\n", CLOTHBENCH_CXX_COMPILER, CLOTHBENCH_BUILD_TYPE,
                CLOTHBENCH_CXX_FLAGS);
    return 0;
  }
  if (argc != 3 || arg != "--workload") return usage(all, "expected --workload NAME");
  for (const Workload& w : all) {
    if (argv[2] != std::string(w.name)) continue;
    const RegionTimes t = w.run();
    std::printf("measured region: wall %.3f ms, cpu %.3f ms\n", t.wall_ms, t.cpu_ms);
    return 0;
  }
  return usage(all, ("unknown workload `" + std::string(argv[2]) + "`").c_str());
}

}  // namespace
}  // namespace clothbench::perf

int main(int argc, char** argv) {
  try {
    return clothbench::perf::run(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "clothbench_perf_workloads: %s\n", e.what());
    return 2;
  }
}
