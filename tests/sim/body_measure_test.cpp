// Body measurements (sim/src/body_measure.cpp): sections of shapes whose girths are known.
#include "clothbench/sim/body_measure.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace clothbench {
namespace {

constexpr double kPi = 3.14159265358979323846;

// a closed capsule 1 m long, radius 10 cm, standing on y = 0, with 48 sectors: its sections are 48-gons
BodyFrame upright_capsule() { return make_capsule_body(Vec3(0, 0.6f, 0), 0.1f, 1.0f, 16, 48); }

TEST(BodyMeasure, ACylindersSectionIsOneLoopOfItsGirth) {
  const BodyFrame body = upright_capsule();
  const auto loops = cross_section(body, 0.55);
  ASSERT_EQ(loops.size(), 1u);
  const double polygon = 2 * 48 * 0.1 * std::sin(kPi / 48);  // the 48-gon's perimeter
  EXPECT_NEAR(loops[0].girth(), polygon, 1e-4);
  EXPECT_NEAR(loops[0].area(), 0.5 * 48 * 0.01 * std::sin(2 * kPi / 48), 1e-5);
  EXPECT_NEAR(loops[0].width(), 0.2, 1e-3);
  EXPECT_NEAR(loops[0].centroid().norm(), 0, 1e-6);
  EXPECT_TRUE(cross_section(body, 1.5).empty());  // above it
}

// an elliptic section: the capsule stretched 2x along x; a tape around it reads the ellipse's perimeter
TEST(BodyMeasure, AnEllipsesGirthIsItsPerimeter) {
  BodyFrame body = upright_capsule();
  body.positions.row(0) *= 2;
  const auto loops = cross_section(body, 0.6);
  ASSERT_EQ(loops.size(), 1u);
  const double a = 0.2, b = 0.1, h = std::pow(a - b, 2) / std::pow(a + b, 2);
  const double ramanujan = kPi * (a + b) * (1 + 3 * h / (10 + std::sqrt(4 - 3 * h)));
  EXPECT_NEAR(loops[0].girth(), ramanujan, 0.003 * ramanujan);  // a 48-gon inscribed
  EXPECT_NEAR(loops[0].width(), 0.4, 2e-3);
}

// a tape spans a hollow: a loop with a notch reads its convex hull's perimeter, not its outline's
TEST(BodyMeasure, AGirthSpansTheHollows) {
  SectionLoop notched;
  notched.points = {{0, 0}, {2, 0}, {2, 2}, {1, 1}, {0, 2}};
  EXPECT_NEAR(notched.girth(), 8, 1e-9);
  EXPECT_NEAR(notched.area(), 3, 1e-9);
}

// two cylinders side by side (two legs): two loops, the larger first
TEST(BodyMeasure, TwoLegsAreTwoLoopsLargestFirst) {
  BodyFrame left = make_capsule_body(Vec3(-0.15f, 0.6f, 0), 0.08f, 1.0f, 16, 48);
  const BodyFrame right = make_capsule_body(Vec3(0.15f, 0.6f, 0), 0.06f, 1.0f, 16, 48);
  const Eigen::Index n = left.positions.cols();
  BodyFrame both = left;
  both.positions.conservativeResize(3, n + right.positions.cols());
  both.positions.rightCols(right.positions.cols()) = right.positions;
  both.triangles.conservativeResize(3, left.triangles.cols() + right.triangles.cols());
  both.triangles.rightCols(right.triangles.cols()) = right.triangles.array() + static_cast<int>(n);
  const auto loops = cross_section(both, 0.5);
  ASSERT_EQ(loops.size(), 2u);
  EXPECT_LT(loops[0].centroid().x(), 0);  // the wider one first
  EXPECT_GT(loops[0].area(), loops[1].area());
}

// a body that does not stand with its legs apart has no crotch: a clear error, not garbage
TEST(BodyMeasure, ABodyWithoutLegsIsRefusedNamingWhatIsMissing) {
  try {
    measure_body(upright_capsule());
    FAIL() << "a capsule was measured";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("legs"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace clothbench
