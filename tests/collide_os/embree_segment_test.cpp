// EmbreeDistance::segment_crossings (one occlusion ray per segment) against every triangle.
#include <gtest/gtest.h>

#include <filesystem>
#include <limits>
#include <random>
#include <vector>

#include "clothbench/bench/oracle.hpp"
#include "clothbench/collide_os/embree_distance.hpp"
#include "clothbench/io/body_loader.hpp"
#include "clothbench/io/data_root.hpp"
#include "surface_points.hpp"

namespace clothbench {
namespace {

// does the segment meet any triangle: every triangle tried
bool brute_crosses(const BodyFrame& body, const Vec3& a, const Vec3& b) {
  for (int t = 0; t < body.triangle_count(); ++t)
    if (segment_crosses_triangle(a, b, body.positions.col(body.triangles(0, t)),
                                 body.positions.col(body.triangles(1, t)), body.positions.col(body.triangles(2, t))))
      return true;
  return false;
}

struct Segments {
  Points3 ends;  // 2 per segment (3 x 2n) [m]
  Pairs pairs;   // (2k, 2k + 1)
};

// segments up to 6 cm long around points near the surface, random directions, fixed seed
Segments random_segments(const BodyFrame& body, int count, unsigned seed) {
  const Points3 centres = test::surface_points(body, count, seed);
  std::mt19937 rng(seed + 1);
  std::normal_distribution<Real> gauss(0, 1);
  std::uniform_real_distribution<Real> length(0, 0.06f);
  Segments s{Points3(3, 2 * count), Pairs(2, count)};
  for (int k = 0; k < count; ++k) {
    const Vec3 half = 0.5f * length(rng) * Vec3(gauss(rng), gauss(rng), gauss(rng)).normalized();
    s.ends.col(2 * k) = Vec3(centres.col(k)) - half;
    s.ends.col(2 * k + 1) = Vec3(centres.col(k)) + half;
    s.pairs.col(k) << 2 * k, 2 * k + 1;
  }
  return s;
}

// compares with the brute-force answer where it is robust: unchanged when both ends move 1 um
void expect_agreement(const EmbreeDistance& embree, const BodyFrame& body, const Segments& s) {
  std::vector<std::uint8_t> crosses(std::size_t(s.pairs.cols()));
  embree.segment_crossings(s.ends, s.pairs, crosses.data());
  const Vec3 nudge = Vec3(1, -1, 1) * 1e-6f;
  int compared = 0, crossing = 0;
  for (Eigen::Index k = 0; k < s.pairs.cols(); ++k) {
    const Vec3 a = s.ends.col(2 * k), b = s.ends.col(2 * k + 1);
    const bool expected = brute_crosses(body, a, b);
    if (brute_crosses(body, a + nudge, b - nudge) != expected || brute_crosses(body, a - nudge, b + nudge) != expected)
      continue;
    ++compared;
    crossing += expected ? 1 : 0;
    EXPECT_EQ(crosses[std::size_t(k)] != 0, expected)
        << "segment " << k << ": " << a.transpose() << " -> " << b.transpose();
  }
  // nearly every segment is robust, and a fair share of them cross
  EXPECT_GT(compared, 0.99 * double(s.pairs.cols()));
  EXPECT_GT(crossing, s.pairs.cols() / 5);
  EXPECT_LT(crossing, 4 * s.pairs.cols() / 5);
}

TEST(EmbreeSegments, AgreeWithEveryTriangleOnACapsule) {
  const BodyFrame body = make_capsule_body(Vec3(0, 1, 0), 0.1f, 0.4f);
  EmbreeDistance embree;
  embree.set_body(body);
  expect_agreement(embree, body, random_segments(body, 3000, 5));
}

TEST(EmbreeSegments, FollowARefittedBody) {
  // the body is stretched sideways after set_body: the refitted BVH answers for the new frame
  const BodyFrame body = make_capsule_body(Vec3(0, 1, 0), 0.1f, 0.4f);
  EmbreeDistance embree;
  embree.set_body(body);
  BodyFrame wide = body;
  wide.positions.row(0) *= 1.3f;
  embree.update_body(wide);
  expect_agreement(embree, wide, random_segments(wide, 3000, 6));
}

TEST(EmbreeSegments, AgreeWithEveryTriangleOnTheWalkingBody) {
  // thin fingers and 26,756 triangles; a frame of the walk, refitted from the rest pose
  const std::string path = data_path("body/mh_female_walk.glb");
  if (!std::filesystem::exists(path))
    GTEST_SKIP() << "data root absent: " << path << " not found (set CLOTHBENCH_DATA)";
  const BodyModel model = load_body(path);
  const BodyFrame walk = model.frame(model.animation_index("walk_07_01"), 2.0);
  EmbreeDistance embree;
  embree.set_body(model.rest());
  embree.update_body(walk);
  expect_agreement(embree, walk, random_segments(walk, 400, 7));
}

TEST(EmbreeSegments, NothingBeforeABodyAndForNonFiniteEnds) {
  Points3 ends(3, 2);
  ends << Vec3(0, -1, 0), Vec3(0, 3, 0);
  Pairs pairs(2, 1);
  pairs << 0, 1;
  std::uint8_t crosses = 7;
  EmbreeDistance embree;
  embree.segment_crossings(ends, pairs, &crosses);
  EXPECT_EQ(crosses, 0);
  embree.set_body(make_capsule_body(Vec3(0, 1, 0), 0.1f, 0.4f));
  embree.segment_crossings(ends, pairs, &crosses);
  EXPECT_EQ(crosses, 1);  // straight through both caps
  ends(1, 1) = std::numeric_limits<Real>::quiet_NaN();
  embree.segment_crossings(ends, pairs, &crosses);
  EXPECT_EQ(crosses, 0);
}

}  // namespace
}  // namespace clothbench
