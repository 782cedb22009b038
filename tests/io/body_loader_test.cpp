// Bodies through assimp: the walking body of scenes/data, Debian's human.zae, skinning, velocities, bad input.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>

#include "clothbench/config.h"
#include "clothbench/io/body_loader.hpp"
#include "clothbench/io/data_root.hpp"
#include "clothbench/io/errors.hpp"
#include "test_support.hpp"

namespace clothbench {
namespace {

const std::string kBad = std::string(CLOTHBENCH_SOURCE_DIR) + "/tests/data/bad/";

std::string walking_body() {
  const std::string path = data_path("body/mh_female_walk.glb");
  return std::filesystem::exists(path) ? path : "";
}

#define REQUIRE_WALKING_BODY(path)         \
  const std::string path = walking_body(); \
  if (path.empty()) GTEST_SKIP() << "walking body absent from the data root (" << data_root() << ")"

// largest distance from a vertex of `a` to the nearest vertex of `b` [m] (order-free comparison)
double max_nearest_distance(const Points3& a, const Points3& b) {
  double worst = 0;
  for (Eigen::Index i = 0; i < a.cols(); ++i)
    worst = std::max(worst, double((b.colwise() - a.col(i)).colwise().squaredNorm().minCoeff()));
  return std::sqrt(worst);
}

// mean of the vertices in the hip band of the rest pose (|x| < 0.2 m leaves out the A-pose hands)
Vec3 hip_centre(const BodyFrame& rest, const BodyFrame& frame) {
  Vec3 sum = Vec3::Zero();
  int n = 0;
  for (Eigen::Index v = 0; v < rest.positions.cols(); ++v)
    if (rest.positions(1, v) > 0.85f && rest.positions(1, v) < 1.0f && std::abs(rest.positions(0, v)) < 0.2f) {
      sum += frame.positions.col(v);
      ++n;
    }
  return sum / Real(n);
}

TEST(BodyLoader, WalkingBodyCountsClosedAndHeight) {
  REQUIRE_WALKING_BODY(path);
  const BodyModel body = load_body(path);
  EXPECT_EQ(body.rest().positions.cols(), 13380);
  EXPECT_EQ(body.rest().triangles.cols(), 26756);
  EXPECT_TRUE(check_edges(body.rest().triangles).closed());
  const Box3 box = bounding_box(body.rest().positions);
  EXPECT_NEAR(box.size().y(), 1.65, 0.01);
  EXPECT_NEAR(box.min.y(), 0.0, 1e-6);
  EXPECT_GT(box.max.z(), -box.min.z()) << "the body faces +Z (breasts, nose in front)";
  EXPECT_EQ(body.bone_count(), 31);
  ASSERT_EQ(body.animations().size(), 2u);
  EXPECT_EQ(body.animations()[0].name, "walk_07_01");
  EXPECT_NEAR(body.animations()[0].duration_s, 3.617, 0.01);
  EXPECT_EQ(body.dropped_parts(), 0);
}

// the shipped rest body written again with its vertices mapped by f (x, y, z -> new x, y, z)
std::string rewritten_body(const std::string& name, const std::function<Vec3(const Vec3&)>& f) {
  std::ifstream in(data_path("body/mh_female_walk_rest.obj"));
  const std::string out = test::temp_path(name + ".obj");
  std::ofstream o(out);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("v ", 0) == 0) {
      std::istringstream v(line.substr(2));
      Vec3 p;
      v >> p.x() >> p.y() >> p.z();
      const Vec3 q = f(p);
      o << "v " << q.x() << " " << q.y() << " " << q.z() << "\n";
    } else {
      o << line << "\n";
    }
  }
  return out;
}

bool has_note(const BodyModel& body, const std::string& part) {
  for (const std::string& n : body.notes())
    if (n.find(part) != std::string::npos) return true;
  return false;
}

// what loading changed is said, and a body turned away from +Z is warned about, not silently used
TEST(BodyLoader, NotesSayWhatNormalisationChangedAndWarnOfAnotherFacing) {
  if (!std::filesystem::exists(data_path("body/mh_female_walk_rest.obj"))) GTEST_SKIP() << "no rest body";
  const BodyModel as_is = load_body(data_path("body/mh_female_walk_rest.obj"));
  EXPECT_FALSE(has_note(as_is, "warning")) << ::testing::PrintToString(as_is.notes());
  const BodyModel z_up_cm =
      load_body(rewritten_body("z_up_cm", [](const Vec3& p) -> Vec3 { return Vec3(p.x(), -p.z(), p.y()) * 100; }));
  EXPECT_TRUE(has_note(z_up_cm, "turned +Y up")) << ::testing::PrintToString(z_up_cm.notes());
  EXPECT_TRUE(has_note(z_up_cm, "scaled by")) << ::testing::PrintToString(z_up_cm.notes());
  EXPECT_FALSE(has_note(z_up_cm, "warning")) << ::testing::PrintToString(z_up_cm.notes());
  const BodyModel side =
      load_body(rewritten_body("facing_x", [](const Vec3& p) -> Vec3 { return Vec3(p.z(), p.y(), -p.x()); }));
  EXPECT_TRUE(has_note(side, "may face +-X")) << ::testing::PrintToString(side.notes());
  const BodyModel back =
      load_body(rewritten_body("facing_back", [](const Vec3& p) -> Vec3 { return Vec3(-p.x(), p.y(), -p.z()); }));
  EXPECT_TRUE(has_note(back, "may face -Z")) << ::testing::PrintToString(back.notes());
}

TEST(BodyLoader, PoseAtZeroEqualsRestObj) {
  REQUIRE_WALKING_BODY(path);
  const BodyModel body = load_body(path);
  const BodyModel obj = load_body(data_path("body/mh_female_walk_rest.obj"));
  const BodyFrame f0 = body.frame(body.animation_index("walk_07_01"), 0.0);
  EXPECT_LT(max_nearest_distance(f0.positions, obj.rest().positions), 1e-3);
  EXPECT_LT((f0.positions - body.rest().positions).cwiseAbs().maxCoeff(), 1e-3);
}

TEST(BodyLoader, VelocitiesMatchCentralDifference) {
  REQUIRE_WALKING_BODY(path);
  const BodyModel body = load_body(path);
  const int a = body.animation_index("walk_07_01");
  const double t = 2.0, h = 1e-3;
  const BodyFrame f = body.frame(a, t), lo = body.frame(a, t - h), hi = body.frame(a, t + h);
  const Points3 diff = (hi.positions - lo.positions) / Real(2 * h);
  const Real vmax = f.velocities.colwise().norm().maxCoeff();
  EXPECT_GT(vmax, 0.5f) << "a walking body moves";
  EXPECT_LT((diff - f.velocities).colwise().norm().maxCoeff(), 0.02f * vmax);
  EXPECT_TRUE(f.moving);
  EXPECT_TRUE(check_edges(f.triangles).closed());
}

TEST(BodyLoader, WalkInPlaceKeepsHips) {
  REQUIRE_WALKING_BODY(path);
  const BodyModel body = load_body(path);
  const int a = body.animation_index("walk_07_01");
  const Vec3 start = hip_centre(body.rest(), body.frame(a, 0.0, true));
  double worst = 0, travelled = 0;
  for (double t = 0; t <= body.animations()[a].duration_s; t += 0.1) {
    const Vec3 d = hip_centre(body.rest(), body.frame(a, t, true)) - start;
    const Vec3 free = hip_centre(body.rest(), body.frame(a, t, false)) - start;
    worst = std::max(worst, double(Eigen::Vector2f(d.x(), d.z()).norm()));
    travelled = std::max(travelled, double(Eigen::Vector2f(free.x(), free.z()).norm()));
  }
  EXPECT_LT(worst, 0.05);
  EXPECT_GT(travelled, 2.0) << "without walk-in-place the body crosses the room";
}

TEST(BodyLoader, DebianHumanLoadsClosedAfterDroppingEyes) {
  if (!std::filesystem::exists(kDebianHumanBody)) GTEST_SKIP() << "assimp-testmodels not installed";
  const BodyModel body = load_body(kDebianHumanBody);
  EXPECT_TRUE(check_edges(body.rest().triangles).closed());
  EXPECT_GT(body.dropped_parts(), 0) << "human.zae has open eye parts";
  EXPECT_NEAR(bounding_box(body.rest().positions).size().y(), 1.66, 0.05);
  EXPECT_EQ(body.bone_count(), 0);
  EXPECT_TRUE(body.animations().empty());
}

// the message must name the file and say what is wrong
void expect_input_error(const std::string& path, const std::string& what, BodyLoadOptions options = {}) {
  try {
    load_body(path, options);
    FAIL() << path << " loaded without error";
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find(path), std::string::npos) << msg;
    EXPECT_NE(msg.find(what), std::string::npos) << msg;
  }
}

// body.collision_triangles: the simplified copy keeps some of the body's own vertices, skinned as the body skins them
TEST(BodyLoader, SimplifiedBodyKeepsItsVerticesAndSkin) {
  REQUIRE_WALKING_BODY(path);
  const BodyModel body = load_body(path);
  const BodyModel proxy = body.simplified(8000);
  const Eigen::Index tris = proxy.rest().triangles.cols();
  EXPECT_LE(tris, 8000);
  EXPECT_GT(tris, 7000);
  EXPECT_TRUE(check_edges(proxy.rest().triangles).closed());
  EXPECT_LT(proxy.rest().positions.cols(), body.rest().positions.cols() / 2);
  // each kept vertex is one of the body's, in every frame (its skin came with it)
  const int walk = body.animation_index("walk_07_01");
  for (const double t : {0.0, 1.7}) {
    const BodyFrame full = body.frame(walk, t, true), coarse = proxy.frame(walk, t, true);
    EXPECT_LT(max_nearest_distance(coarse.positions, full.positions), 1e-6) << "t = " << t;
    EXPECT_EQ(coarse.triangles.cols(), tris);
  }
  for (const int bad : {0, -5, 26756, 40000}) EXPECT_THROW(body.simplified(bad), InputError) << bad;
}

TEST(BodyLoader, BadFilesGiveClearErrors) {
  expect_input_error(kBad + "does_not_exist.obj", "not found");
  expect_input_error(kBad + "body_text_renamed.obj", "");
  expect_input_error(kBad + "body_empty.obj", "");
  expect_input_error(kBad + "body_junk.glb", "");
  expect_input_error(kBad + "body_open.obj", "4 boundary edges");
  expect_input_error(kBad + "body_nan.obj", "");
  BodyLoadOptions open_ok;
  open_ok.require_closed = false;  // assimp would draw the bones as a closed 42-vertex mesh
  expect_input_error(kBad + "body_skeleton_only.bvh", "contains no meshes", open_ok);
  EXPECT_EQ(load_body(kBad + "body_open.obj", open_ok).rest().triangles.cols(), 2);
}

// files on which Debian's assimp (5.2) crashes or loops (fuzz/assimp-findings): a clear error, and
// the test process survives
const std::string kAssimpFindings = std::string(CLOTHBENCH_SOURCE_DIR) + "/fuzz/assimp-findings/";

TEST(BodyLoader, AssimpCrashesAndHangsBecomeErrors) {
  BodyLoadOptions quick;
  quick.isolate_timeout_s = 3;
  expect_input_error(kAssimpFindings + "skin_without_inverse_bind_matrices.glb", "assimp crashed", quick);
  expect_input_error(kAssimpFindings + "ply_more_faces_declared_than_given.ply", "assimp crashed", quick);
  expect_input_error(kAssimpFindings + "ply_header_without_end_header.ply", "did not finish reading it within 3 s",
                     quick);
}

TEST(BodyLoader, NonFiniteAnimationKeysAreRejected) {
  BodyLoadOptions open_ok;
  open_ok.require_closed = false;
  expect_input_error(kBad + "body_nan_animation_key.gltf", "non-finite key", open_ok);
}

TEST(BodyLoader, BadAnimationOrTime) {
  REQUIRE_WALKING_BODY(path);
  const BodyModel body = load_body(path);
  EXPECT_THROW(body.animation_index("moonwalk"), InputError);
  EXPECT_THROW(body.frame(0, -0.1), InputError);
  EXPECT_THROW(body.frame(0, 100.0), InputError);
  EXPECT_THROW(body.frame(7, 1.0), InputError);
}

// the CLI maps every bad input to exit code 2
TEST(BodyCommand, ExitCodes) {
  const char* bin = std::getenv("CLOTHBENCH_BIN");
  if (!bin || !std::filesystem::exists(bin)) GTEST_SKIP() << "CLOTHBENCH_BIN not set";
  const auto run = [&](const std::string& args) {
    const int rc = std::system((std::string(bin) + " body " + args + " > /dev/null 2>&1").c_str());
    return WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
  };
  EXPECT_EQ(run(kBad + "body_open.obj"), 2);
  EXPECT_EQ(run(kBad + "body_junk.glb"), 2);
  EXPECT_EQ(run(kBad + "missing.glb"), 2);
  EXPECT_EQ(run(kAssimpFindings + "skin_without_inverse_bind_matrices.glb"), 2);
  EXPECT_EQ(run(kAssimpFindings + "ply_more_faces_declared_than_given.ply"), 2);
  EXPECT_EQ(run(kBad + "body_open.obj --open-ok --json"), 0);
  const std::string walk = walking_body();
  if (walk.empty()) return;
  EXPECT_EQ(run(walk + " --animation nope --at 1"), 2);
  EXPECT_EQ(run(walk + " --animation walk_07_01 --at 99"), 2);
  EXPECT_EQ(run(walk + " --animation walk_07_01 --at 2 --json"), 0);
}

// "data:REL" names a file under the data root, for the CLI as for scenes; a missing one names the root
TEST(BodyLoader, DataReferencesResolveUnderTheDataRoot) {
  EXPECT_EQ(load_body("data:body/mh_female_walk_rest.obj").rest().positions.cols(),
            load_body(data_path("body/mh_female_walk_rest.obj")).rest().positions.cols());
  try {
    load_body("data:body/nobody.glb");
    FAIL() << "no error for a missing data file";
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find(data_root()), std::string::npos) << msg;
    EXPECT_NE(msg.find("CLOTHBENCH_DATA"), std::string::npos) << msg;
  }
}

// the repository ships its data: a clone with nothing beside it has the walking body
TEST(BodyLoader, TheRepositoryShipsTheWalkingBody) {
  EXPECT_TRUE(std::filesystem::exists(std::string(CLOTHBENCH_SOURCE_DIR) + "/scenes/data/body/mh_female_walk.glb"));
  EXPECT_TRUE(std::filesystem::exists(std::string(CLOTHBENCH_SOURCE_DIR) + "/scenes/data/LICENSES.txt"));
}

}  // namespace
}  // namespace clothbench
