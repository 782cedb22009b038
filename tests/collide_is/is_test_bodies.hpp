#pragma once
/// Bodies and GL availability shared by the image-space tests.
#include <gtest/gtest.h>

#include <filesystem>
#include <memory>
#include <string>

#include "clothbench/collide_is/map_set.hpp"
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

}  // namespace clothbench::test

/// Skips the current test, with the reason, when no OpenGL context can be created.
#define CLOTHBENCH_REQUIRE_GL()                                                      \
  do {                                                                               \
    if (!::clothbench::test::gl_unavailable().empty())                               \
      GTEST_SKIP() << "no OpenGL context: " << ::clothbench::test::gl_unavailable(); \
  } while (0)
