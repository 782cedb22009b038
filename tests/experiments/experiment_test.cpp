// ExperimentContext: what reproduce --jobs N hands back from its worker processes equals what a run in the
// process measures, but for timings, and carries the cloth's end state (the drape error needs it).
#include "clothbench/experiments/experiment.hpp"

#include <gtest/gtest.h>

#include "test_support.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "clothbench/bench/registry.hpp"
#include "clothbench/bench/run_result_json.hpp"
#include "clothbench/experiments/statistics.hpp"
#include "clothbench/sim/body_frame.hpp"

namespace clothbench {
namespace {

// every field but the timings (as tests/cluster/same_except_timings.py: keys ending in _ms, estimate_s) and the
// end state (compared on its own)
void drop_timings(nlohmann::json& j) {
  for (auto it = j.begin(); it != j.end();) {
    const std::string k = j.is_object() ? it.key() : "";
    const bool timing = k == "estimate_s" || (k.size() > 3 && k.compare(k.size() - 3, 3, "_ms") == 0);
    if (timing) {
      it = j.erase(it);
      continue;
    }
    if (it->is_object()) drop_timings(*it);
    ++it;
  }
}
nlohmann::json without_timings(const RunResult& r) {
  nlohmann::json j = to_json(r);
  drop_timings(j);
  j.erase("sew_iteration_ms");
  return j;
}

TEST(ExperimentContext, PrefetchedRunsEqualRunsInTheProcessButForTimings) {
  const std::string out = test::temp_path("prefetch-test");
  const std::vector<ExperimentContext::Request> grid{
      {"walking/tablecloth_sphere.toml", "sphere", {"garment.vertices=100", "stop.drape_max_s=0.05"}},
      {"walking/tablecloth_sphere.toml", "brute", {"garment.vertices=64", "stop.drape_max_s=0.05"}}};
  ExperimentContext alone(out + "/1", false, 1, 1), workers(out + "/2", false, 1, 2);
  workers.prefetch(grid);
  for (const auto& q : grid) {
    const RunResult& a = alone.run(q.scene, q.collider, q.sets);
    const RunResult& b = workers.run(q.scene, q.collider, q.sets);
    ASSERT_GT(a.mesh.positions.cols(), 0);
    EXPECT_EQ(b.mesh.positions, a.mesh.positions) << q.collider;
    EXPECT_EQ(b.mesh.quads, a.mesh.quads) << q.collider;
    EXPECT_EQ(without_timings(b), without_timings(a)) << q.collider;
  }
  std::filesystem::remove_all(out);
}

// a verdict asks for more runs of a request already made once: run() adds them, the first one kept among them,
// and asking for fewer changes nothing
TEST(ExperimentContext, ARequestRunOnceGetsTheRunsAVerdictAsksFor) {
  const std::string out = test::temp_path("repeat-test");
  ExperimentContext ctx(out, false, 1, 1);
  const ExperimentContext::Request q{
      "walking/tablecloth_sphere.toml", "sphere", {"garment.vertices=64", "stop.drape_max_s=0.02"}};
  const RunResult* first = &ctx.run(q.scene, q.collider, q.sets);
  ASSERT_EQ(ctx.repetitions_of(*first).size(), 1u);
  const nlohmann::json once = without_timings(*first);
  const auto runs = ctx.repetitions_of(ctx.run(q.scene, q.collider, q.sets, {}, 3));
  ASSERT_EQ(runs.size(), 3u);
  for (const RunResult* r : runs) EXPECT_EQ(without_timings(*r), once);  // deterministic: the same run thrice
  EXPECT_EQ(ctx.repetitions_of(ctx.run(q.scene, q.collider, q.sets, {}, 2)).size(), 3u);
  std::filesystem::remove_all(out);
}

// reproduce draws pictures with OpenGL before its grids run; a forked worker inherits OSMesa but not llvmpipe's
// threads, and is-gl in it waited forever (a full reproduce --jobs 2 hung): is-gl requests stay in this process
TEST(ExperimentContext, PrefetchLeavesOpenGlToThisProcessOnceItHasDrawn) {
  const auto built = available_colliders();
  if (std::find(built.begin(), built.end(), "is-gl") == built.end()) GTEST_SKIP() << "is-gl not built";
  auto gl = make_collider("is-gl");
  gl->set_body(make_sphere_body(Vec3::Zero(), 0.2f));  // this process has drawn
  EXPECT_TRUE(ExperimentContext::needs_opengl("is-gl"));
  EXPECT_FALSE(ExperimentContext::needs_opengl("is-cpu"));
  const std::string out = test::temp_path("prefetch-gl-test");
  ExperimentContext workers(out, false, 1, 2);
  const ExperimentContext::Request q{
      "walking/tablecloth_sphere.toml", "is-gl", {"garment.vertices=64", "stop.drape_max_s=0.02"}};
  workers.prefetch({q});  // hung here when it forked is-gl
  EXPECT_GT(workers.run(q.scene, q.collider, q.sets).mesh.positions.cols(), 0);
  std::filesystem::remove_all(out);
}

// a page opens with its summary: right under the title, before the machine and the definitions; six lines are
// not a summary
TEST(ExperimentContext, APageOpensWithItsSummary) {
  const std::string out = test::temp_path("summary-test");
  ExperimentContext ctx(out, true, 1);
  ctx.write("page", "A page", "The body.\n", {"The paper: a figure.", "Ours: a figure.", "Verdict: holds."});
  std::ifstream in(out + "/page.md");
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  ASSERT_GE(lines.size(), 8u);
  EXPECT_EQ(lines[0], "# page: A page");
  EXPECT_EQ(lines[2], "**Summary.**");
  EXPECT_EQ(lines[4], "- The paper: a figure.");
  EXPECT_EQ(lines[6], "- Verdict: holds.");
  EXPECT_EQ(lines[7], "");
  EXPECT_EQ(lines[8].rfind("Generated by", 0), 0u);
  EXPECT_THROW(ctx.write("page", "A page", "", std::vector<std::string>(6, "a line")), std::logic_error);
  std::filesystem::remove_all(out);
}

TEST(Statistics, ASpreadIsTheMedianWithTheLeastAndMostAndSaysHowManyRuns) {
  const Spread s = spread({0.4, 0.1, 0.3, 0.2});
  EXPECT_EQ(s.median, 0.3);  // of an even count, the upper middle value
  EXPECT_EQ(s.lo, 0.1);
  EXPECT_EQ(s.hi, 0.4);
  EXPECT_EQ(runs_text(s, 1), "median of 4 runs, 0.1-0.4");
  EXPECT_EQ(runs_text(spread({0.25}), 2), "one run");
  EXPECT_EQ(median_range({2.0, 1.0, 3.0}, 0), "2 (1-3)");
}

}  // namespace
}  // namespace clothbench
