// Layers of garments: an outer garment's points inside or too near the dressed cloth under it are moved out along
// its normal to the clearance; points clear of it, or beyond the reach, stay where they are. The cloth under is a
// moving body for the layer over it, facing out, given to its collider again once it has moved.
#include "clothbench/sim/layers.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

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

// a collider that keeps the bodies it is given and answers no point hit
class Recorder final : public Collider {
 public:
  std::string_view name() const override { return "recorder"; }
  void set_body(const BodyFrame& body) override { bodies.push_back(body), ++sets; }
  void update_body(const BodyFrame& body) override { bodies.push_back(body); }
  void query(PointsView points, ContactsOut out) override {
    queried += points.count;
    for (std::size_t i = 0; i < out.count; ++i) out[i] = Contact{};
  }
  CollideStats stats() const override { return {}; }
  std::vector<BodyFrame> bodies;
  std::size_t queried = 0;
  int sets = 0;
};

TEST(Layers, TheClothUnderIsABodyFacingOutGivenAgainOnceItHasMoved) {
  for (const bool inward : {false, true}) {  // the cells' winding does not decide which side is out
    SCOPED_TRACE(inward);
    const Cylinder inner(0.15f, 32, 6, inward), outer(0.17f, 32, 6);
    const Eigen::Index under = inner.x.cols();
    ClothMesh mesh;
    mesh.positions.resize(3, 2 * under);
    mesh.positions << inner.x, outer.x;
    mesh.quads.resize(4, 2 * inner.cells.cols());
    mesh.quads << inner.cells, (outer.cells.array() + std::int32_t(under)).matrix();
    Recorder recorder;
    LayersUnder layers(recorder, mesh, under, 0.002f, true);
    Points3 x = mesh.positions, v = Points3::Zero(3, 2 * under);
    layers.detect(x, v);
    ASSERT_EQ(recorder.bodies.size(), 1u);
    const BodyFrame& body = recorder.bodies[0];
    EXPECT_EQ(body.vertex_count(), under);
    EXPECT_EQ(body.triangle_count(), 2 * inner.cells.cols());
    EXPECT_TRUE(body.moving);
    for (Eigen::Index i = 0; i < under; ++i) EXPECT_GT(body.normals.col(i).dot(Vec3(x(0, i), 0, x(2, i))), 0) << i;
    // the points over it, then the midpoints of their quads
    EXPECT_EQ(layers.first_quad(), inner.cells.cols());
    EXPECT_EQ(layers.contacts().size(), std::size_t(under + outer.cells.cols()));
    EXPECT_EQ(recorder.queried, layers.contacts().size());
    // moved less than the redraw distance: the body stays as it was given
    x.leftCols(under).row(0).array() += 0.001f;
    layers.detect(x, v);
    EXPECT_EQ(recorder.bodies.size(), 1u);
    // one point more: given again, where the cloth is, with its velocities
    x(0, 5) += 0.0015f;
    v.col(5) = Vec3(1, 0, 0);
    layers.detect(x, v);
    ASSERT_EQ(recorder.bodies.size(), 2u);
    EXPECT_EQ(recorder.sets, 1);
    EXPECT_EQ(recorder.bodies[1].positions, x.leftCols(under));
    EXPECT_EQ(recorder.bodies[1].velocities(0, 5), 1.0f);
    EXPECT_EQ(layers.draws(), 2);
  }
  const Cylinder one(0.15f, 8, 3);
  ClothMesh mesh;
  mesh.positions = one.x;
  mesh.quads = one.cells;
  Recorder recorder;
  EXPECT_THROW(LayersUnder(recorder, mesh, 0, 0.002f, false), std::invalid_argument);
  EXPECT_THROW(LayersUnder(recorder, mesh, one.x.cols(), 0.002f, false), std::invalid_argument);
}

}  // namespace
}  // namespace clothbench
