// run_scene on small scenes: sewing closes, determinism, divergence reported, accuracy from the oracle.
#include <gtest/gtest.h>

#include "clothbench/config.h"
#include "runner.hpp"

namespace clothbench {
namespace {

// a small tablecloth dropped on the analytic sphere: fast, no body file needed
Scene small_tablecloth() {
  Scene s = load_scene(std::string(CLOTHBENCH_SOURCE_DIR) + "/scenes/walking/tablecloth_sphere.toml",
                       {"garment.vertices=225", "body.move_s=0.1", "stop.drape_max_s=0.3"});
  return s;
}

TEST(Runner, SameSceneTwiceGivesIdenticalPositions) {
  RunOptions quiet;
  quiet.progress = false;
  const RunResult a = run_scene(small_tablecloth(), quiet), b = run_scene(small_tablecloth(), quiet);
  ASSERT_FALSE(a.divergence);
  EXPECT_EQ(a.iterations(), b.iterations());
  EXPECT_EQ(a.frames, b.frames);
  ASSERT_EQ(a.mesh.positions.size(), b.mesh.positions.size());
  EXPECT_EQ(0, std::memcmp(a.mesh.positions.data(), b.mesh.positions.data(), sizeof(Real) * a.mesh.positions.size()))
      << "bit-identical on one thread";
  EXPECT_EQ(a.accuracy.inside, b.accuracy.inside);
}

TEST(Runner, MovingSphereIsAnimatedAndMeasured) {
  RunOptions quiet;
  quiet.progress = false;
  const RunResult r = run_scene(small_tablecloth(), quiet);
  EXPECT_EQ(r.frames, 6);  // 0.1 s at 60 fps
  EXPECT_GT(r.animate.iterations, 0);
  EXPECT_GT(r.accuracy.points, 0u);
  EXPECT_LT(r.accuracy.inside_pct, 50.0);
  EXPECT_GT(r.dt_s, 0);
  EXPECT_LE(r.dt_s, r.dt_bound_s);
}

// the sphere's velocity applies to the animation only: dressing sees a body at rest
TEST(Runner, MovingSphereRestsWhileDressing) {
  RunOptions quiet;
  quiet.progress = false;
  Scene still = small_tablecloth(), fast = small_tablecloth();
  still.body.move_s = fast.body.move_s = 0;
  still.body.velocity = Vec3::Zero();
  fast.body.velocity = Vec3(5, 0, 0);
  const RunResult a = run_scene(still, quiet), b = run_scene(fast, quiet);
  ASSERT_EQ(a.mesh.positions.size(), b.mesh.positions.size());
  EXPECT_EQ(0, std::memcmp(a.mesh.positions.data(), b.mesh.positions.data(), sizeof(Real) * a.mesh.positions.size()));
}

TEST(Runner, DivergenceIsReportedNotThrown) {
  Scene s = small_tablecloth();
  s.solver.allow_unstable_dt = true;
  s.solver.dt = 0.05f;  // about 40x the Eq. 4 bound
  s.solver.limit = Limit::kNone;
  RunOptions quiet;
  quiet.progress = false;
  const RunResult r = run_scene(s, quiet);
  ASSERT_TRUE(r.divergence.has_value());
  EXPECT_GT(r.divergence->iteration, 0);
  EXPECT_FALSE(r.converged);
}

// the scene a new user runs first (README) ends sewn and settled with no skin showing through:
// nothing inside the body, no structural spring crossing it, every seam closed
TEST(Runner, TheFirstStaticSceneEndsDressedWithNoSkinShowing) {
  RunOptions quiet;
  quiet.progress = false;
  const RunResult r = run_scene(load_scene(std::string(CLOTHBENCH_SOURCE_DIR) + "/scenes/dressing/skirt.toml"), quiet);
  ASSERT_FALSE(r.divergence);
  EXPECT_TRUE(r.converged);
  EXPECT_LE(r.accuracy.inside_pct, 0.5);
  EXPECT_LE(r.accuracy.crossings_pct, 0.5);
  EXPECT_LE(r.seam_gap_max_mm, 2.0);
}

// rk45 moves points by more than h v_end (its drift): the limits, seam caps and the response must see that
// displacement, or the seams fling vertices off (it diverged at iteration 98 when they did not)
TEST(Runner, Rk45SewsAndDrapesTheSkirtWithoutDiverging) {
  RunOptions quiet;
  quiet.progress = false;
  const RunResult r = run_scene(load_scene(std::string(CLOTHBENCH_SOURCE_DIR) + "/scenes/dressing/skirt.toml",
                                           {"garment.vertices=336", "solver.integrator=rk45"}),
                                quiet);
  ASSERT_FALSE(r.divergence) << r.divergence->reason;
  EXPECT_TRUE(r.sew.reached);
  EXPECT_LE(r.accuracy.inside_pct, 0.5);
}

}  // namespace
}  // namespace clothbench
