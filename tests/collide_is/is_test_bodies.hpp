#pragma once
/// Bodies and GL availability shared by the image-space tests.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>

#include "clothbench/collide_is/map_set.hpp"
#include "clothbench/config.h"
#ifdef CLOTHBENCH_WITH_EGL
#include "clothbench/collide_is/egl_collider.hpp"
#endif
#include "clothbench/io/body_loader.hpp"
#include "clothbench/io/data_root.hpp"

namespace clothbench::test {

/// The walking body of the data root (mh_female_walk.glb), or "" when the data root lacks it.
inline std::string walking_body_path() {
  const std::string p = data_path("body/mh_female_walk.glb");
  return std::filesystem::exists(p) ? p : std::string();
}

/// The real body when the data root exists, else Debian's human.zae, loaded once per process.
inline const BodyModel& test_body_model() {
  static const BodyModel model = [] {
    const std::string walk = walking_body_path();
    return load_body(walk.empty() ? std::string(kDebianHumanBody) : walk);
  }();
  return model;
}

/// Empty when an OpenGL context can be created, else why not.
inline std::string gl_unavailable() {
  static const std::string why = [] {
    try {
      make_gl_map_renderer();
      return std::string();
    } catch (const std::exception& e) {
      return std::string(e.what());
    }
  }();
  return why;
}

/// Empty when is-egl can make an EGL context, else why not (or that the build has no is-egl).
inline const std::string& egl_unavailable() {
  static const std::string why = [] {
#ifdef CLOTHBENCH_WITH_EGL
    try {
      make_egl_map_renderer();
      return std::string();
    } catch (const std::exception& e) {
      return std::string(e.what());
    }
#else
    return std::string("is-egl is not built (CLOTHBENCH_WITH_EGL=OFF)");
#endif
  }();
  return why;
}

/// Maps an OpenGL renderer drew (`gl`, of `body` with `o`) agree with the CPU rasteriser's as for the papers' two
/// views (map_set_test.cpp, GlMaps): the same coverage in every map (views and peeled layers), depth
/// bit-identical on 99.9 % of the covered pixels, within 10 um. That is llvmpipe's arithmetic, which the CPU
/// rasteriser copies; a GPU (`software` false) rasterises its own way: there coverage may differ on 1 in 10,000
/// covered pixels (a peeled layer's gap test deciding otherwise) and depth by 1 mm on as many (measured on an
/// NVIDIA H100: 5 of 112,943 and up to 0.77 mm, results/gpu-h100).
inline void expect_maps_match_cpu(const MapSet& gl, const BodyFrame& body, const ColliderOptions& o, const char* what,
                                  bool software = true) {
  const MapSet cpu = render_maps(body, "cpu", o);
  ASSERT_EQ(gl.z.size(), cpu.z.size());
  ASSERT_EQ(gl.z.size(), static_cast<std::size_t>(gl.frame.map_count()) * gl.view_pixels());
  long covered = 0, coverage_mismatch = 0, identical = 0, beyond_mm = 0;
  double worst = 0;
  for (std::size_t i = 0; i < gl.z.size(); ++i) {
    const bool a = gl.mask[i] != MapSet::kEmpty, b = cpu.mask[i] != MapSet::kEmpty;
    coverage_mismatch += a != b;
    if (!a || !b) continue;
    ++covered;
    identical += gl.z[i] == cpu.z[i];
    const double difference = std::abs(double(gl.z[i]) - double(cpu.z[i]));
    worst = std::max(worst, difference);
    beyond_mm += difference > 1e-3;
  }
  std::cout << "[ maps ] " << what << " " << o.views << " views, " << o.layers << " layers " << o.map_size
            << "^2: covered " << covered << ", coverage mismatches " << coverage_mismatch << ", depth bit-identical on "
            << 100.0 * double(identical) / double(covered) << " %, max " << worst * 1e6 << " um\n";
  EXPECT_GT(covered, 1000 * o.views);
  if (!software) {
    EXPECT_LE(double(coverage_mismatch), 1e-4 * double(covered));
    EXPECT_LE(double(beyond_mm), 1e-4 * double(covered));
    return;
  }
  EXPECT_EQ(coverage_mismatch, 0);
  EXPECT_LT(worst, 10e-6);
  EXPECT_GE(double(identical) / double(covered), 0.999);
}

/// The same for is-gl's renderer (OSMesa).
inline void expect_gl_matches_cpu(const BodyFrame& body, const ColliderOptions& o, const char* what) {
  expect_maps_match_cpu(render_maps(body, "gl", o), body, o, what);
}

}  // namespace clothbench::test

/// Skips the current test, with the reason, when is-egl cannot make its context (or is not built).
#define CLOTHBENCH_REQUIRE_EGL()                                                   \
  do {                                                                             \
    if (!::clothbench::test::egl_unavailable().empty())                            \
      GTEST_SKIP() << "no EGL context: " << ::clothbench::test::egl_unavailable(); \
  } while (0)

/// Skips the current test, with the reason, when no OpenGL context can be created.
#define CLOTHBENCH_REQUIRE_GL()                                                      \
  do {                                                                               \
    if (!::clothbench::test::gl_unavailable().empty())                               \
      GTEST_SKIP() << "no OpenGL context: " << ::clothbench::test::gl_unavailable(); \
  } while (0)
