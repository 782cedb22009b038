// is-egl: the maps through a windowless EGL context (Mesa's llvmpipe here, a GPU where there is one) are
// is-gl's: the same shaders and FBO on the same Mesa give bit-identical maps, and both agree with the CPU
// rasteriser as is-gl does. Conformance (tests/conformance) runs is-egl with every built collider.
#include <gtest/gtest.h>

#include <cstdlib>
#include <iostream>
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
  EXPECT_EQ(a.z, b.z) << what;
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

}  // namespace
}  // namespace clothbench
