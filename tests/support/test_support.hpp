#pragma once
/// Shared test helpers: assets, precision-aware comparisons.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "clothbench/sim/types.hpp"

namespace clothbench::test {

/// AssertionResult for |a - b| <= tol per component, naming the worst component.
inline ::testing::AssertionResult near_vec(const Vec3& a, const Vec3& b, double tol) {
  const double err = (a - b).cwiseAbs().maxCoeff();
  if (err <= tol) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "(" << a.transpose() << ") vs (" << b.transpose() << "): max error "
                                       << err << " > " << tol;
}

/// This test process's own temporary folder, removed when the process ends (by the process that made it,
/// not by a forked worker exiting).
struct TempFolder {
  pid_t owner = ::getpid();
  std::filesystem::path path =
      std::filesystem::temp_directory_path() / ("clothbench_test_" + std::to_string(::getpid()));
  ~TempFolder() {
    std::error_code ignored;
    if (::getpid() == owner) std::filesystem::remove_all(path, ignored);
  }
};
inline TempFolder temp_folder;

/// A path that no other test process uses (two clones' test runs at once shared fixed names in /tmp and
/// read each other's files): NAME in this process's temporary folder.
inline std::string temp_path(const std::string& name) {
  std::filesystem::create_directories(temp_folder.path);
  return (temp_folder.path / name).string();
}

/// Angle between two vectors [degrees].
inline double angle_deg(const Vec3& a, const Vec3& b) {
  const double c = a.normalized().dot(b.normalized());
  return std::acos(std::max(-1.0, std::min(1.0, c))) * 180.0 / M_PI;
}

}  // namespace clothbench::test
