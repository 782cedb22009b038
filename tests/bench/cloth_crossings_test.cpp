// Cloth against cloth, measured: springs through the cloth's own triangles, counted by hand on two grids.
#include "clothbench/bench/cloth_crossings.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <stdexcept>

#include "clothbench/bench/oracle.hpp"

namespace clothbench {
namespace {

// two 7 x 7 grids 0.1 m apart as one cloth: `a` first, then `b` (its indices after a's)
struct TwoGrids {
  Points3 x;
  Pairs springs;
  Quads quads;
};
TwoGrids join(const ClothMesh& a, const ClothMesh& b) {
  const Eigen::Index na = a.positions.cols();
  TwoGrids g;
  g.x.resize(3, na + b.positions.cols());
  g.x << a.positions, b.positions;
  const Pairs sa = structural_springs(a), sb = structural_springs(b);
  g.springs.resize(2, sa.cols() + sb.cols());
  g.springs << sa, (sb.array() + int(na)).matrix();
  g.quads.resize(4, a.quads.cols() + b.quads.cols());
  g.quads << a.quads, (b.quads.array() + int(na)).matrix();
  return g;
}

// the first grid flat in y = 0 (x, z in [-0.3, 0.3])
ClothMesh flat() { return make_grid_cloth(7, 7, 0.1f, Vec3(-0.3f, 0, -0.3f), Vec3::UnitX(), Vec3::UnitZ()); }
// the second upright in z = `z`, x in [-0.25, 0.35], y in [-0.27, 0.33]: no vertex or crossing on an edge of the other
ClothMesh upright(Real z) { return make_grid_cloth(7, 7, 0.1f, Vec3(-0.25f, -0.27f, z), Vec3::UnitX(), Vec3::UnitY()); }

TEST(ClothCrossings, AFlatClothCrossesNothing) {
  const ClothMesh a = flat();
  const ClothCrossings c = cloth_crossings(a.positions, structural_springs(a), a.quads);
  EXPECT_EQ(c.segments, std::size_t(structural_springs(a).cols()));
  EXPECT_EQ(c.crossings, 0u);
  EXPECT_EQ(c.pct, 0);
}

TEST(ClothCrossings, TwoGridsThroughEachOtherCountedByHand) {
  const TwoGrids g = join(flat(), upright(0.03f));
  const ClothCrossings c = cloth_crossings(g.x, g.springs, g.quads);
  // the upright grid's springs from y = -0.07 to 0.03 at x = -0.25 ... 0.25 (six; x = 0.35 is beyond the flat one),
  // and the flat grid's from z = 0 to 0.1 at x = -0.2 ... 0.3 (six; x = -0.3 is beyond the upright one)
  EXPECT_EQ(c.crossings, 12u);
  EXPECT_DOUBLE_EQ(c.pct, 100.0 * 12 / double(g.springs.cols()));
  // apart, nothing crosses
  EXPECT_EQ(cloth_crossings(join(flat(), upright(0.5f)).x, g.springs, g.quads).crossings, 0u);
}

TEST(ClothCrossings, ASewnPointIsNoCrossing) {
  // the second grid hangs from the first's edge z = 0.3, its top row on the first's vertices (coincident, as sewn)
  const ClothMesh b = make_grid_cloth(7, 7, 0.1f, Vec3(-0.3f, -0.6f, 0.3f), Vec3::UnitX(), Vec3::UnitY());
  const TwoGrids g = join(flat(), b);
  EXPECT_EQ(cloth_crossings(g.x, g.springs, g.quads).crossings, 0u);
}

TEST(ClothCrossings, NonFiniteSpringsAreNotTestedAndBadIndicesThrow) {
  ClothMesh a = flat();
  const Pairs springs = structural_springs(a);
  a.positions(0, 0) = std::numeric_limits<Real>::quiet_NaN();  // vertex 0: two springs and one quad
  EXPECT_EQ(cloth_crossings(a.positions, springs, a.quads).segments, std::size_t(springs.cols() - 2));
  Pairs bad = springs;
  bad(1, 0) = int(a.positions.cols());
  EXPECT_THROW(cloth_crossings(a.positions, bad, a.quads), std::invalid_argument);
}

}  // namespace
}  // namespace clothbench
