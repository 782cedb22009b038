// drape_error: the symmetric vertex-to-surface distance between two drapes of any resolutions.
#include "clothbench/bench/drape_error.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

namespace clothbench {
namespace {

// a 30 cm square in the xy plane at height z, n x n vertices
ClothMesh square(int n, Real z) {
  const Real spacing = 0.3f / Real(n - 1);
  return make_grid_cloth(n, n, spacing, Vec3(0, 0, z), Vec3::UnitX(), Vec3::UnitY());
}

TEST(DrapeError, IsZeroForOneDrapeAtTwoResolutions) {
  const DrapeError same = drape_error(square(11, 0), square(11, 0));
  EXPECT_EQ(same.rms, 0);
  EXPECT_EQ(same.points, 242u);
  const DrapeError fine = drape_error(square(7, 0), square(31, 0));
  EXPECT_LT(fine.max, 1e-6);
}

TEST(DrapeError, MeasuresAnOffsetAlongTheNormal) {
  const DrapeError e = drape_error(square(7, 0), square(13, 0.01f));
  EXPECT_NEAR(e.rms, 0.01, 1e-6);
  EXPECT_NEAR(e.max, 0.01, 1e-6);
}

TEST(DrapeError, FindsASurfaceBeyondTheGridRings) {
  // 40 cm apart: farther than the grid's rings reach, answered by every triangle
  const DrapeError e = drape_error(square(5, 0), square(5, 0.4f));
  EXPECT_NEAR(e.max, 0.4, 1e-5);
}

TEST(DrapeError, BendingRaisesTheErrorWhereTheClothMoved) {
  ClothMesh bent = square(11, 0);
  for (Eigen::Index v = 0; v < bent.positions.cols(); ++v)
    if (bent.positions(0, v) > 0.15f) bent.positions(2, v) = 0.5f * (bent.positions(0, v) - 0.15f);
  const DrapeError e = drape_error(square(21, 0), bent);
  EXPECT_GT(e.max, 0.07);  // the far edge: 7.5 cm up
  EXPECT_LT(e.rms, e.max);
  EXPECT_GT(e.rms, 0.01);
}

TEST(DrapeError, NeedsQuads) {
  ClothMesh none;
  none.positions = Points3::Zero(3, 2);
  EXPECT_THROW(drape_error(none, square(3, 0)), std::invalid_argument);
}

}  // namespace
}  // namespace clothbench
