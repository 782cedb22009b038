#include "clothbench/sim/garment.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <stdexcept>

namespace clothbench {
namespace {

// A rectangle w x h [cm] with edges bottom(0), right(1), top(2), left(3).
Panel rect(const std::string& name, double w, double h) {
  Panel p;
  p.name = name;
  p.outline = {Vec2d(0, 0), Vec2d(w, 0), Vec2d(w, h), Vec2d(0, h)};
  p.edge_begin = {0, 1, 2, 3};
  return p;
}

// Two panels sewn along both sides, like the papers' two-panel shirt or skirt.
Pattern two_panel(double w, double h) {
  Pattern pat;
  pat.name = "tube";
  pat.panels = {rect("front", w, h), rect("back", w, h)};
  pat.seams = {{0, 1, 1, 3, true}, {0, 3, 1, 1, true}};
  return pat;
}

TEST(Garment, VertexCountsWithinFivePercent) {
  // paper counts (dressing section 7, Table 1/2; Durupinar section 5)
  for (int target : {544, 1800, 336, 672, 1024, 3840, 600, 272, 1400, 2774}) {
    MeshingOptions o;
    o.target_vertices = target;
    const MeshedPattern m = mesh_pattern(two_panel(50, 60), o);
    EXPECT_NEAR(m.mesh.vertex_count(), target, 0.05 * target) << "target " << target;
  }
}

TEST(Garment, BoundaryOnOutlineAndSeamsMatched) {
  Pattern pat = two_panel(40, 50);
  // a slanted edge exercises snapping off the grid lines
  pat.panels[0].outline[2] = Vec2d(35, 50);
  const MeshedPattern m = mesh_pattern(pat, 2.3);
  int on = 0;
  for (int v = 0; v < m.mesh.vertex_count(); ++v) {
    if (!m.boundary[static_cast<std::size_t>(v)]) continue;
    const auto& o = pat.panels[static_cast<std::size_t>(m.mesh.panel[static_cast<std::size_t>(v)])].outline;
    EXPECT_LT(distance_to_outline(o, m.uv.col(v)) / 100.0, 1e-6);
    ++on;
  }
  EXPECT_GT(on, 40);
  ASSERT_EQ(m.seam_pair_count.size(), 2u);
  for (int c : m.seam_pair_count) EXPECT_GE(c, 20);
  for (Eigen::Index s = 0; s < m.mesh.seam_pairs.cols(); ++s)
    EXPECT_NE(m.mesh.panel[static_cast<std::size_t>(m.mesh.seam_pairs(0, s))],
              m.mesh.panel[static_cast<std::size_t>(m.mesh.seam_pairs(1, s))]);
  EXPECT_EQ(m.mesh.count(SpringKind::kStructural) > 0 && m.mesh.count(SpringKind::kShear) > 0 &&
                m.mesh.count(SpringKind::kFlexion) > 0,
            true);
  EXPECT_GT(m.mesh.quads.cols(), 0);
}

TEST(Garment, CellsCoverThePanelUpToItsOutline) {
  // a panel with a slanted side: the cells the outline cuts along it have three kept corners and
  // become triangles, so the cloth's area (its masses) and its faces reach the outline. With full
  // cells only, a staircase of triangles along the slant was missing (a hole in every picture)
  Pattern pat = two_panel(40, 50);
  pat.panels[0].outline[2] = Vec2d(31, 50);
  const double area_cm2 = 0.5 * (40 + 31) * 50;
  for (double spacing : {1.7, 2.3, 3.1}) {
    const MeshedPattern m = mesh_pattern(pat, spacing);
    double cloth_cm2 = 0;
    int triangles = 0;
    for (int v = 0; v < m.mesh.vertex_count(); ++v)
      if (m.mesh.panel[static_cast<std::size_t>(v)] == 0) cloth_cm2 += 1e4 * double(m.mesh.vertex_area[v]);
    for (Eigen::Index q = 0; q < m.mesh.quads.cols(); ++q) triangles += m.mesh.quads(3, q) == m.mesh.quads(2, q);
    std::printf("[ area    ] spacing %.1f cm: cloth %.1f cm^2 of %.1f, %d triangles\n", spacing, cloth_cm2, area_cm2,
                triangles);
    EXPECT_NEAR(cloth_cm2, area_cm2, 1e-3 * area_cm2) << "spacing " << spacing;  // full cells only: 0.2-0.4 % short
    EXPECT_GT(triangles, 0);
  }
}

TEST(Garment, RejectsBadPatterns) {
  Pattern pat = two_panel(40, 50);
  pat.seams.push_back(pat.seams[0]);
  EXPECT_THROW(validate_pattern(pat), std::invalid_argument);
  pat = two_panel(40, 50);
  pat.seams[0].edge_b = 9;
  EXPECT_THROW(validate_pattern(pat), std::invalid_argument);
  pat = two_panel(40, 50);
  std::swap(pat.panels[0].outline[1], pat.panels[0].outline[2]);  // bow tie
  EXPECT_THROW(validate_pattern(pat), std::invalid_argument);
}

}  // namespace
}  // namespace clothbench
