// Layers of garments: an outer garment's points inside or too near the dressed cloth under it are moved out along
// its normal to the clearance; points clear of it, or beyond the reach, stay where they are.
#include "clothbench/sim/layers.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace clothbench {
namespace {

// a cylinder round the y axis, radius r, from y = 0 to 0.4: n points round, m rows, cells between them
struct Cylinder {
  Points3 x;
  Quads cells;
  Cylinder(Real r, int n, int m, bool inward_cells = false) {
    x.resize(3, n * m);
    for (int j = 0; j < m; ++j)
      for (int i = 0; i < n; ++i) {
        const double a = 2 * M_PI * i / n;
        x.col(j * n + i) = Vec3(Real(r * std::cos(a)), Real(0.4 * j / (m - 1)), Real(r * std::sin(a)));
      }
    cells.resize(4, n * (m - 1));
    for (int j = 0; j + 1 < m; ++j)
      for (int i = 0; i < n; ++i) {
        const int a = j * n + i, b = j * n + (i + 1) % n;
        cells.col(j * n + i) << a, b, b + n, a + n;
        if (inward_cells) std::swap(cells(1, j * n + i), cells(3, j * n + i));
      }
  }
};

Real radius(const Points3& x, Eigen::Index i) { return std::hypot(x(0, i), x(2, i)); }

TEST(Layers, PointsInsideOrNearTheClothUnderThemMoveOutToTheClearance) {
  for (const bool inward : {false, true}) {  // the cells' winding does not decide which side is out
    SCOPED_TRACE(inward);
    const Cylinder inner(0.15f, 64, 21, inward);
    // an outer garment's points: inside the inner cloth, just outside it, clear of it, and beyond the reach
    Points3 outer(3, 4);
    outer.col(0) = Vec3(0.13f, 0.2f, 0);
    outer.col(1) = Vec3(0, 0.21f, 0.155f);
    outer.col(2) = Vec3(-0.18f, 0.2f, 0);
    outer.col(3) = Vec3(0, 0.2f, -0.40f);
    const Points3 before = outer;
    EXPECT_EQ(clear_of_layer(inner.x, inner.cells, outer, 0.01f, 0.1f), 2);
    EXPECT_NEAR(radius(outer, 0), 0.16, 1e-3);  // out along the normal, to the clearance
    EXPECT_NEAR(radius(outer, 1), 0.16, 1e-3);
    EXPECT_NEAR(outer(1, 0), 0.2, 1e-6);  // straight out: its height kept
    EXPECT_EQ(outer.col(2), before.col(2));
    EXPECT_EQ(outer.col(3), before.col(3));
  }
}

}  // namespace
}  // namespace clothbench
