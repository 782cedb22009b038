// is-egl: the maps through a windowless EGL context (Mesa's llvmpipe here, a GPU where there is one) are
// is-gl's: the same shaders and FBO on the same Mesa give bit-identical maps, and both agree with the CPU
// rasteriser as is-gl does. Conformance (tests/conformance) runs is-egl with every built collider.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <random>
#include <vector>
#include <iostream>
#include <limits>
#include <memory>
#include <string>

#include "clothbench/collide_is/egl_collider.hpp"
#include "clothbench/collide_is/image_space_collider.hpp"
#include "clothbench/collide_is/map_set.hpp"
#include "is_test_bodies.hpp"

namespace clothbench {
namespace {

MapSet egl_maps(const BodyFrame& body, const ColliderOptions& o) {
  const auto r = make_egl_map_renderer();
  return render_maps(body, *r, o);
}

// every array of two map sets equal, byte for byte
void expect_identical(const MapSet& a, const MapSet& b, const std::string& what) {
  ASSERT_EQ(a.z.size(), b.z.size()) << what;
  std::size_t differ = 0;
  double most = 0;
  for (std::size_t i = 0; i < a.z.size(); ++i)
    if (a.z[i] != b.z[i]) ++differ, most = std::max(most, std::abs(double(a.z[i]) - double(b.z[i])));
  EXPECT_EQ(differ, 0u) << what << ": z differs at " << differ << " elements, by up to " << most * 1e6 << " um";
  EXPECT_EQ(a.mask, b.mask) << what;
  EXPECT_EQ(a.normal, b.normal) << what;
  EXPECT_EQ(a.velocity, b.velocity) << what;
  EXPECT_EQ(a.normal8, b.normal8) << what;
  EXPECT_EQ(a.velocity8, b.velocity8) << what;
}

TEST(EglMaps, DeviceNamesEglAndTheRenderer) {
  CLOTHBENCH_REQUIRE_EGL();
  const auto r = make_egl_map_renderer();
  EXPECT_EQ(r->name(), "egl");
  std::cout << "[ egl ] " << r->device() << "\n";
  EXPECT_NE(r->device().find("EGL"), std::string::npos) << r->device();
  EXPECT_NE(r->device().find("OpenGL"), std::string::npos) << r->device();
  const auto c = make_is_egl_collider(ColliderOptions{});
  EXPECT_EQ(c->name(), "is-egl");
  EXPECT_EQ(c->device(), r->device());
}

// on llvmpipe as is-gl does (bit for bit, nearly); on a GPU within its own rasterisation's differences
TEST(EglMaps, SameAsCpuAsIsGlIs) {
  CLOTHBENCH_REQUIRE_EGL();
  const bool software = cpu_device(make_egl_map_renderer()->device());
  const BodyModel& model = test::test_body_model();
  const BodyFrame sphere = make_sphere_body(Vec3(0.01f, 0.4f, 0.02f), 0.25f);
  for (int views : {2, 6})
    for (int layers : {1, 4}) {
      ColliderOptions o;
      o.views = views;
      o.layers = layers;
      o.side_layer = false;
      test::expect_maps_match_cpu(egl_maps(sphere, o), sphere, o, "sphere (egl)", software);
      test::expect_maps_match_cpu(egl_maps(model.rest(), o), model.rest(), o, (model.path() + " (egl)").c_str(),
                                  software);
    }
}

// the same Mesa behind OSMesa and EGL: the same maps, bit for bit, float and 8-bit, moving body included
TEST(EglMaps, IdenticalToOsmesa) {
  CLOTHBENCH_REQUIRE_EGL();
  if (!test::gl_unavailable().empty()) GTEST_SKIP() << "no OSMesa context: " << test::gl_unavailable();
  const BodyModel& model = test::test_body_model();
  BodyFrame body = model.rest();
  if (!model.animations().empty()) body = model.frame(0, 0.5);
  for (bool floats : {true, false})
    for (int views : {2, 6}) {
      ColliderOptions o;
      o.float_maps = floats;
      o.views = views;
      o.layers = views == 6 ? 5 : 1;
      expect_identical(egl_maps(body, o), render_maps(body, "gl", o),
                       std::string(floats ? "float" : "8-bit") + ", " + std::to_string(views) + " views");
    }
}

// contexts of both providers in one thread, drawing in turn: each renderer rebinds its own
TEST(EglMaps, TakesTurnsWithOsmesaInOneProcess) {
  CLOTHBENCH_REQUIRE_EGL();
  if (!test::gl_unavailable().empty()) GTEST_SKIP() << "no OSMesa context: " << test::gl_unavailable();
  const BodyModel& model = test::test_body_model();
  const BodyFrame small = make_sphere_body(Vec3(0.0f, 0.5f, 0.0f), 0.2f), big = model.rest();
  const auto egl = make_egl_map_renderer();
  const auto gl = make_gl_map_renderer();
  ColliderOptions o;
  o.side_layer = false;
  const MapSet first = render_maps(big, *egl, o);
  for (int turn = 0; turn < 3; ++turn) {
    const MapSet g = render_maps(turn % 2 ? small : big, *gl, o);
    const MapSet e = render_maps(turn % 2 ? small : big, *egl, o);
    expect_identical(e, g, "turn " + std::to_string(turn));
  }
  expect_identical(render_maps(big, *egl, o), first, "again");
}

TEST(EglMaps, ADeviceOutOfRangeIsNamed) {
  CLOTHBENCH_REQUIRE_EGL();
  for (const char* bad : {"99", "-1", "gpu"}) {
    setenv("CLOTHBENCH_EGL_DEVICE", bad, 1);
    try {
      make_egl_map_renderer();
      ADD_FAILURE() << "device " << bad << " accepted";
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find(std::string("CLOTHBENCH_EGL_DEVICE=") + bad), std::string::npos) << e.what();
    }
  }
  unsetenv("CLOTHBENCH_EGL_DEVICE");
}

// Mesa's surfaceless platform (the fallback where EGL lists no device) draws the same maps as the device
TEST(EglMaps, SurfacelessPlatformDrawsTheSameMaps) {
  CLOTHBENCH_REQUIRE_EGL();
  setenv("CLOTHBENCH_EGL_DEVICE", "surfaceless", 1);
  std::unique_ptr<MapRenderer> surfaceless;
  try {
    surfaceless = make_egl_map_renderer();
  } catch (const std::runtime_error& e) {
    unsetenv("CLOTHBENCH_EGL_DEVICE");
    GTEST_SKIP() << "no surfaceless platform here: " << e.what();
  }
  unsetenv("CLOTHBENCH_EGL_DEVICE");
  std::cout << "[ egl ] " << surfaceless->device() << "\n";
  EXPECT_NE(surfaceless->device().find("surfaceless"), std::string::npos) << surfaceless->device();
  const BodyModel& model = test::test_body_model();
  ColliderOptions o;
  o.views = 6;
  o.layers = 3;
  const auto device = make_egl_map_renderer();
  expect_identical(render_maps(model.rest(), *surfaceless, o), render_maps(model.rest(), *device, o), "surfaceless");
}

// egl's maps answered on the CPU: the renderer's maps without its device (device_maps() null)
class AnsweredOnTheCpu final : public MapRenderer {
 public:
  explicit AnsweredOnTheCpu(std::unique_ptr<MapRenderer> r) : r_(std::move(r)) {}
  std::string_view name() const override { return r_->name(); }
  std::string device() const override { return r_->device(); }
  void render(const BodyFrame& body, MapSet& maps) override { r_->render(body, maps); }

 private:
  std::unique_ptr<MapRenderer> r_;
};

// points within 3 cm of the body's vertices along their normals, and some anywhere in its box
Points3 points_near(const BodyFrame& body, int count, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> off(-0.03f, 0.03f), unit(0.0f, 1.0f);
  std::uniform_int_distribution<int> vertex(0, body.vertex_count() - 1);
  const Box3 box = bounding_box(body.positions);
  Points3 p(3, count);
  for (int k = 0; k < count; ++k) {
    if (k % 10 == 9) {
      p.col(k) = box.min + Vec3(unit(rng), unit(rng), unit(rng)).cwiseProduct(box.size());
    } else {
      const int v = vertex(rng);
      p.col(k) = body.positions.col(v) + off(rng) * body.normals.col(v).normalized();
    }
  }
  return p;
}

// the maps kept on the device, their side layer grown and the points answered there, are the maps and answers of
// the CPU path: static and walking bodies, float and 8-bit, 2 and 6 views, 1 and 5 layers, whole maps and the rows
// of a region (on llvmpipe to the bit for the maps and the hits; a GPU's arithmetic may round a few points across)
TEST(EglQueries, AnsweredOnTheDeviceAsOnTheCpu) {
  CLOTHBENCH_REQUIRE_EGL();
  const bool software = cpu_device(make_egl_map_renderer()->device());
  const BodyModel& model = test::test_body_model();
  std::vector<std::pair<std::string, BodyFrame>> bodies = {{"rest", model.rest()}};
  if (!model.animations().empty()) bodies.emplace_back("walking", model.frame(0, 1.3));
  for (const auto& [name, body] : bodies)
    for (bool floats : {true, false})
      for (int views : {2, 6})
        for (int layers : {1, 5})
          for (bool parts : {true, false}) {
            if (!parts && (views != 6 || layers == 1)) continue;  // a sheet's rules: the peeled layers' only
            ColliderOptions o;
            o.float_maps = floats;
            o.views = views;
            o.layers = layers;
            o.overlapping_parts = parts;
            const std::string what = name + (floats ? " float " : " 8-bit ") + std::to_string(views) + " views " +
                                     std::to_string(layers) + " layers" + (parts ? "" : ", a sheet");
            ImageSpaceCollider device(make_egl_map_renderer(), o, 0.0, image_space_depth_test(o));
            ImageSpaceCollider cpu(std::make_unique<AnsweredOnTheCpu>(make_egl_map_renderer()), o, 0.0,
                                   image_space_depth_test(o));
            ASSERT_NE(make_egl_map_renderer()->device_maps(), nullptr);
            const Points3 p = points_near(body, 4000, 31u + static_cast<unsigned>(views + layers));
            if (name == "walking") {
              // the rows of the hips and legs only, as a walking run's region
              Box3 region = bounding_box(body.positions);
              region.max.y() = region.min.y() + 0.55f * region.size().y();
              device.set_query_region(region);
              cpu.set_query_region(region);
            }
            device.set_body(body);
            cpu.set_body(body);
            expect_identical(device.maps(), cpu.maps(), what + " (maps)");
            std::vector<Contact> a(static_cast<std::size_t>(p.cols())), b(a.size());
            device.query(PointsView(p), ContactsOut{a.data(), a.size()});
            cpu.query(PointsView(p), ContactsOut{b.data(), b.size()});
            std::size_t hit_differs = 0, hits = 0;
            double depth = 0, normal = 0, velocity = 0;
            for (std::size_t k = 0; k < a.size(); ++k) {
              hit_differs += a[k].hit != b[k].hit;
              if (!a[k].hit || !b[k].hit) continue;
              ++hits;
              depth = std::max(depth, double(std::abs(a[k].depth - b[k].depth)));
              normal = std::max(normal, double((a[k].normal - b[k].normal).norm()));
              velocity = std::max(velocity, double((a[k].body_velocity - b[k].body_velocity).norm()));
            }
            std::cout << "[ egl queries ] " << what << ": " << hits << " hits of " << a.size() << ", hit differs on "
                      << hit_differs << ", depth by up to " << depth * 1e6 << " um, normal " << normal << ", velocity "
                      << velocity << " m/s\n";
            EXPECT_GT(hits, 100u) << what;
            EXPECT_LE(hit_differs, software ? 0u : a.size() / 1000) << what;
            EXPECT_LE(depth, 1e-6) << what;
            EXPECT_LE(normal, 1e-4) << what;
            EXPECT_LE(velocity, 1e-4) << what;
            EXPECT_EQ(device.stats().points, static_cast<std::int64_t>(a.size()));
          }
}

// a point that is not finite is counted as degenerate, never answered, on the device as on the CPU
TEST(EglQueries, PointsThatAreNotFiniteAreDegenerate) {
  CLOTHBENCH_REQUIRE_EGL();
  auto c = make_is_egl_collider(ColliderOptions{});
  c->set_body(make_sphere_body(Vec3(0, 0.5f, 0), 0.3f));
  Points3 p(3, 3);
  p.col(0) = Vec3(0, 0.5f, 0);
  p.col(1) = Vec3(std::nanf(""), 0.5f, 0);
  p.col(2) = Vec3(0, std::numeric_limits<float>::infinity(), 0);
  std::vector<Contact> out(3);
  c->query(PointsView(p), ContactsOut{out.data(), out.size()});
  EXPECT_TRUE(out[0].hit);
  EXPECT_FALSE(out[1].hit);
  EXPECT_FALSE(out[2].hit);
  EXPECT_EQ(c->stats().degenerate, 2);
  EXPECT_EQ(c->stats().hits, 1);
}

}  // namespace
}  // namespace clothbench
