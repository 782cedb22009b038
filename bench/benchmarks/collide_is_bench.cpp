// Image-space collider costs: map rendering per frame (both views, depth + normal + velocity) for
// every renderer (OpenGL through OSMesa, OpenGL through EGL, our CPU rasteriser), both encodings and three map
// sizes, and the walking dress's 6 views x 5 layers; the query cost per point, and per batch of the walking
// dress's 2,300 points (is-egl: answered on its device, the batch's upload and read-back included).
#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <memory>
#include <random>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "clothbench/collide_is/device_maps.hpp"
#include "clothbench/collide_is/image_space_collider.hpp"
#include "clothbench/config.h"
#ifdef CLOTHBENCH_WITH_EGL
#include "clothbench/collide_is/egl_collider.hpp"
#endif
#include "clothbench/io/body_loader.hpp"
#include "clothbench/io/data_root.hpp"

namespace clothbench {
namespace {

// the walking body at t = 2 s (moving: velocity maps too), or Debian's static human
struct BenchBody {
  std::string path;
  BodyFrame frame;
};

const BenchBody& bench_body() {
  static const BenchBody body = [] {
    const std::string walk = data_path("body/mh_female_walk.glb");
    if (std::filesystem::exists(walk)) {
      const BodyModel m = load_body(walk);
      return BenchBody{walk, m.frame(m.animation_index("walk_07_01"), 2.0)};
    }
    // static: flagged moving (zero velocities) so update_body renders every iteration
    BodyFrame rest = load_body(kDebianHumanBody).rest();
    rest.moving = true;
    return BenchBody{kDebianHumanBody, rest};
  }();
  return body;
}

std::unique_ptr<MapRenderer> make_renderer(const std::string& name) {
  if (name == "gl") return make_gl_map_renderer();
#ifdef CLOTHBENCH_WITH_EGL
  if (name == "egl") return make_egl_map_renderer();
#else
  if (name == "egl") throw std::runtime_error("is-egl: not built (configure with -DCLOTHBENCH_WITH_EGL=ON)");
#endif
  return make_cpu_map_renderer();
}

// one frame's maps as update_body renders them: reset, both views, side layer
Points3 near_surface_points(const BodyFrame& body, int count);

// a walking frame's work without the cloth: the maps, then `batches` query batches of 2,300 points (the walking
// dress's), or an idle pause of `idle_ms` (a device left idle between frames may clock down)
struct FrameLoad {
  int batches = 0;
  int idle_ms = 0;
};

void bm_render(benchmark::State& state, const std::string& renderer, bool float_maps, int size, int views = 2,
               int layers = 1, FrameLoad load = {}) {
  ColliderOptions o;
  o.map_size = size;
  o.float_maps = float_maps;
  o.views = views;
  o.layers = layers;
  std::unique_ptr<Collider> c;
  const DeviceMaps* device = nullptr;
  try {
    auto r = make_renderer(renderer);
    device = r->device_maps();
    c = std::make_unique<ImageSpaceCollider>(std::move(r), o, 0.0);
    c->set_body(bench_body().frame);  // warm-up: first frame compiles shaders
  } catch (const std::exception& e) {
    state.SkipWithError(e.what());
    return;
  }
  const Points3 points = near_surface_points(bench_body().frame, 2300);
  std::vector<Contact> out(static_cast<std::size_t>(points.cols()));
  for (auto _ : state) {
    c->update_body(bench_body().frame);
    for (int b = 0; b < load.batches; ++b) c->query(PointsView(points), ContactsOut{out.data(), out.size()});
    if (load.idle_ms > 0) std::this_thread::sleep_for(std::chrono::milliseconds(load.idle_ms));
  }
  const CollideStats s = c->stats();
  state.counters["update_ms"] = s.update_ms / static_cast<double>(s.updates);
  if (s.queries > 0) state.counters["query_batch_ms"] = s.query_ms / static_cast<double>(s.queries);
  // the device's own time per phase of a frame's maps (timestamp queries)
  if (device)
    for (const auto& [phase, ms] : device->draw_phases_ms()) state.counters["gpu_" + phase + "_ms"] = ms;
  state.counters["setup_ms"] = s.setup_ms;
  state.counters["body_triangles"] = bench_body().frame.triangle_count();
  state.SetLabel(c->device());
}

// 10,000 points within 3 cm of the surface (fixed seed) queried in one batch
Points3 near_surface_points(const BodyFrame& body, int count) {
  std::mt19937 rng(4242);
  std::uniform_int_distribution<int> tri(0, body.triangle_count() - 1);
  std::uniform_real_distribution<Real> unit(0, 1), offset(-0.03f, 0.03f);
  Points3 p(3, count);
  for (int i = 0; i < count; ++i) {
    const int t = tri(rng);
    const Vec3 a = body.positions.col(body.triangles(0, t)), b = body.positions.col(body.triangles(1, t)),
               c = body.positions.col(body.triangles(2, t));
    const Real r1 = std::sqrt(unit(rng)), r2 = unit(rng);
    p.col(i) = (1 - r1) * a + r1 * (1 - r2) * b + r1 * r2 * c + offset(rng) * (b - a).cross(c - a).normalized();
  }
  return p;
}

void bm_query(benchmark::State& state, const std::string& renderer, bool float_maps, DepthTest test, int count,
              int views = 2, int layers = 1) {
  ColliderOptions o;
  o.float_maps = float_maps;
  o.views = views;
  o.layers = layers;
  std::unique_ptr<ImageSpaceCollider> made;
  try {
    made = std::make_unique<ImageSpaceCollider>(make_renderer(renderer), o, 0.0, test);
    made->set_body(bench_body().frame);
  } catch (const std::exception& e) {
    state.SkipWithError(e.what());
    return;
  }
  ImageSpaceCollider& c = *made;
  const Points3 points = near_surface_points(bench_body().frame, count);
  std::vector<Contact> out(static_cast<std::size_t>(points.cols()));
  for (auto _ : state) {
    c.query(PointsView(points), ContactsOut{out.data(), out.size()});
    benchmark::DoNotOptimize(out.data());
  }
  state.SetItemsProcessed(state.iterations() * points.cols());
  state.counters["time_per_point"] = benchmark::Counter(
      static_cast<double>(points.cols()), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  state.counters["hit_pct"] = 100.0 * static_cast<double>(c.stats().hits) / static_cast<double>(c.stats().points);
  state.SetLabel(c.device());
}

void register_all() {
  for (const std::string renderer : {"gl", "egl", "cpu"})
    for (const bool float_maps : {true, false})
      for (const int size : {320, 512, 1024})
        benchmark::RegisterBenchmark(
            ("render/" + renderer + "/" + (float_maps ? "float" : "8bit") + "/" + std::to_string(size)).c_str(),
            [=](benchmark::State& s) { bm_render(s, renderer, float_maps, size); })
            ->Unit(benchmark::kMillisecond);
  // the walking dress's maps (walking-t2: 6 views, 5 layers), alone, with a frame's query batches (a walking run
  // of the stable regime asks about 200 a frame) or after an idle pause
  for (const std::string renderer : {"gl", "egl", "cpu"})
    for (const FrameLoad load : {FrameLoad{}, FrameLoad{200, 0}, FrameLoad{0, 50}}) {
      const std::string suffix = load.batches ? "/200batches" : load.idle_ms ? "/idle50ms" : "";
      benchmark::RegisterBenchmark(("render/" + renderer + "/float/320/6views5layers" + suffix).c_str(),
                                   [=](benchmark::State& s) { bm_render(s, renderer, true, 320, 6, 5, load); })
          ->Unit(benchmark::kMillisecond);
    }
  for (const bool float_maps : {true, false})
    for (const DepthTest test : {DepthTest::kPapers, DepthTest::kTangentPlane})
      benchmark::RegisterBenchmark(("query/" + std::string(float_maps ? "float" : "8bit") + "/" +
                                    (test == DepthTest::kPapers ? "papers_z" : "tangent_plane") + "/10000pts")
                                       .c_str(),
                                   [=](benchmark::State& s) { bm_query(s, "cpu", float_maps, test, 10000); })
          ->Unit(benchmark::kMicrosecond);
  // a batch of the walking dress's points, on the CPU and on is-egl's device
  for (const std::string renderer : {"cpu", "egl"})
    for (const int count : {2300, 10000})
      for (const bool dress : {false, true})
        benchmark::RegisterBenchmark(("query/" + renderer + "/float/tangent_plane/" + std::to_string(count) + "pts" +
                                      (dress ? "/6views5layers" : ""))
                                         .c_str(),
                                     [=](benchmark::State& s) {
                                       bm_query(s, renderer, true, DepthTest::kTangentPlane, count, dress ? 6 : 2,
                                                dress ? 5 : 1);
                                     })
            ->Unit(benchmark::kMicrosecond);
}

}  // namespace
}  // namespace clothbench

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::AddCustomContext("body", clothbench::bench_body().path);
  benchmark::AddCustomContext("body_triangles", std::to_string(clothbench::bench_body().frame.triangle_count()));
  clothbench::register_all();
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
