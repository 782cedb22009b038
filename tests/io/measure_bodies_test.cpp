// Body measurements (sim/src/body_measure.cpp) of the bodies this project ships or finds: Debian's human.zae and
// the walking body's rest pose, and the same body scaled.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <utility>

#include "clothbench/io/body_loader.hpp"
#include "clothbench/io/data_root.hpp"
#include "clothbench/sim/body_measure.hpp"

namespace clothbench {
namespace {

// the landmarks lie in the order of a standing body, and the girths in a tailor's order
void expect_a_standing_body(const BodyMeasurements& m, const std::string& which) {
  for (const auto& x : m.all)
    std::printf("[ measure ] %s %s %.1f cm at %.1f cm\n", which.c_str(), x.name.c_str(), 100 * x.value_m,
                100 * x.height_m);
  const char* upwards[] = {"knee girth", "crotch height", "hip girth",  "waist girth",
                           "bust girth", "armpit height", "neck girth", "stature"};
  for (std::size_t i = 0; i + 1 < std::size(upwards); ++i)
    EXPECT_LT(m[upwards[i]].height_m, m[upwards[i + 1]].height_m) << which << ": " << upwards[i];
  const std::pair<const char*, const char*> smaller[] = {{"waist girth", "hip girth"},
                                                         {"waist girth", "bust girth"},
                                                         {"neck girth", "waist girth"},
                                                         {"knee girth", "thigh girth"},
                                                         {"upper arm girth", "thigh girth"}};
  for (const auto& [a, b] : smaller) EXPECT_LT(m[a].value_m, m[b].value_m) << which << ": " << a << " < " << b;
  EXPECT_GT(m["inseam"].value_m, 0.35 * m["stature"].value_m) << which;
}

TEST(MeasureBodies, DebianHumanAndItsScaledCopy) {
  if (!std::filesystem::exists(kDebianHumanBody)) GTEST_SKIP() << "assimp-testmodels not installed";
  const BodyFrame rest = load_body("debian:human").rest();
  const BodyMeasurements m = measure_body(rest);
  expect_a_standing_body(m, "debian:human");
  // a body 10 % larger in every direction (soles stay at y = 0): every girth and length 10 % larger
  BodyFrame big = rest;
  big.positions *= 1.1f;
  const BodyMeasurements b = measure_body(big);
  for (const auto& x : m.all) EXPECT_NEAR(b[x.name].value_m / x.value_m, 1.1, 0.03) << x.name;
}

TEST(MeasureBodies, TheWalkingBodysRestPose) {
  const std::string path = data_path("body/mh_female_walk.glb");
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "walking body absent from the data root";
  expect_a_standing_body(measure_body(load_body(path).rest()), "walking body");
}

// the CLI: a standing body prints its measurements; a closed mesh that is no standing body, and a missing file,
// exit 2 (bad input) saying what is wrong
TEST(MeasureCommand, ExitCodes) {
  const char* bin = std::getenv("CLOTHBENCH_BIN");
  if (!bin || !std::filesystem::exists(bin)) GTEST_SKIP() << "CLOTHBENCH_BIN not set";
  const std::string out = testing::TempDir() + "measure_out.txt";
  const auto run = [&](const std::string& args) {
    const int rc = std::system((std::string(bin) + " measure " + args + " > " + out + " 2>&1").c_str());
    return WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
  };
  const auto printed = [&] {
    std::ifstream in(out);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  const std::string tetrahedron = testing::TempDir() + "tetrahedron.obj";
  std::ofstream(tetrahedron) << "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
  EXPECT_EQ(run(tetrahedron), 2);
  EXPECT_NE(printed().find("legs"), std::string::npos) << printed();
  EXPECT_EQ(run(testing::TempDir() + "no_such_body.obj"), 2);
  if (!std::filesystem::exists(kDebianHumanBody)) return;
  EXPECT_EQ(run("debian:human --json"), 0);
  EXPECT_NE(printed().find("\"waist girth\""), std::string::npos) << printed();
}

}  // namespace
}  // namespace clothbench
