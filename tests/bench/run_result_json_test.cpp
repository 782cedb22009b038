// A RunResult through JSON and back (what a prefetch worker hands its parent): every measured field kept.
#include "clothbench/bench/run_result_json.hpp"

#include <gtest/gtest.h>

#include "clothbench/bench/report.hpp"

namespace clothbench {
namespace {

TEST(RunResultJson, TheEndStateTravelsOnlyWhenAsked) {
  RunResult r;
  r.mesh.positions.resize(3, 4);
  r.mesh.positions << 0.1f, 0.2f, 0.3f, 0.4f, 1.f / 3, 0.6f, 0.7f, 0.8f, -0.9f, 1.0f, 1.1f, 1.2f;
  r.mesh.quads.resize(4, 1);
  r.mesh.quads << 0, 1, 2, 3;
  EXPECT_FALSE(to_json(r).contains("end_positions"));
  EXPECT_EQ(run_result_from_json(to_json(r)).mesh.positions.cols(), 0);
  const RunResult b = run_result_from_json(to_json(r, true));
  EXPECT_EQ(b.mesh.positions, r.mesh.positions);  // bit for bit: the drape error is computed from it
  EXPECT_EQ(b.mesh.quads, r.mesh.quads);
  EXPECT_EQ(b.mesh.surface_triangles().cols(), 2);
}

TEST(RunResultJson, EveryMeasuredFieldSurvivesTheRoundTrip) {
  RunResult r;
  r.scene = "shirt";
  r.collider = "is-egl";
  r.device = "EGL device 0 of 1: Mesa llvmpipe";
  r.regime = "papers";
  r.config_hash = "0123456789abcdef";
  r.vertices = 1817;
  r.dt_s = 0.005;
  r.k_structural = 0.36;
  r.sew = {90, 50.5, 49.0, 3.4, 40.1, 38.2, true};
  r.drape = {161, 140.0, 139.0, 6.1, 110.0, 100.0, false};
  r.accuracy.inside_pct = 0.17;
  r.accuracy.crossings = 21;
  r.accuracy.crossings_pct = 0.61;
  r.strain_max = 0.151;
  r.strain_max_where = "spring 4863";
  r.seam_gap_where = "seam pair 3";
  r.depth_max_where = "vertex 1916";
  r.animate_strain_max = 0.23;
  r.animate_strain_max_where = "spring 10273 at t = 2.50 s";
  r.sew_iteration_ms = {0.5f, 0.25f};
  r.converged = true;
  r.frame_samples = {{1.033, 0.1, 0.5, 0.2, 0.12, 0.08}, {1.067, 0, 0, 0.05, 0.11, 0.07}};
  r.window_seam_gap_mm = 1.5;
  r.divergence = Divergence{13, Phase::kSew, 910, "speed 51 m/s above max_speed"};
  const RunResult b = run_result_from_json(to_json(r));
  EXPECT_EQ(to_json(b), to_json(r));
  // and the row a report writes from it is the same
  EXPECT_EQ(result_row(b, "x"), result_row(r, "x"));
  ASSERT_TRUE(b.divergence.has_value());
  EXPECT_EQ(b.divergence->phase, Phase::kSew);
  EXPECT_EQ(b.divergence->reason, "speed 51 m/s above max_speed");
  EXPECT_EQ(b.drape.limit_ms, 100.0);
  EXPECT_FALSE(b.drape.reached);
  ASSERT_EQ(b.frame_samples.size(), 2u);
  EXPECT_EQ(b.frame_samples[1].crossings_pct, 0.05);
  EXPECT_EQ(b.frame_samples[1].strain_p99, 0.07);
  EXPECT_EQ(b.window_seam_gap_mm, 1.5);
  EXPECT_EQ(b.depth_max_where, "vertex 1916");
  EXPECT_EQ(b.seam_gap_where, "seam pair 3");
  EXPECT_EQ(b.animate_strain_max_where, "spring 10273 at t = 2.50 s");
  RunResult none = r;
  none.divergence.reset();
  EXPECT_FALSE(run_result_from_json(to_json(none)).divergence.has_value());
}

}  // namespace
}  // namespace clothbench
