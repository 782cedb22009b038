// MarkdownTable (experiments/src/markdown_table.cpp) and linear_fit (experiments/src/statistics.cpp).
#include "clothbench/experiments/markdown_table.hpp"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace clothbench
