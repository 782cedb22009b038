// MarkdownTable (experiments/src/markdown_table.cpp); linear_fit, power_fit and judge_growth
// (experiments/src/statistics.cpp).
#include "clothbench/experiments/markdown_table.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "clothbench/experiments/statistics.hpp"

namespace clothbench {
namespace {

TEST(MarkdownTable, HeaderSeparatorThenRows) {
  MarkdownTable t({"a", "b"});
  t.row({"1", "2"});
  t.row({"x", "y"});
  EXPECT_EQ(t.str(), "| a | b |\n|---|---|\n| 1 | 2 |\n| x | y |\n");
  EXPECT_EQ(MarkdownTable({"only"}).str(), "| only |\n|---|\n");
}

TEST(Statistics, LinearFitRecoversALineAndItsR2) {
  const std::vector<double> x{1, 2, 3, 4}, y{3, 5, 7, 9};  // y = 1 + 2 x
  double a = 0, b = 0, r2 = 0;
  linear_fit(x, y, a, b, r2);
  EXPECT_NEAR(a, 1, 1e-12);
  EXPECT_NEAR(b, 2, 1e-12);
  EXPECT_NEAR(r2, 1, 1e-12);
  linear_fit(x, {3, 6, 6, 9}, a, b, r2);  // scattered: 0 < R^2 < 1
  EXPECT_GT(r2, 0.5);
  EXPECT_LT(r2, 1);
}

// time = fixed cost + per-vertex cost: linear although a log-log slope over these sizes would read well under 1
TEST(Statistics, PowerFitFindsTheExponentAndItsInterval) {
  const std::vector<double> x{500, 1000, 2000, 3500, 5000, 8000, 12000, 20000};
  std::vector<double> line, square;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double noise = 1 + 0.01 * (i % 2 ? 1 : -1);  // +-1 %
    line.push_back((2 + 0.003 * x[i]) * noise);
    square.push_back((2 + 1e-6 * x[i] * x[i]) * noise);
  }
  const PowerFit l = power_fit(x, line), q = power_fit(x, square);
  EXPECT_NEAR(l.k, 1, 0.05);
  EXPECT_LE(l.k_low, 1);
  EXPECT_GE(l.k_high, 1);
  EXPECT_NEAR(q.k, 2, 0.05);
  EXPECT_GT(q.k_low, 1.5);  // 1 lies far outside
  EXPECT_FALSE(l.at_grid_edge);
  EXPECT_LT(l.k_high - l.k_low, 0.5);
  EXPECT_EQ(power_fit({1, 2, 3}, {1, 2, 3}).k, 0);  // too few points: no fit
}

// the medians' interval decides; repeated series on both sides of 1 withhold a departure, never make one
TEST(Statistics, GrowthIsJudgedOnTheMediansAndTheRepeatedSeries) {
  const std::vector<double> x{500, 1000, 2000, 3500, 5000, 8000};
  auto series = [&](double k) {
    std::vector<double> y;
    for (std::size_t i = 0; i < x.size(); ++i)
      y.push_back((1 + 10 * std::pow(x[i] / 1000, k)) * (1 + 0.01 * (i % 2 ? 1 : -1)));  // +-1 %
    return power_fit(x, y);
  };
  const PowerFit line = series(1), steep = series(1.3), flat = series(0.8);
  EXPECT_EQ(judge_growth(line, {series(0.7), series(1.4)}), Growth::kLinear);
  EXPECT_EQ(judge_growth(steep, {series(1.2), series(1.4)}), Growth::kAbove);
  EXPECT_EQ(judge_growth(flat, {series(0.7), series(0.9)}), Growth::kBelow);
  EXPECT_EQ(judge_growth(steep, {series(1.3), series(0.9)}), Growth::kStraddles);
  PowerFit unbounded = steep;
  unbounded.at_grid_edge = true;
  EXPECT_EQ(judge_growth(unbounded, {}), Growth::kUndecided);
  EXPECT_STRNE(growth_text(Growth::kStraddles), growth_text(Growth::kAbove));
}

}  // namespace
}  // namespace clothbench
