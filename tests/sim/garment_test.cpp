#include "clothbench/sim/garment.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
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

TEST(Garment, SeamEdgesOfDifferentCountsGetVerticesUntilEveryOneHasAPartner) {
  // a back shorter than the front, and a slanted front side: the back's sides cross fewer grid rows
  Pattern pat = two_panel(40, 50);
  pat.panels[1] = rect("back", 40, 38);
  pat.panels[0].outline[2] = Vec2d(35, 50);
  for (const double h : {1.7, 2.3, 3.1, 4.4}) {
    const MeshedPattern m = mesh_pattern(pat, h);
    EXPECT_EQ(m.mesh.seam_loose.cols(), 0) << "spacing " << h;
    for (const double offset : m.seam_offset_cm) EXPECT_LT(offset, 1e-6) << "spacing " << h;
    // the added vertices are woven into the cloth: each has springs and cells, none of them of zero length
    std::vector<int> springs(static_cast<std::size_t>(m.mesh.vertex_count())), cells = springs;
    for (Eigen::Index s = 0; s < m.mesh.springs.cols(); ++s) {
      ++springs[static_cast<std::size_t>(m.mesh.springs(0, s))],
          ++springs[static_cast<std::size_t>(m.mesh.springs(1, s))];
      EXPECT_GT(m.mesh.rest_length[s], 0.2f * float(h) / 100);
    }
    for (Eigen::Index q = 0; q < m.mesh.quads.cols(); ++q)
      for (Eigen::Index k = 0; k < 4; ++k) ++cells[static_cast<std::size_t>(m.mesh.quads(k, q))];
    for (int v = 0; v < m.mesh.vertex_count(); ++v) {
      EXPECT_GE(springs[static_cast<std::size_t>(v)], 2) << "vertex " << v << ", spacing " << h;
      EXPECT_GE(cells[static_cast<std::size_t>(v)], 1) << "vertex " << v << ", spacing " << h;
    }
  }
}

TEST(Garment, EverySeamVertexIsPairedOrHasItsSegmentOfPartnerEdge) {
  // the back's left side is sewn twice: to the front, then to a taller flap. The second seam finds it
  // placed already, so the flap's side keeps more vertices than it, some without a partner
  Pattern pat = two_panel(40, 50);
  pat.panels[1] = rect("back", 40, 38);
  pat.panels.push_back(rect("flap", 10, 70));
  pat.seams.push_back({2, 3, 1, 3, false});
  const MeshedPattern m = mesh_pattern(pat, 2.3);
  const auto& loose = m.mesh.seam_loose;
  ASSERT_EQ(m.seam_loose_count.size(), 3u);
  EXPECT_EQ(m.seam_loose_count[0], 0);
  EXPECT_EQ(m.seam_loose_count[1], 0);
  EXPECT_GT(m.seam_loose_count[2], 0);
  EXPECT_EQ(loose.cols(), m.seam_loose_count[2]);
  const auto panel = [&](int v) { return m.mesh.panel[static_cast<std::size_t>(v)]; };
  const auto is_paired = [&](int v) { return (m.mesh.seam_pairs.array() == v).any(); };
  const std::array<double, 3> width{40, 40, 10}, height{50, 38, 70};
  for (Eigen::Index l = 0; l < loose.cols(); ++l) {
    const int v = loose(0, l), b0 = loose(1, l), b1 = loose(2, l);
    EXPECT_FALSE(is_paired(v)) << v;
    EXPECT_EQ(panel(v), 2);
    EXPECT_EQ(panel(b0), 1);
    EXPECT_EQ(panel(b1), 1);
    // in the pattern, the vertex's height up its side lies between its partner vertices' (as fractions of the sides)
    const auto up = [&](int u) { return m.uv(1, u) / height[static_cast<std::size_t>(panel(u))]; };
    EXPECT_LE(std::min(up(b0), up(b1)) - 1e-9, up(v)) << v;
    EXPECT_GE(std::max(up(b0), up(b1)) + 1e-9, up(v)) << v;
  }
  // every vertex on a sewn side is paired or listed without a partner
  for (int v = 0; v < m.mesh.vertex_count(); ++v) {
    const auto p = static_cast<std::size_t>(panel(v));
    const double u = m.uv(0, v), y = m.uv(1, v);
    const bool on_side = m.boundary[static_cast<std::size_t>(v)] && (u < 1e-9 || (p < 2 && u > width[p] - 1e-9)) &&
                         y > 1e-9 && y < height[p] - 1e-9;
    if (on_side) {
      EXPECT_TRUE(is_paired(v) || (loose.row(0).array() == v).any()) << "vertex " << v;
    }
  }
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

TEST(Garment, NoStructuralSpringFromTheOutlineInwardIsShorterThanHalfASpacing) {
  // a slanted side and a round panel cut the grid at every offset: the inside nodes nearest the outline stand
  // half a spacing off it, so the ring snapped onto the outline joins them by springs of at least that. Without
  // it they stood from a quarter of a spacing off it, and a millimetre of error on those springs was a large strain
  Pattern slanted = two_panel(40, 50);
  slanted.panels[0].outline[2] = Vec2d(31, 50);
  Pattern round;
  round.name = "disc";
  Panel disc;
  disc.name = "disc";
  for (int k = 0; k < 40; ++k)
    disc.outline.push_back(20 * Vec2d(std::cos(2 * M_PI * k / 40), std::sin(2 * M_PI * k / 40)));
  disc.edge_begin = {0};
  round.panels = {disc};
  for (const Pattern* pat : {&slanted, &round})
    for (double spacing : {1.7, 2.3, 3.1}) {
      const MeshedPattern m = mesh_pattern(*pat, spacing);
      double shortest = 1e9;
      for (Eigen::Index s = 0; s < m.mesh.springs.cols(); ++s) {
        const auto a = static_cast<std::size_t>(m.mesh.springs(0, s)), b = static_cast<std::size_t>(m.mesh.springs(1, s));
        if (m.mesh.kind[static_cast<std::size_t>(s)] == SpringKind::kStructural && m.boundary[a] != m.boundary[b])
          shortest = std::min(shortest, 100 * double(m.mesh.rest_length[s]));
      }
      std::printf("[ inward  ] %s, spacing %.1f cm: shortest spring from the outline inward %.3f spacings\n",
                  pat->name.c_str(), spacing, shortest / spacing);
      EXPECT_GE(shortest, (0.5 - 1e-4) * spacing) << pat->name << ", spacing " << spacing;
    }
}

TEST(Garment, NoSpringAlongTheOutlineOffTheSeamsIsShorterThanHalfASpacing) {
  // the shirt of scenes/garments/shirt.pattern: slanted shoulders sewn front to back, curved armholes and necklines
  // left open. Ring vertices snapped to nearby points of a curve, and a shoulder seam's end moved onto the neck's
  // corner beside the neckline's first vertex, made springs along the outline shorter than half a spacing. An edge
  // no seam places is spread evenly along itself when two of its vertices stand closer than that
  auto panel = [](const char* name, double neck_dip) {
    Panel p;
    p.name = name;
    auto edge = [&](std::vector<Vec2d> points) {
      p.edge_begin.push_back(static_cast<int>(p.outline.size()));
      p.outline.insert(p.outline.end(), points.begin(), points.end());
    };
    auto curve = [](Vec2d a, Vec2d c, Vec2d b) {
      auto pts = flatten_bezier(a, {c}, b, 12);
      pts.insert(pts.begin(), a);
      pts.pop_back();
      return pts;
    };
    edge({Vec2d(-26.4, 0)});                                          // hem
    edge({Vec2d(26.4, 0)});                                           // side_r
    edge(curve(Vec2d(25.3, 28), Vec2d(15.4, 30), Vec2d(13.2, 52)));   // armhole_r
    edge({Vec2d(13.2, 52)});                                          // shoulder_r
    edge(curve(Vec2d(8, 55), Vec2d(0, neck_dip), Vec2d(-8, 55)));     // neck
    edge({Vec2d(-8, 55)});                                            // shoulder_l
    edge(curve(Vec2d(-13.2, 52), Vec2d(-15.4, 30), Vec2d(-25.3, 28)));  // armhole_l
    edge({Vec2d(-25.3, 28)});                                         // side_l
    return p;
  };
  Pattern pat;
  pat.name = "shirt";
  pat.panels = {panel("front", 46), panel("back", 52)};
  pat.seams = {{0, 1, 1, 7, true}, {0, 7, 1, 1, true}, {0, 3, 1, 5, true}, {0, 5, 1, 3, true}};
  for (double spacing : {0.9, 1.2, 1.7, 2.3, 3.1}) {
    const MeshedPattern m = mesh_pattern(pat, spacing);
    std::vector<bool> sewn(static_cast<std::size_t>(m.mesh.vertex_count()), false);
    for (Eigen::Index k = 0; k < m.mesh.seam_pairs.size(); ++k)
      sewn[static_cast<std::size_t>(m.mesh.seam_pairs(k))] = true;
    double shortest = 1e9;
    for (Eigen::Index s = 0; s < m.mesh.springs.cols(); ++s) {
      const auto a = static_cast<std::size_t>(m.mesh.springs(0, s)), b = static_cast<std::size_t>(m.mesh.springs(1, s));
      if (m.mesh.kind[static_cast<std::size_t>(s)] == SpringKind::kStructural && m.boundary[a] && m.boundary[b] &&
          !(sewn[a] && sewn[b]))
        shortest = std::min(shortest, 100 * double(m.mesh.rest_length[s]));
    }
    std::printf("[ along   ] spacing %.1f cm: shortest spring along the outline off the seams %.3f spacings\n",
                spacing, shortest / spacing);
    EXPECT_GE(shortest, (0.5 - 1e-4) * spacing) << "spacing " << spacing;
  }
}

TEST(Garment, NoCellSpansTheHollowOfANeckline) {
  // a neckline's dip: a circular arc cut into the top of a panel. A cell whose corners the ring snaps onto the arc
  // would span the dip, cloth where the pattern has none, its midpoint (queried with face queries) in the neck
  Pattern pat;
  pat.name = "neckline";
  Panel front;
  front.name = "front";
  const Vec2d centre(20, 60);
  const double radius = 22;
  front.outline = {Vec2d(0, 0), Vec2d(40, 0), Vec2d(40, 50)};
  const double right = std::atan2(50 - centre.y(), std::sqrt(radius * radius - 100)), left = -M_PI - right;
  for (int k = 0; k <= 30; ++k) {
    const double a = right + (left - right) * k / 30;
    front.outline.push_back(centre + radius * Vec2d(std::cos(a), std::sin(a)));
  }
  front.outline.push_back(Vec2d(0, 50));
  front.edge_begin = {0};
  pat.panels = {front};
  for (double spacing : {1.7, 2.3, 3.1, 3.9}) {
    const MeshedPattern m = mesh_pattern(pat, spacing);
    double nearest = 1e9;  // the cells' middles' distance from the arc's centre
    for (Eigen::Index q = 0; q < m.mesh.quads.cols(); ++q) {
      Vec2d mid = Vec2d::Zero();
      for (int k = 0; k < 4; ++k) mid += 0.25 * m.uv.col(m.mesh.quads(k, q));
      nearest = std::min(nearest, (mid - centre).norm());
    }
    std::printf("[ hollow  ] spacing %.1f cm: the cell middle nearest the dip %.3f cm below its arc (negative: in it)\n",
                spacing, nearest - radius);
    EXPECT_GE(nearest, radius - 1e-6) << "spacing " << spacing;
  }
}

// A panel symmetric about x = 0 with slanted sides, a bend and a curved top (a skirt's or a bodice's), and its twin
// turned round, sewn side to side as the drafted garments are.
Pattern slanted_pair() {
  Panel p;
  p.name = "front";
  p.outline = {{-30, 0}, {30, 0}, {24, 20}, {19, 45}, {8, 52}, {0, 47}, {-8, 52}, {-19, 45}, {-24, 20}};
  p.edge_begin = {0, 1, 3, 7};  // hem, side_r (with its bend), top, side_l
  Pattern pat;
  pat.name = "pair";
  pat.panels = {p, p};
  pat.panels[1].name = "back";
  pat.seams = {{0, 1, 1, 3, true}, {0, 3, 1, 1, true}};
  return pat;
}

// Durupinar's construction (section 2): every vertex a grid node, so every structural spring one spacing and every
// shear spring a diagonal; the two mirrored sides drawn as matching staircases, every vertex paired with none left
// over
TEST(Garment, OnTheGridEveryVertexIsAGridNodeAndMirroredSeamsPairUp) {
  const Pattern pat = slanted_pair();
  for (const double h : {1.7, 2.9, 4.3}) {
    const MeshedPattern m = mesh_pattern(pat, h, true, true);
    const ClothMesh& c = m.mesh;
    for (Eigen::Index s = 0; s < c.springs.cols(); ++s) {
      const double expected = c.kind[static_cast<std::size_t>(s)] == SpringKind::kStructural ? h
                              : c.kind[static_cast<std::size_t>(s)] == SpringKind::kShear    ? h * std::sqrt(2.0)
                                                                                             : 2 * h;
      EXPECT_NEAR(100 * c.rest_length[s], expected, 1e-4) << "spring " << s << ", spacing " << h;
    }
    EXPECT_EQ(slivers(m).total(), 0);
    ASSERT_EQ(m.seam_pair_count.size(), 2u);
    EXPECT_EQ(m.seam_pair_count[0], m.seam_pair_count[1]);
    EXPECT_GE(m.seam_pair_count[0], static_cast<int>(45 / h));
    for (int loose : m.seam_loose_count) EXPECT_EQ(loose, 0) << "spacing " << h;
    for (double offset : m.seam_offset_cm) EXPECT_LT(offset, 1e-9) << "spacing " << h;
    // the drawn panel follows its outline: its points on nodes a column outward and half a row off at most, the
    // lines between them within half a diagonal of those
    for (int v = 0; v < c.vertex_count(); ++v) {
      if (!m.boundary[static_cast<std::size_t>(v)]) continue;
      EXPECT_LT(distance_to_outline(pat.panels[0].outline, m.uv.col(v)), 1.62 * h) << "spacing " << h;
    }
    // the ring mesher, for comparison: vertices on the outline itself
    std::printf("[ on grid ] spacing %.1f cm: %d vertices on the grid, %d with the ring snapped onto the outline\n", h,
                c.vertex_count(), mesh_pattern(pat, h).mesh.vertex_count());
  }
  // a strip thinner than a spacing is drawn a cell tall (the grid is centred on its box, between two rows)
  const MeshedPattern strip = mesh_pattern(two_panel(10, 0.5), 5, true, true);
  EXPECT_GT(strip.mesh.quads.cols(), 0);
}

// Durupinar's step 7 (MeshingOptions::smooth): the drawn outline's vertices moved onto the outline, as far as keeps
// every structural spring at least half a spacing long; the seams' runs aligned, every vertex paired at its partner's
// arc fraction
TEST(Garment, SmoothedOnTheGridTheOutlineIsFollowedWithoutSlivers) {
  const Pattern pat = slanted_pair();
  for (const double h : {1.7, 2.9, 4.3}) {
    const MeshedPattern drawn = mesh_pattern(pat, h, true, true), smooth = mesh_pattern(pat, h, true, true, true);
    ASSERT_GE(smooth.mesh.vertex_count(), drawn.mesh.vertex_count());
    EXPECT_EQ(slivers(smooth).total(), 0) << "spacing " << h << ": along " << slivers(smooth).along << ", inward " << slivers(smooth).inward;
    for (Eigen::Index s = 0; s < smooth.mesh.springs.cols(); ++s) {
      if (smooth.mesh.kind[static_cast<std::size_t>(s)] != SpringKind::kStructural) continue;
      EXPECT_GE(100 * smooth.mesh.rest_length[s], 0.5 * h - 1e-4) << "spring " << s << ", spacing " << h;
    }
    int on = 0, boundary = 0;
    double before = 0, after = 0;
    for (int v = 0; v < smooth.mesh.vertex_count(); ++v) {
      if (!smooth.boundary[static_cast<std::size_t>(v)]) continue;
      const auto& outline = pat.panels[0].outline;
      const double d = distance_to_outline(outline, smooth.uv.col(v));
      ++boundary, on += d < 1e-6, after = std::max(after, d);
      before = std::max(before, distance_to_outline(outline, drawn.uv.col(v)));
    }
    std::printf("[ smooth ] spacing %.1f cm: %d of %d outline vertices on the outline, farthest %.2f cm (drawn: %.2f)\n",
                h, on, boundary, after, before);
    EXPECT_GE(on, boundary * 3 / 4) << "spacing " << h;
    EXPECT_LT(after, 0.75 * h) << "spacing " << h;  // drawn: up to a column and a half outward
    EXPECT_EQ(smooth.seam_pair_count[0], smooth.seam_pair_count[1]);
    for (int loose : smooth.seam_loose_count) EXPECT_EQ(loose, 0) << "spacing " << h;
    for (double offset : smooth.seam_offset_cm) EXPECT_LT(offset, 1e-9) << "spacing " << h;
  }
  EXPECT_THROW(mesh_pattern(pat, 2.0, true, false, true), std::invalid_argument);  // the ring is smooth already
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
  pat = two_panel(40, 50);
  pat.panels[1].outline = {Vec2d(0, 0), Vec2d(20, 0), Vec2d(40, 0), Vec2d(10, 0)};  // no area
  EXPECT_THROW(validate_pattern(pat), std::invalid_argument);
}

std::vector<Vec2d> points(std::initializer_list<std::array<double, 2>> xy) {
  std::vector<Vec2d> out;
  for (const auto& p : xy) out.push_back(Vec2d(p[0], p[1]));
  return out;
}

TEST(Garment, OutlineFaultsFromBoostGeometry) {
  // simple outlines pass whichever way they turn, straight runs of several points included
  for (const auto& o :
       {points({{0, 0}, {10, 0}, {20, 0}, {20, 10}, {0, 10}}), points({{0, 0}, {0, 10}, {20, 10}, {20, 0}, {10, 0}})}) {
    const OutlineFault f = outline_fault(o);
    EXPECT_EQ(f.what, "");
    EXPECT_EQ(f.segment, -1);
    EXPECT_FALSE(outline_self_intersects(o));
  }
  struct Case {
    const char* name;
    std::vector<Vec2d> outline;
    const char* what;
    int segment, other;
    Vec2d at;
  };
  const Case cases[] = {
      // segments 0 and 2 cross in the middle
      {"bow tie", points({{0, 0}, {4, 4}, {4, 0}, {0, 4}}), "intersects itself", 2, 0, Vec2d(2, 2)},
      // two lobes meet at one point (20, 20), the outline touching itself; clockwise too
      {"figure eight", points({{0, 0}, {20, 0}, {20, 20}, {40, 20}, {40, 40}, {20, 40}, {20, 20}, {0, 20}}),
       "intersects itself", 5, 1, Vec2d(20, 20)},
      {"figure eight, clockwise", points({{0, 20}, {20, 20}, {20, 40}, {40, 40}, {40, 20}, {20, 20}, {20, 0}, {0, 0}}),
       "intersects itself", 4, 0, Vec2d(20, 20)},
      // a point of the outline lies on another segment
      {"touching an edge", points({{0, 0}, {40, 0}, {40, 40}, {20, 0}, {0, 40}}), "intersects itself", 2, 0,
       Vec2d(20, 0)},
      // the outline runs back along the segment it came on (collinear overlap)
      {"spike", points({{0, 0}, {50, 0}, {40, 0}, {40, 50}, {0, 50}}), "runs back along itself", 1, 0, Vec2d(50, 0)},
      {"no area", points({{0, 0}, {20, 0}, {40, 0}}), "runs back along itself", 2, 1, Vec2d(40, 0)},
      {"far away", points({{0, 0}, {2e6, 0}, {0, 10}}), "beyond", 1, -1, Vec2d(2e6, 0)},
      {"not finite", points({{0, 0}, {10, 0}, {std::nan(""), 10}}), "not finite", 2, -1, Vec2d::Constant(std::nan(""))},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.name);
    const OutlineFault f = outline_fault(c.outline);
    EXPECT_NE(f.what.find(c.what), std::string::npos) << f.what;
    EXPECT_EQ(f.segment, c.segment);
    EXPECT_EQ(f.other_segment, c.other);
    if (c.at.allFinite()) {
      EXPECT_LT((f.at - c.at).norm(), 1e-9) << f.at.transpose();
    }
    EXPECT_TRUE(outline_self_intersects(c.outline));
  }
  // Boost's integer rescaling cannot take a vanishingly small outline: an answer, not an exception
  EXPECT_NO_THROW(outline_fault(points({{0, 0}, {1e-14, 0}, {1e-14, 1e-14}, {0, 1e-14}})));
}

// Meshes one panel at spacing h and counts its vertices, checking the corners are among them.
int exact_grid_vertices(const Panel& panel, double h) {
  Pattern pat;
  pat.name = "grid";
  pat.panels = {panel};
  const MeshedPattern m = mesh_pattern(pat, h);
  for (const auto& corner : panel.outline) {
    bool found = false;
    for (Eigen::Index v = 0; v < m.uv.cols(); ++v) found = found || (m.uv.col(v) - corner).norm() < 1e-9;
    EXPECT_TRUE(found) << "no vertex at the corner (" << corner.transpose() << ") at spacing " << h;
  }
  return m.mesh.vertex_count();
}

TEST(Garment, SpacingThatDividesARectangleKeepsEveryGridVertex) {
  // every grid node on the outline is a vertex: the (u-min, v-min) corner was dropped (1,848 of 1,849)
  Panel square = rect("cloth", 100, 100);
  for (auto& q : square.outline) q.x() -= 50;  // as the pattern file's `rect`: bottom edge centred
  EXPECT_EQ(exact_grid_vertices(square, 100.0 / 42), 43 * 43);
  EXPECT_EQ(exact_grid_vertices(square, 2), 51 * 51);
  EXPECT_EQ(exact_grid_vertices(square, 100.0 / 3), 4 * 4);
  EXPECT_EQ(exact_grid_vertices(rect("wide", 200, 100), 10), 21 * 11);
  EXPECT_EQ(exact_grid_vertices(rect("tall", 30, 70), 100.0 / 30), 10 * 22);
  // clockwise, and away from the origin
  Panel cw = rect("cw", 36, 12);
  std::reverse(cw.outline.begin(), cw.outline.end());
  for (auto& q : cw.outline) q += Vec2d(13.7, -41.3);
  EXPECT_EQ(exact_grid_vertices(cw, 1.2), 31 * 11);
  // an L (a reflex corner at (10, 10)): 11 x 11 nodes less the 5 x 5 of the missing quarter
  Panel ell;
  ell.name = "ell";
  ell.outline = points({{0, 0}, {20, 0}, {20, 10}, {10, 10}, {10, 20}, {0, 20}});
  ell.edge_begin = {0, 1, 2, 3, 4, 5};
  EXPECT_EQ(exact_grid_vertices(ell, 2), 11 * 11 - 5 * 5);
}

TEST(Garment, SpacingThatDividesARectangleMakesFullCells) {
  Pattern pat;
  pat.name = "grid";
  pat.panels = {rect("cloth", 200, 100)};
  const MeshedPattern m = mesh_pattern(pat, 10);
  EXPECT_EQ(m.mesh.quads.cols(), 20 * 10);
  for (Eigen::Index q = 0; q < m.mesh.quads.cols(); ++q) EXPECT_NE(m.mesh.quads(3, q), m.mesh.quads(2, q));
  int boundary = 0;
  for (auto b : m.boundary) boundary += b;
  EXPECT_EQ(boundary, 2 * (21 + 11) - 4);
}

}  // namespace
}  // namespace clothbench
