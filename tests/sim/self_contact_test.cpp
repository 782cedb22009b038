// Cloth against itself: a point moving into a triangle of the same cloth nearer than the thickness is stopped, the
// impulse shared with the triangle's corners (momentum kept); one moving away, one farther, or a triangle with a
// corner at the point (sewn or a seam partner) is left alone.
#include "clothbench/sim/self_contact.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <vector>

namespace clothbench {
namespace {

// one quad in the plane y = 0 (x, z in [0, 0.1]) and a fifth vertex `above` it at (0.03, height, 0.02)
struct QuadAndPoint {
  ClothMesh mesh;
  Points3 x, v;
  Scalars inv_m = Scalars::Constant(5, 100);
  explicit QuadAndPoint(Real height) {
    mesh.positions.resize(3, 5);
    mesh.positions << 0, 0.1f, 0.1f, 0, 0.03f, 0, 0, 0, 0, height, 0, 0, 0.1f, 0.1f, 0.02f;
    mesh.quads.resize(4, 1);
    mesh.quads << 0, 1, 2, 3;
    mesh.rest_length = Scalars::Constant(1, 0.1f);
    x = mesh.positions;
    v = Points3::Zero(3, 5);
  }
  Vec3 momentum() const { return v.rowwise().sum() / 100; }
};

TEST(SelfContact, APointMovingIntoTheClothNearerThanTheThicknessIsStopped) {
  QuadAndPoint s(0.002f);
  s.v.col(4) = Vec3(0.5f, -1, 0);  // down into the quad and along it
  const Vec3 before = s.momentum();
  SelfContacts contacts;
  EXPECT_GT(contacts.respond(s.mesh, {}, s.x, s.v, s.inv_m, 0.005f), 0);
  // no relative motion along the normal is left: the point and the point under it (in the quad's triangle 0, 1, 2 at
  // barycentric 0.7, 0.1, 0.2) move alike
  const Vec3 under = 0.7f * s.v.col(0) + 0.1f * s.v.col(1) + 0.2f * s.v.col(2);
  EXPECT_NEAR(s.v(1, 4), under.y(), 1e-5f);
  EXPECT_FLOAT_EQ(s.v(0, 4), 0.5f);  // sliding along it is not stopped
  EXPECT_TRUE((s.momentum() - before).isZero(1e-6f));
}

TEST(SelfContact, AwayFartherOrAtItsOwnPointNothingChanges) {
  SelfContacts contacts;
  for (const Real height : {0.002f, 0.01f}) {
    QuadAndPoint s(height);
    s.v.col(4) = Vec3(0, height < 0.005f ? 1.f : -1.f, 0);  // near and leaving, or farther than the thickness
    const Points3 v0 = s.v;
    EXPECT_EQ(contacts.respond(s.mesh, {}, s.x, s.v, s.inv_m, 0.005f), 0);
    EXPECT_EQ(s.v, v0);
  }
  // sewn to a corner, or that corner's seam partner: the quad is its own cloth
  QuadAndPoint s(0.002f);
  s.v.col(4) = Vec3(0, -1, 0);
  EXPECT_EQ(contacts.respond(s.mesh, {{0, 4}}, s.x, s.v, s.inv_m, 0.005f), 0);
  s.mesh.seam_pairs.resize(2, 1);
  s.mesh.seam_pairs << 4, 2;
  EXPECT_EQ(contacts.respond(s.mesh, {}, s.x, s.v, s.inv_m, 0.005f), 0);
  EXPECT_FLOAT_EQ(s.v(1, 4), -1);
}

// the grid finds a triangle torn across the space or with a non-finite corner (kept beside the grid) from any box,
// visits every triangle for a box over the whole space, and a small box only the triangles of its cells
TEST(TriangleGrid, TornAndNonFiniteTrianglesAreFoundAndHugeBoxesVisitEverything) {
  Points3 x(3, 8);
  x.col(0) = Vec3(0, 0, 0), x.col(1) = Vec3(0.01f, 0, 0), x.col(2) = Vec3(0, 0.01f, 0);
  x.col(3) = Vec3(1e6f, 0, 0), x.col(4) = Vec3(0, 0, std::numeric_limits<Real>::quiet_NaN());
  x.col(5) = Vec3(0.5f, 0.5f, 0.5f), x.col(6) = Vec3(0.51f, 0.5f, 0.5f), x.col(7) = Vec3(0.5f, 0.51f, 0.5f);
  // a small one at the origin, one a thousand kilometres long, one with a NaN corner, a small one at (0.5, 0.5, 0.5)
  const std::vector<TriangleGrid::Triangle> triangles{{0, 1, 2}, {0, 1, 3}, {0, 1, 4}, {5, 6, 7}};
  TriangleGrid grid;
  grid.build(x, triangles, 0.02);
  const auto found = [&](const Vec3& lo, const Vec3& hi) {
    std::vector<int> out;
    grid.near(lo, hi, [&](int t) { out.push_back(t); });
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
  };
  EXPECT_EQ(found(Vec3::Constant(-0.001f), Vec3::Constant(0.001f)), (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(found(Vec3(0.49f, 0.49f, 0.49f), Vec3(0.52f, 0.51f, 0.51f)), (std::vector<int>{1, 2, 3}));
  EXPECT_EQ(found(Vec3::Constant(-1e9f), Vec3::Constant(1e9f)), (std::vector<int>{0, 1, 2, 3}));
}

}  // namespace
}  // namespace clothbench
