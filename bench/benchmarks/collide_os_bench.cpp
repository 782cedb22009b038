// Object-space collider costs on the real body: BVH build, refit per animation frame, closest
// point per query point (near the surface, and far outside), and how the query cost grows as the
// body is subdivided (27k -> 107k -> 428k triangles). brute runs on a few points only.
// Body: the walking body of the data root, else Debian's human.zae (static: refit uses a
// deformed copy). Counters: ns_per_point from the collider's own query timer.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "clothbench/bench/oracle.hpp"
#include "clothbench/bench/registry.hpp"
#include "clothbench/io/body_loader.hpp"
#include "clothbench/io/data_root.hpp"

namespace clothbench {
namespace {

// two frames of one body, one 1/30 s after the other (refit alternates between them)
struct Bodies {
  std::string source;
  BodyFrame a, b;
};

const Bodies& bodies() {
  static const Bodies cached = [] {
    Bodies out;
    const std::string walk = data_path("body/mh_female_walk.glb");
    if (std::filesystem::exists(walk)) {
      const BodyModel model = load_body(walk);
      const int anim = model.animation_index("walk_07_01");
      out.source = walk;
      out.a = model.frame(anim, 1.0, true);
      out.b = model.frame(anim, 1.0 + 1.0 / 30, true);
      return out;
    }
    BodyLoadOptions options;
    options.require_closed = false;
    const BodyModel model = load_body(kDebianHumanBody, options);
    out.source = kDebianHumanBody;
    out.a = model.rest();
    out.b = out.a;
    out.b.positions.row(0) *= 1.01f;
    return out;
  }();
  return cached;
}

// the body subdivided `level` times (cached)
const BodyFrame& subdivided(int level) {
  static std::map<int, BodyFrame> cache;
  auto it = cache.find(level);
  if (it != cache.end()) return it->second;
  BodyFrame b = level == 0 ? bodies().a : subdivided(level - 1);
  if (level > 0) b = subdivide_body(b);
  return cache.emplace(level, std::move(b)).first->second;
}

void set_counters(benchmark::State& state, const Collider& c, const BodyFrame& body) {
  const CollideStats s = c.stats();
  state.counters["body_triangles"] = body.triangle_count();
  state.counters["threads"] = s.threads;
  if (s.points > 0) state.counters["ns_per_point"] = s.query_ms * 1e6 / double(s.points);
  if (s.updates > 0) state.counters["update_ms"] = s.update_ms / double(s.updates);
}

void bm_build(benchmark::State& state, const std::string& name) {
  const BodyFrame& body = bodies().a;
  double setup_ms = 0;
  for (auto _ : state) {
    auto c = make_collider(name);
    c->set_body(body);
    setup_ms += c->stats().setup_ms;
  }
  state.counters["setup_ms"] = setup_ms / double(state.iterations());
  state.counters["body_triangles"] = body.triangle_count();
}

void bm_refit(benchmark::State& state, const std::string& name) {
  auto c = make_collider(name);
  c->set_body(bodies().a);
  bool flip = false;
  for (auto _ : state) {
    c->update_body(flip ? bodies().a : bodies().b);
    flip = !flip;
  }
  set_counters(state, *c, bodies().a);
}

// query cost per point; `far` puts the points 10-20 cm outside (beyond the search radius)
void bm_query(benchmark::State& state, const std::string& name, int level, int count, bool far) {
  const BodyFrame& body = subdivided(level);
  ColliderOptions options;
  options.threads = static_cast<int>(state.range(0));
  options.coherent = false;  // every repetition searches again (coherence would skip the repeated points)
  auto c = make_collider(name, options);
  c->set_body(body);
  const Points3 points =
      far ? points_off_surface(body, count, 0.10f, 0.20f, 12345) : points_off_surface(body, count, -0.03f, 0.03f, 12345);
  std::vector<Contact> out(std::size_t(points.cols()));
  for (auto _ : state) c->query(points, {out.data(), out.size()});
  state.SetItemsProcessed(state.iterations() * points.cols());
  set_counters(state, *c, body);
  state.counters["hits_pct"] = 100.0 * double(c->stats().hits) / double(c->stats().points);
}

void bm_oracle(benchmark::State& state) {
  const BodyFrame& body = bodies().a;
  const Oracle oracle(body);
  const Points3 points = points_off_surface(body, 10000, -0.03f, 0.03f, 12345);
  std::vector<Real> d;
  for (auto _ : state) oracle.signed_distance(points, d);
  state.SetItemsProcessed(state.iterations() * points.cols());
  state.counters["ns_per_point"] = benchmark::Counter(
      double(points.cols()), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  state.counters["embree"] = Oracle::uses_embree();
}

void register_all() {
  for (const std::string& name :
       colliders([](const ColliderInfo& c) { return c.family != Family::kImageSpace; })) {  // object space, reference
    const bool brute = collider_info(name)->family == Family::kReference;
    benchmark::RegisterBenchmark(("build/" + name).c_str(), bm_build, name)->Unit(benchmark::kMillisecond);
    if (!brute) benchmark::RegisterBenchmark(("refit/" + name).c_str(), bm_refit, name)->Unit(benchmark::kMillisecond);
    // brute: 100 points only (O(points x triangles))
    const int count = brute ? 100 : 10000;
    auto* q = benchmark::RegisterBenchmark(("query_near/" + name).c_str(), bm_query, name, 0, count, false);
    q->Unit(benchmark::kMillisecond)->Arg(1);
    if (name == "embree") q->Arg(2);
    if (brute) continue;
    benchmark::RegisterBenchmark(("query_far/" + name).c_str(), bm_query, name, 0, count, true)
        ->Unit(benchmark::kMillisecond)
        ->Arg(1);
    for (int level = 1; level <= 2; ++level)
      benchmark::RegisterBenchmark(("query_near_subdiv" + std::to_string(level) + "/" + name).c_str(), bm_query, name,
                                   level, count, false)
          ->Unit(benchmark::kMillisecond)
          ->Arg(1);
  }
  benchmark::RegisterBenchmark("oracle/signed_distance", bm_oracle)->Unit(benchmark::kMillisecond);
}

}  // namespace
}  // namespace clothbench

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::AddCustomContext("body", clothbench::bodies().source);
  clothbench::register_all();
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
