// run_scene on small scenes: sewing closes, determinism, divergence reported, accuracy from the oracle.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <regex>
#include <string>

#include "clothbench/bench/body_between_frames.hpp"
#include "clothbench/bench/registry.hpp"
#include "clothbench/bench/report.hpp"
#include "clothbench/bench/runner.hpp"
#include "clothbench/config.h"
#include "clothbench/io/data_root.hpp"
#include "clothbench/io/errors.hpp"
#include "clothbench/sim/sphere_collider.hpp"
#include "test_support.hpp"

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

// two garments in one scene: their panels are named after their garments (the same pattern twice is numbered), so
// that a report of the cloth through itself says which garment crosses which
TEST(Runner, TwoGarmentsPanelsAreNamedAfterTheirGarments) {
  Scene s = small_tablecloth();
  s.garments.push_back(s.garments.front());
  s.garments.back().jitter_mm = 50, s.garments.back().seed = 1;
  s.stop.drape_max_s = 0.05;
  RunOptions quiet;
  quiet.progress = false;
  const RunResult r = run_scene(s, quiet);
  EXPECT_EQ(r.mesh.panel_names, (std::vector<std::string>{"tablecloth_sphere.cloth", "tablecloth_sphere#2.cloth"}));
  EXPECT_EQ(run_scene(small_tablecloth(), quiet).mesh.panel_names, (std::vector<std::string>{"cloth"}));
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

// --every-frame: one oracle sample per animation frame, and the deepest vertex of the deepest frame named
// (a sphere thrust up through the cloth at 3 m/s leaves points inside)
TEST(Runner, EveryFrameIsMeasuredAndTheDeepestPointIsNamed) {
  RunOptions o;
  o.progress = false;
  o.measure_frames = true;
  Scene s = small_tablecloth();
  s.body.velocity = Vec3(0, 3, 0);
  s.solver.push_out = false;
  const RunResult r = run_scene(s, o);
  ASSERT_FALSE(r.divergence);
  ASSERT_EQ(r.frame_samples.size(), static_cast<std::size_t>(r.frames));
  const double deepest = r.frame_max(&FrameSample::depth_max_mm);
  ASSERT_GT(deepest, 0);
  char depth[32];
  std::snprintf(depth, sizeof depth, "%.1f mm inside", deepest);
  EXPECT_EQ(r.depth_max_where.rfind("vertex ", 0), 0u) << r.depth_max_where;
  EXPECT_NE(r.depth_max_where.find(depth), std::string::npos) << r.depth_max_where;
  // the JSON row (run --json, results/*.json) carries the worst and the mean frame, not only the end state
  const nlohmann::json row = result_row(r, "sphere");
  EXPECT_EQ(row.at("frames_measured").get<long>(), r.frames);
  EXPECT_EQ(row.at("worst_frame_depth_max_mm").get<double>(), deepest);
  EXPECT_EQ(row.at("worst_frame_inside_pct").get<double>(), r.frame_max(&FrameSample::inside_pct));
  EXPECT_EQ(row.at("mean_frame_crossings_pct").get<double>(), r.frame_mean(&FrameSample::crossings_pct));
  EXPECT_EQ(row.at("depth_max_where").get<std::string>(), r.depth_max_where);
  // and where and when the most strained frame's most strained spring was
  ASSERT_GT(r.animate_strain_max, 0);
  EXPECT_EQ(r.animate_strain_max_where.rfind("spring ", 0), 0u) << r.animate_strain_max_where;
  EXPECT_NE(r.animate_strain_max_where.find(" at t = "), std::string::npos) << r.animate_strain_max_where;
  EXPECT_EQ(row.at("worst_frame_strain_where").get<std::string>(), r.animate_strain_max_where);
}

// without --every-frame the end state's deepest point is named, a quad's midpoint too with face queries
TEST(Runner, TheEndStatesDeepestPointIsNamed) {
  RunOptions o;
  o.progress = false;
  for (const bool faces : {false, true}) {
    Scene s = small_tablecloth();
    s.body.velocity = Vec3(0, 3, 0);
    s.solver.push_out = false;
    s.solver.face_queries = faces;
    const RunResult r = run_scene(s, o);
    ASSERT_FALSE(r.divergence);
    ASSERT_GT(r.accuracy.depth_max_mm, 0);
    char depth[40];
    std::snprintf(depth, sizeof depth, "%.1f mm inside at the end", r.accuracy.depth_max_mm);
    EXPECT_NE(r.depth_max_where.find(depth), std::string::npos) << r.depth_max_where;
    const bool midpoint = r.accuracy.deepest >= r.vertices;
    EXPECT_EQ(r.depth_max_where.rfind(midpoint ? "the midpoint of quad " : "vertex ", 0), 0u) << r.depth_max_where;
  }
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
  s.solver.limit = "none";
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

// `fit`: a skirt drafted from Debian's human's own measurements (Durupinar section 2), sewn and draped on it within
// every limit; its configuration names the fit, not a file
TEST(Runner, AFittedSkirtIsDraftedFromTheBodysMeasurementsAndDressedOnIt) {
  if (!std::filesystem::exists(kDebianHumanBody)) GTEST_SKIP() << "assimp-testmodels not installed";
  RunOptions quiet;
  quiet.progress = false;
  const Scene s = load_scene(std::string(CLOTHBENCH_SOURCE_DIR) + "/scenes/dressing/skirt.toml",
                             {"garment.file=", "garment.fit=skirt", "garment.size=M", "garment.vertices=300"});
  const RunResult r = run_scene(s, quiet);
  ASSERT_FALSE(r.divergence);
  EXPECT_TRUE(r.sew.reached);
  EXPECT_TRUE(limit_misses(r).empty()) << limits_cell(r);
  EXPECT_NE(config_text(s).find("garment.fit = \"skirt\""), std::string::npos) << config_text(s);
}

// a sewing that stops closing: the tall MakeHuman body's drafted shirt with sleeves (size M, 800 vertices), whose
// armpit pair, where a sleeve's corners meet the front's and the back's, the limit holds about 4 mm apart; once the
// widest gap has not narrowed for stop.settle_window_s, every pair being within twice merge_distance, they merge, and
// the shirt is sewn within every limit (before, that pair stayed open to the end of the sew phase's time)
TEST(Runner, ASewingThatStopsClosingIsMerged) {
  RunOptions quiet;
  quiet.progress = false;
  const Scene s = load_scene(std::string(CLOTHBENCH_SOURCE_DIR) + "/scenes/dressing/shirt.toml",
                             {"body.file=data:body/mh_female_tall.obj", "garment.file=", "garment.fit=shirt_sleeves",
                              "garment.size=M", "garment.vertices=800", "solver.face_queries=true"});
  const RunResult r = run_scene(s, quiet);
  ASSERT_FALSE(r.divergence);
  EXPECT_TRUE(r.sew.reached);
  EXPECT_TRUE(limit_misses(r).empty()) << limits_cell(r);
}

// an outfit (scenes/dressing/outfit.toml): a dress worn over a shirt with sleeves, the shirt dressed first and the
// dress placed clear of it (garment.layer), the cloth against itself answered twice a step (self_contact_last). Both
// garments are sewn and draped within every body limit, with at most 1 % of the structural springs through the
// cloth; answered once a step, the limit's second pass carries more of them through it. Only a layer set is hashed
RunResult outfit(const std::vector<std::string>& sets) {
  RunOptions quiet;
  quiet.progress = false;
  return run_scene(load_scene(std::string(CLOTHBENCH_SOURCE_DIR) + "/scenes/dressing/outfit.toml", sets), quiet);
}

TEST(Runner, AnOutfitIsDressedInnerFirstWithTheClothKeptOutOfItself) {
  if (!std::filesystem::exists(kDebianHumanBody)) GTEST_SKIP() << "assimp-testmodels not installed";
  const RunResult r = outfit({});
  ASSERT_FALSE(r.divergence);
  EXPECT_TRUE(r.sew.reached);
  EXPECT_TRUE(r.drape.reached);
  EXPECT_TRUE(limit_misses(r).empty()) << limits_cell(r);
  EXPECT_LE(r.accuracy.cloth_crossings_pct, 1.0);
  EXPECT_GT(r.vertices, 1500);  // both garments
  const RunResult once = outfit({"solver.self_contact_last=false"});
  EXPECT_GT(once.accuracy.cloth_crossings_pct, 2 * r.accuracy.cloth_crossings_pct);
  const std::string scene = std::string(CLOTHBENCH_SOURCE_DIR) + "/scenes/dressing/outfit.toml";
  EXPECT_NE(config_text(load_scene(scene)).find("garment.layer = 1"), std::string::npos);
  EXPECT_EQ(config_text(load_scene(scene, {"garment.layer=0"})).find("garment.layer"), std::string::npos);
  EXPECT_THROW(load_scene(scene, {"garment.layer=17"}), InputError);
  EXPECT_THROW(load_scene(scene, {"garment.layer=-1"}), InputError);
}

// collider.cloth_under: the dress answered against the maps of the shirt under it (the CPU rasteriser's, six views)
// keeps its springs out of the shirt as the cloth against itself in object space does, within every body limit;
// without any, more than 5 % cross. An object-space collider there, a skin as thick as the hit distance, are bad
// input; only the keys set are hashed
TEST(Runner, AnOuterLayerIsKeptOutOfTheMapsOfTheClothUnderIt) {
  if (!std::filesystem::exists(kDebianHumanBody)) GTEST_SKIP() << "assimp-testmodels not installed";
  const std::vector<std::string> none{"solver.self_contact_mm=0", "solver.self_contact_last=false"};
  std::vector<std::string> image = none;
  image.insert(image.end(), {"collider.cloth_under=is-cpu", "collider.cloth_skin_mm=3", "collider.views=6"});
  const RunResult r = outfit(image);
  ASSERT_FALSE(r.divergence);
  EXPECT_TRUE(limit_misses(r).empty()) << limits_cell(r);
  EXPECT_LE(r.accuracy.cloth_crossings_pct, 1.0);
  EXPECT_GT(r.cloth_ms_per_iteration(), 0);
  EXPECT_GT(outfit(none).accuracy.cloth_crossings_pct, 5.0);
  const std::string scene = std::string(CLOTHBENCH_SOURCE_DIR) + "/scenes/dressing/outfit.toml";
  EXPECT_THROW(load_scene(scene, {"collider.cloth_under=is-cpu", "collider.cloth_skin_mm=5"}), InputError);
  EXPECT_THROW(outfit({"collider.cloth_under=embree"}), InputError);
  EXPECT_EQ(config_text(load_scene(scene)).find("cloth_"), std::string::npos);
  EXPECT_NE(config_text(load_scene(scene, image)).find("collider.cloth_under = \"is-cpu\""), std::string::npos);
}

// body.scale: a body the project has not seen, the walking body 1.15 times as broad and deep, gets a fitted shirt (at
// the scene's 400 vertices, with face queries: without, 1.5 % of its springs cross the bust and shoulder blades)
// that sews and meets every limit; its final body is the scaled one; a scale outside [0.2, 5], or of a sphere, is
// bad input
TEST(Runner, AFittedShirtDressesABodyScaledAcross) {
  RunOptions quiet;
  quiet.progress = false;
  const std::string scene = std::string(CLOTHBENCH_SOURCE_DIR) + "/scenes/dressing/shirt.toml";
  const std::vector<std::string> sets{"body.file=data:body/mh_female_walk_rest.obj",
                                      "garment.file=", "garment.fit=shirt", "solver.face_queries=true"};
  std::vector<std::string> one_step = sets;
  one_step.push_back("stop.max_iterations=1");
  const RunResult plain = run_scene(load_scene(scene, one_step), quiet);
  std::vector<std::string> broad = sets;
  broad.push_back("body.scale=[1.15, 1, 1.15]");
  const Scene s = load_scene(scene, broad);
  const RunResult r = run_scene(s, quiet);
  ASSERT_FALSE(r.divergence);
  EXPECT_TRUE(r.sew.reached);
  EXPECT_TRUE(limit_misses(r).empty()) << limits_cell(r);
  const Vec3 a = bounding_box(plain.final_body.positions).size(), b = bounding_box(r.final_body.positions).size();
  EXPECT_NEAR(b.x() / a.x(), 1.15, 1e-4);
  EXPECT_NEAR(b.y() / a.y(), 1.0, 1e-4);
  EXPECT_NEAR(b.z() / a.z(), 1.15, 1e-4);
  EXPECT_NE(config_text(s).find("body.scale = [1.1499999"), std::string::npos) << config_text(s);
  EXPECT_EQ(config_text(load_scene(scene, sets)).find("body.scale"), std::string::npos);  // unset: not hashed
  Scene tiny = load_scene(scene, sets);
  tiny.body.scale = Vec3(0.1f, 1, 1);
  EXPECT_THROW(run_scene(tiny, quiet), InputError);
  Scene sphere = small_tablecloth();
  sphere.body.scale = Vec3(2, 2, 2);
  EXPECT_THROW(run_scene(sphere, quiet), InputError);
}

// a garment dressed on a walking body's pose mid-stride: the body stands still while it is sewn and draped,
// so the cloth settles on it (given the clip's velocity at that pose, the contacts dragged it along and it
// never settled). One limit pass, once a step: the cloth stretches round the open stride while it is sewn (the
// walking scenes' 16 passes after the response hold it at its limit and the side seam stays open). No skin: with the
// scene's 4.5 mm answered while dressing, that one pass leaves the drape hopping off the skin unsettled
TEST(Runner, AWalkingBodyStandsStillWhileTheGarmentIsDressedOnIt) {
  RunOptions quiet;
  quiet.progress = false;
  const RunResult r =
      run_scene(load_scene(std::string(CLOTHBENCH_SOURCE_DIR) + "/scenes/walking/skirt.toml",
                           {"garment.vertices=200", "collider.name=embree", "collider.dress_with=embree",
                            "body.dress_at_s=1.5", "body.start_s=1.5", "body.end_s=1.55", "solver.limit_passes=1",
                            "solver.limit_after_response=false", "body.skin_mm=0"}),
                quiet);
  ASSERT_FALSE(r.divergence) << r.divergence->reason;
  EXPECT_TRUE(r.drape.reached);
  EXPECT_LT(r.window_seam_gap_mm, 10.0);  // 105 mm when the contacts dragged the cloth along
  std::printf("[ dressed ] mid-stride skirt: sew %ld + drape %ld iterations, seam gap %.2f mm at the window\n",
              r.sew.iterations, r.drape.iterations, r.window_seam_gap_mm);
}

// 0.2 s of the walking skirt (200 vertices) with is-cpu, `more` set on top
RunResult short_skirt_walk(const std::vector<std::string>& more) {
  RunOptions quiet;
  quiet.progress = false;
  std::vector<std::string> sets{"garment.vertices=200", "collider.name=is-cpu", "body.end_s=1.2"};
  sets.insert(sets.end(), more.begin(), more.end());
  return run_scene(load_scene(std::string(CLOTHBENCH_SOURCE_DIR) + "/scenes/walking/skirt.toml", sets), quiet);
}

// two runs ended with the cloth in the same place, bit for bit
void expect_same_cloth(const RunResult& a, const RunResult& b) {
  ASSERT_EQ(a.mesh.positions.size(), b.mesh.positions.size());
  EXPECT_EQ(0, std::memcmp(a.mesh.positions.data(), b.mesh.positions.data(), sizeof(Real) * a.mesh.positions.size()));
}

// image space on a moving body draws only the map rows the cloth's box (grown by collider.query_margin_mm) spans:
// the run is the one with every row drawn, bit for bit, and the maps cost less
TEST(Runner, MapsOfTheRowsTheClothSpansGiveTheSameRun) {
  const RunResult rows = short_skirt_walk({"collider.dress_with=embree", "collider.query_margin_mm=100"});
  const RunResult every = short_skirt_walk({"collider.dress_with=embree", "collider.query_margin_mm=0"});
  ASSERT_FALSE(rows.divergence);
  expect_same_cloth(rows, every);
  std::printf("[ rows ] skirt, is-cpu maps per frame: %.2f ms with the cloth's rows, %.2f ms with every row\n",
              rows.collider_update_ms / double(rows.frames), every.collider_update_ms / double(every.frames));
}

// body.pose_fps: the body posed (the collider updated) that often, the frame's steps shared among the poses; posed
// once per frame it is the run of pose_fps = 0 bit for bit, posed more often the cloth meets it at other times
TEST(Runner, PosingTheBodyMoreOftenSharesTheFramesStepsAmongThePoses) {
  RunOptions quiet;
  quiet.progress = false;
  const auto run = [&](double pose_fps) {
    Scene s = small_tablecloth();
    s.body.pose_fps = pose_fps;
    s.body.velocity = Vec3(0, 3, 0);  // thrust up through the cloth: its contacts move with the poses
    return run_scene(s, quiet);
  };
  const RunResult unset = run(0), once = run(60), thrice = run(180);
  ASSERT_FALSE(unset.divergence || once.divergence || thrice.divergence);
  EXPECT_EQ(unset.collider_updates, unset.frames);
  EXPECT_EQ(thrice.collider_updates, 3 * thrice.frames);
  EXPECT_EQ(thrice.frames, unset.frames);
  EXPECT_EQ(thrice.steps_per_frame, unset.steps_per_frame);
  EXPECT_EQ(thrice.animate.iterations, unset.animate.iterations);
  expect_same_cloth(once, unset);
  EXPECT_NE(0, std::memcmp(thrice.mesh.positions.data(), unset.mesh.positions.data(),
                           sizeof(Real) * unset.mesh.positions.size()));
  EXPECT_EQ(result_row(thrice, "sphere").at("poses_per_frame").get<double>(), 3.0);
}

// body.prepare_ahead: the next frame skinned and its maps drawn on a second thread while the cloth steps through this
// one; the same run bit for bit (lead-in and measured window), and the run says it used the second thread
TEST(Runner, FramesPreparedAheadGiveTheSameRun) {
  const RunResult ahead = short_skirt_walk({"body.prepare_ahead=true"});
  const RunResult serial = short_skirt_walk({"body.prepare_ahead=false"});
  ASSERT_FALSE(ahead.divergence);
  EXPECT_EQ(serial.frames - 1, ahead.prepared_frames);  // every measured frame but the first
  EXPECT_EQ(2, ahead.threads);
  EXPECT_EQ(0, serial.prepared_frames);
  EXPECT_EQ(1, serial.threads);
  expect_same_cloth(ahead, serial);
  EXPECT_EQ(ahead.final_body.positions, serial.final_body.positions);
  // with the body posed twice a frame (body.pose_fps) the worker prepares each pose
  const RunResult ahead2 = short_skirt_walk({"body.prepare_ahead=true", "body.pose_fps=60"});
  const RunResult serial2 = short_skirt_walk({"body.prepare_ahead=false", "body.pose_fps=60"});
  ASSERT_FALSE(ahead2.divergence);
  EXPECT_EQ(2 * serial2.frames, serial2.collider_updates);
  expect_same_cloth(ahead2, serial2);
}

// a garment placed half inside the body is named on stderr before anything runs; the shipped placement is not
TEST(Runner, AGarmentPlacedInsideTheBodyIsWarnedAbout) {
  const std::string src = CLOTHBENCH_SOURCE_DIR, dir = test::temp_path("inside");
  std::filesystem::create_directories(dir);
  const auto read = [](const std::string& path) {
    std::ifstream in(path);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  };
  // the skirt's panels 2 cm before and behind the torso's axis, not wrapped round it
  const std::string pattern =
      std::regex_replace(read(src + "/scenes/garments/skirt.pattern"),
                         std::regex("offset 0 0 (-?)20 (yaw 180 )?wrap 20"), "offset 0 0 $012 $2wrap 0");
  std::ofstream(dir + "/inside.pattern") << pattern;
  std::ofstream(dir + "/inside.toml") << std::regex_replace(
      read(src + "/scenes/dressing/skirt.toml"), std::regex("garments/skirt\\.pattern"), dir + "/inside.pattern");
  RunOptions estimate;
  estimate.progress = false;
  estimate.estimate_only = true;
  testing::internal::CaptureStderr();
  run_scene(load_scene(dir + "/inside.toml", {}), estimate);
  const std::string warned = testing::internal::GetCapturedStderr();
  EXPECT_NE(warned.find("inside the body"), std::string::npos) << warned;
  testing::internal::CaptureStderr();
  run_scene(load_scene(src + "/scenes/dressing/skirt.toml", {}), estimate);
  const std::string shipped = testing::internal::GetCapturedStderr();
  EXPECT_EQ(shipped.find("inside the body"), std::string::npos) << shipped;
}

// is-egl keeps its maps on its device and answers there: on one device the same run twice, bit for bit, with the
// next frame's maps drawn on a second thread (its second context) and with every map row drawn too
TEST(Runner, IsEglGivesTheSameRunOnOneDevice) {
  const auto built = available_colliders();
  if (std::find(built.begin(), built.end(), "is-egl") == built.end()) GTEST_SKIP() << "is-egl is not built";
  RunResult first;
  try {
    first = short_skirt_walk({"collider.name=is-egl"});
  } catch (const std::runtime_error& e) {
    GTEST_SKIP() << "no EGL context: " << e.what();
  }
  ASSERT_FALSE(first.divergence);
  EXPECT_NE(first.device.find("EGL"), std::string::npos) << first.device;
  expect_same_cloth(first, short_skirt_walk({"collider.name=is-egl"}));
  const RunResult ahead = short_skirt_walk({"collider.name=is-egl", "body.prepare_ahead=true"});
  EXPECT_EQ(first.frames - 1, ahead.prepared_frames);
  expect_same_cloth(first, ahead);
  expect_same_cloth(first, short_skirt_walk({"collider.name=is-egl", "collider.query_margin_mm=0"}));
  EXPECT_GT(first.collider_queries, first.frames);
}

// body.collision_triangles: the colliders see a simplified copy of the body, the oracle and the pictures the exact
// one; the run says how far the copy is from it
TEST(Runner, ACollisionProxyIsWhatTheCollidersSeeNotWhatTheOracleMeasures) {
  const RunResult exact = short_skirt_walk({});
  const RunResult proxy = short_skirt_walk({"body.collision_triangles=6000"});
  ASSERT_FALSE(proxy.divergence);
  EXPECT_EQ(0, exact.collision_triangles);
  EXPECT_EQ(0, exact.proxy_deviation_mm);
  EXPECT_GT(proxy.collision_triangles, 5000);
  EXPECT_LE(proxy.collision_triangles, 6000);
  EXPECT_GT(proxy.proxy_deviation_mm, 0.1);  // the exact body's vertices are off the coarse surface ...
  EXPECT_LT(proxy.proxy_deviation_mm, 10);   // ... by millimetres
  EXPECT_EQ(proxy.body_triangles, exact.body_triangles);
  EXPECT_EQ(proxy.final_body.triangles.cols(), exact.body_triangles);  // the oracle's body
  EXPECT_EQ(proxy.final_body.positions, exact.final_body.positions);
  std::printf("[ proxy ] skirt, is-cpu maps per frame: %.2f ms of the exact body, %.2f ms of %ld triangles (%.2f mm)\n",
              exact.collider_update_ms / double(exact.frames), proxy.collider_update_ms / double(proxy.frames),
              proxy.collision_triangles, proxy.proxy_deviation_mm);
  Scene sphere = small_tablecloth();
  sphere.body.collision_triangles = 100;
  EXPECT_THROW(run_scene(sphere, {}), InputError);
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

namespace clothbench {
namespace {

// The body between frames. A sphere of radius 0.25 m moving at 1 m/s along +x, posed at a frame's end;
// a point 1 cm inside its leading side was 1 cm outside it 20 ms earlier, and the wrapper says so
TEST(BodyBetweenFrames, AStepBeforeThePoseSeesTheBodyWhereItWasThen) {
  SphereCollider sphere(Vec3::Zero(), 0.25f);
  sphere.set_sphere(Vec3::Zero(), Vec3(1, 0, 0));
  BodyBetweenFrames between(sphere, 0.005f);
  Points3 p(3, 2);
  p.col(0) = Vec3(0.24f, 0, 0);   // leading side: the surface moves outward, toward it
  p.col(1) = Vec3(-0.24f, 0, 0);  // trailing side: the surface retreats from it
  std::vector<Contact> c(2);
  between.query(PointsView(p), {c.data(), c.size()});  // tau = 0: the pose itself
  ASSERT_TRUE(c[0].hit);
  EXPECT_NEAR(c[0].depth, -0.01f, 1e-5f);
  between.set_time_before_pose(0.02f);
  between.query(PointsView(p), {c.data(), c.size()});
  EXPECT_FALSE(c[0].hit);  // not yet reached: d + (n . v) tau = -0.01 + 0.02
  EXPECT_NEAR(c[0].depth, 0.01f, 1e-5f);
  ASSERT_TRUE(c[1].hit);  // the retreating side held the point deeper then
  EXPECT_NEAR(c[1].depth, -0.03f, 1e-5f);
  EXPECT_EQ(between.name(), "sphere");
}

// the skin: a moving body answered 4 mm thicker holds a point resting 2 mm outside it as 2 mm inside
TEST(BodyBetweenFrames, TheSkinMakesTheBodyThicker) {
  SphereCollider sphere(Vec3::Zero(), 0.25f);
  BodyBetweenFrames between(sphere, 0.005f, 0.004f);
  Points3 p(3, 2);
  p.col(0) = Vec3(0.252f, 0, 0);  // 2 mm outside
  p.col(1) = Vec3(0.256f, 0, 0);  // 6 mm outside: beyond tol, not a contact at all
  std::vector<Contact> c(2);
  between.query(PointsView(p), {c.data(), c.size()});
  ASSERT_TRUE(c[0].hit);
  EXPECT_NEAR(c[0].depth, -0.002f, 1e-5f);
  EXPECT_FALSE(c[1].hit);
}

}  // namespace
}  // namespace clothbench
