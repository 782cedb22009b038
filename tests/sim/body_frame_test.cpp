#include "clothbench/sim/body_frame.hpp"

#include <gtest/gtest.h>

#include "test_support.hpp"

namespace clothbench {
namespace {

TEST(BodyFrame, SphereIsClosedWithOutwardNormals) {
  const BodyFrame s = make_sphere_body(Vec3(1, 2, 3), 0.5f, 12, 24);
  EXPECT_TRUE(check_edges(s.triangles).closed());
  for (int v = 0; v < s.vertex_count(); ++v) {
    const Vec3 radial = (s.positions.col(v) - Vec3(1, 2, 3)).normalized();
    EXPECT_LT(test::angle_deg(s.normals.col(v), radial), 1.0) << "vertex " << v;
  }
}

TEST(BodyFrame, CapsuleIsClosedAndSpansItsLength) {
  const BodyFrame c = make_capsule_body(Vec3::Zero(), 0.1f, 0.4f);
  EXPECT_TRUE(check_edges(c.triangles).closed());
  const Box3 box = bounding_box(c.positions);
  EXPECT_NEAR(box.min.y(), -0.3f, 1e-6);
  EXPECT_NEAR(box.max.y(), 0.3f, 1e-6);
  EXPECT_NEAR(box.max.x(), 0.1f, 1e-6);
}

TEST(BodyFrame, OpenMeshCountsBoundaryEdges) {
  BodyFrame s = make_sphere_body(Vec3::Zero(), 1, 4, 6);
  const Eigen::Index nt = s.triangles.cols();
  s.triangles.conservativeResize(3, nt - 1);  // drop one triangle: three boundary edges
  EXPECT_EQ(check_edges(s.triangles).boundary_edges, 3);
}

TEST(BodyFrame, SubdivisionQuadruplesTrianglesAndStaysClosed) {
  const BodyFrame s = make_sphere_body(Vec3::Zero(), 1, 6, 8);
  const BodyFrame d = subdivide_body(s);
  EXPECT_EQ(d.triangle_count(), 4 * s.triangle_count());
  EXPECT_TRUE(check_edges(d.triangles).closed());
}

TEST(BodyFrame, ValidateRejectsBadFrames) {
  BodyFrame s = make_sphere_body(Vec3::Zero(), 1, 4, 6);
  s.positions(0, 3) = std::nanf("");
  EXPECT_THROW(validate_body(s, "test"), std::invalid_argument);
  BodyFrame empty;
  EXPECT_THROW(validate_body(empty, "test"), std::invalid_argument);
  BodyFrame bad = make_sphere_body(Vec3::Zero(), 1, 4, 6);
  bad.triangles(0, 0) = 10000;
  EXPECT_THROW(validate_body(bad, "test"), std::invalid_argument);
}

}  // namespace
}  // namespace clothbench
