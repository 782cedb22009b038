#include "clothbench/collide_is/map_set.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <vector>

#include "is_test_bodies.hpp"
#include "test_support.hpp"

namespace clothbench {
namespace {

// how far two MapSets differ: coverage mismatches and depth differences where both cover
struct MapDiff {
  long coverage_mismatch = 0;
  long covered = 0;
  long identical = 0;     // covered pixels with bit-identical depth
  double depth_max = 0;   // [m]
  double depth_p999 = 0;  // [m]
};

MapDiff compare(const MapSet& a, const MapSet& b) {
  MapDiff d;
  std::vector<double> diffs;
  for (std::size_t i = 0; i < a.z.size(); ++i) {
    const bool ca = a.mask[i] != MapSet::kEmpty, cb = b.mask[i] != MapSet::kEmpty;
    if (ca != cb) ++d.coverage_mismatch;
    if (!ca || !cb) continue;
    ++d.covered;
    d.identical += a.z[i] == b.z[i];
    diffs.push_back(std::abs(static_cast<double>(a.z[i]) - b.z[i]));
  }
  if (diffs.empty()) return d;
  std::sort(diffs.begin(), diffs.end());
  d.depth_max = diffs.back();
  d.depth_p999 = diffs[static_cast<std::size_t>(0.999 * (diffs.size() - 1))];
  return d;
}

ColliderOptions no_side_layer() {
  ColliderOptions o;
  o.side_layer = false;
  return o;
}

TEST(MapFrame, PapersSquareIsBodyHeightFromTheSoles) {
  Box3 box;
  box.min = Vec3(-0.4f, 0.0f, -0.15f);
  box.max = Vec3(0.4f, 1.6f, 0.15f);
  const MapFrame f = make_map_frame(box, ColliderOptions{});
  // dressing Eq. 8: Y = y mapsize / bboxheight, X_front = (x + height / 2) / height mapsize
  EXPECT_FLOAT_EQ(f.pixel, 1.6f / 320);
  EXPECT_FLOAT_EQ(f.map_v(0.8f), 160.0f);
  EXPECT_FLOAT_EQ(f.front_u(0.0f), 160.0f);
  EXPECT_FLOAT_EQ(f.front_u(-0.8f), 0.0f);
  EXPECT_FLOAT_EQ(f.z_max, 0.15f + 0.005f);
}

TEST(MapFrame, FittedSquareHoldsTheWholeBoxAndRejectsTinyMaps) {
  Box3 box;
  box.min = Vec3(-1.0f, 0.0f, -0.1f);
  box.max = Vec3(1.0f, 1.0f, 0.1f);
  ColliderOptions o;
  o.fit_extent = true;
  const MapFrame f = make_map_frame(box, o);
  EXPECT_GT(f.front_u(-1.0f), 0.0f);
  EXPECT_LT(f.front_u(1.0f), static_cast<float>(f.size));
  o.map_size = 4;
  EXPECT_THROW(make_map_frame(box, o), std::invalid_argument);
}

TEST(CpuMaps, SphereDepthAndCoverageMatchTheAnalyticSphere) {
  const Real r = 0.2f;
  const Vec3 c(0.05f, 0.3f, -0.02f);
  const int nlat = 64, nlon = 128;
  const MapSet m = render_maps(make_sphere_body(c, r, nlat, nlon), "cpu", no_side_layer());
  // tessellation error bound: sagitta of one latitude step
  const double sagitta = r * (1 - std::cos(M_PI / nlat));
  const MapFrame& f = m.frame;
  long covered = 0;
  for (int row = 0; row < f.size; ++row) {
    for (int col = 0; col < f.size; ++col) {
      const double x = f.x0 + (col + 0.5) * f.pixel - c.x(), y = f.y0 + (row + 0.5) * f.pixel - c.y();
      const double rho = std::hypot(x, y);
      const std::size_t fi = m.index(MapSet::kFront, col, row), bi = m.index(MapSet::kBack, f.size - 1 - col, row);
      if (rho > r) {
        EXPECT_EQ(m.mask[fi], MapSet::kEmpty) << col << "," << row;
        EXPECT_EQ(m.mask[bi], MapSet::kEmpty) << col << "," << row;
      }
      if (rho > r - 4 * sagitta) continue;
      ++covered;
      ASSERT_EQ(m.mask[fi], MapSet::kBody) << col << "," << row;
      // the flat triangles lie between the spheres of radius r - sagitta and r
      const double h = std::sqrt(r * r - rho * rho);
      const double h_in = std::sqrt((r - sagitta) * (r - sagitta) - rho * rho);
      EXPECT_LE(m.z[fi], c.z() + h + 1e-6) << col << "," << row;
      EXPECT_GE(m.z[fi], c.z() + h_in - 1e-6) << col << "," << row;
      EXPECT_GE(m.z[bi], c.z() - h - 1e-6) << col << "," << row;
      EXPECT_LE(m.z[bi], c.z() - h_in + 1e-6) << col << "," << row;
      EXPECT_LT(test::angle_deg(m.normal_at(fi), Vec3(x, y, h)), 2.0);
    }
  }
  EXPECT_GT(covered, 1000);
}

TEST(CpuMaps, SideLayerAddsOneRingOfPixels) {
  const BodyFrame s = make_sphere_body(Vec3(0, 0.5f, 0), 0.3f);
  ColliderOptions with;
  const MapSet a = render_maps(s, "cpu", no_side_layer());
  const MapSet b = render_maps(s, "cpu", with);
  long body = 0, side = 0;
  for (std::size_t i = 0; i < b.mask.size(); ++i) {
    EXPECT_EQ(a.mask[i] == MapSet::kBody, b.mask[i] == MapSet::kBody);
    body += b.mask[i] == MapSet::kBody;
    side += b.mask[i] == MapSet::kSide;
  }
  // a disc of radius R pixels gains a ring of about 2 pi R pixels (8-neighbour dilation)
  const double radius_px = 0.3 / b.frame.pixel;
  EXPECT_GT(side, 2 * M_PI * radius_px * 0.9 * 2);
  EXPECT_LT(side, 2 * M_PI * radius_px * 1.5 * 2);
  EXPECT_GT(body, 0);
}

TEST(CpuMaps, EightBitEncodingDecodesWithinQuantisation) {
  BodyFrame s = make_sphere_body(Vec3(0, 0.5f, 0), 0.3f);
  s.moving = true;
  for (int v = 0; v < s.vertex_count(); ++v) s.velocities.col(v) = Vec3(1.0f, -0.5f, 2.0f);
  ColliderOptions o = no_side_layer();
  const MapSet f = render_maps(s, "cpu", o);
  o.float_maps = false;
  const MapSet q = render_maps(s, "cpu", o);
  ASSERT_TRUE(q.has_velocity);
  long checked = 0;
  for (std::size_t i = 0; i < q.mask.size(); ++i) {
    if (q.mask[i] != MapSet::kBody) continue;
    ++checked;
    // one 8-bit step is 2 / 255 of the range: maxv * 2 / 255 for velocity (walking Eq. 10)
    EXPECT_TRUE(test::near_vec(q.velocity_at(i), f.velocity_at(i), o.max_speed * 1.0 / 255 + 1e-5));
    EXPECT_LT(test::angle_deg(q.normal_at(i), f.normal_at(i)), 1.0);
  }
  EXPECT_GT(checked, 1000);
}

TEST(Maps, UnknownRendererIsRejected) {
  EXPECT_THROW(render_maps(make_sphere_body(Vec3::Zero(), 1), "vulkan", ColliderOptions{}), std::invalid_argument);
}

// GL and CPU must agree: coverage identical, depth within 10 µm on every pixel. The CPU
// rasteriser repeats llvmpipe's depth arithmetic, so a float depth target (float maps) holds the
// same bits on all but the odd pixel; a 24-bit one (8-bit maps) differs by its quantisation.
void expect_same_maps(const BodyFrame& body, const ColliderOptions& options, const char* what) {
  const MapSet gl = render_maps(body, "gl", options);
  const MapSet cpu = render_maps(body, "cpu", options);
  const MapDiff d = compare(gl, cpu);
  const double identical = d.covered ? static_cast<double>(d.identical) / d.covered : 0.0;
  std::cout << "[ maps ] " << what << " " << options.map_size << "^2 " << (options.float_maps ? "float" : "8-bit")
            << ": covered " << d.covered << ", coverage mismatches " << d.coverage_mismatch
            << ", depth bit-identical on " << 100 * identical << " %, |gl-cpu| 99.9% " << d.depth_p999 * 1e6
            << " um, max " << d.depth_max * 1e6 << " um\n";
  EXPECT_GT(d.covered, 1000);
  EXPECT_EQ(d.coverage_mismatch, 0);
  EXPECT_LT(d.depth_max, 10e-6);
  if (options.float_maps) {
    EXPECT_GE(identical, 0.999);
  }
}

TEST(GlMaps, SameAsCpuOnASphere) {
  CLOTHBENCH_REQUIRE_GL();
  const BodyFrame s = make_sphere_body(Vec3(0.01f, 0.4f, 0.02f), 0.25f);
  expect_same_maps(s, no_side_layer(), "sphere");
  ColliderOptions eight = no_side_layer();
  eight.float_maps = false;
  eight.map_size = 512;
  expect_same_maps(s, eight, "sphere");
}

TEST(GlMaps, SameAsCpuOnTheBody) {
  CLOTHBENCH_REQUIRE_GL();
  const BodyModel& model = test::test_body_model();
  expect_same_maps(model.rest(), no_side_layer(), model.path().c_str());
  ColliderOptions big;
  big.map_size = 1024;
  expect_same_maps(model.rest(), big, model.path().c_str());
}

TEST(GlMaps, SameAsCpuOnAWalkingFrameVelocitiesIncluded) {
  CLOTHBENCH_REQUIRE_GL();
  if (test::walking_body_path().empty()) GTEST_SKIP() << "no walking body in the data root (" << data_root() << ")";
  const BodyModel& model = test::test_body_model();
  const BodyFrame body = model.frame(model.animation_index("walk_07_01"), 2.0);
  expect_same_maps(body, no_side_layer(), "walk_07_01 t=2 s");
  const MapSet gl = render_maps(body, "gl", no_side_layer());
  const MapSet cpu = render_maps(body, "cpu", no_side_layer());
  ASSERT_TRUE(gl.has_velocity && cpu.has_velocity);
  // velocity where the surface faces the camera: the same interpolation in float
  double worst = 0;
  for (std::size_t i = 0; i < gl.mask.size(); ++i)
    if (gl.mask[i] == MapSet::kBody && std::abs(cpu.normal_at(i).z()) >= 0.5)
      worst = std::max(worst, static_cast<double>((gl.velocity_at(i) - cpu.velocity_at(i)).norm()));
  std::cout << "[ maps ] walk_07_01 t=2 s: velocity |gl-cpu| max " << worst * 1000 << " mm/s\n";
  EXPECT_LT(worst, 1e-3);
}

}  // namespace
}  // namespace clothbench
