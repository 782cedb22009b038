// Image space beyond the papers: views 4 and 6 (pairs of cameras along X and Y) and a side layer of
// fixed width in millimetres (ColliderOptions::views, side_layer_mm).
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <stdexcept>
#include <vector>

#include "clothbench/collide_is/image_space_collider.hpp"
#include "is_test_bodies.hpp"
#include "test_support.hpp"

namespace clothbench {
namespace {

// points 2 mm outside a sphere of radius r at c along side-facing normals n = (cos t, sin t, 0),
// every `step` degrees: the papers' front/back cameras see these surfaces edge-on
Points3 side_points(const Vec3& c, Real r, int step) {
  Points3 p(3, 360 / step);
  for (int k = 0; k < p.cols(); ++k) {
    const double t = k * step * M_PI / 180;
    p.col(k) = c + (r + 0.002f) * Vec3(Real(std::cos(t)), Real(std::sin(t)), 0.0f);
  }
  return p;
}

// share of `p` answered hit by is-cpu with `views` views
double hit_share(const BodyFrame& body, const Points3& p, int views, bool side_layer) {
  ColliderOptions o;
  o.views = views;
  o.side_layer = side_layer;
  auto c = make_is_cpu_collider(o);
  c->set_body(body);
  std::vector<Contact> out(static_cast<std::size_t>(p.cols()));
  c->query(PointsView(p), ContactsOut{out.data(), out.size()});
  long hits = 0;
  for (const Contact& k : out) hits += k.hit;
  return double(hits) / double(out.size());
}

TEST(ImageSpaceViews, MoreViewsHitTheSphereSidesWhereTwoMiss) {
  const Vec3 c(0.0f, 0.5f, 0.0f);
  const Real r = 0.3f;
  const BodyFrame s = make_sphere_body(c, r, 64, 128);
  const Points3 p = side_points(c, r, 5);
  for (bool layer : {false, true}) {
    const double h2 = hit_share(s, p, 2, layer), h4 = hit_share(s, p, 4, layer), h6 = hit_share(s, p, 6, layer);
    std::cout << "[ views ] sphere sides 2 mm out (" << p.cols() << " points), side layer " << (layer ? "on" : "off")
              << ": hit 2 views " << 100 * h2 << " %, 4 views " << 100 * h4 << " %, 6 views " << 100 * h6 << " %\n";
    // the pair along X answers near +-X, the pair along Y near +-Y
    EXPECT_GE(h4, h2 + (layer ? 0.0 : 0.5));
    EXPECT_GE(h6, 0.99);
    if (!layer) {
      EXPECT_LT(h2, 0.1);
    }
  }
}

// collider.tangent_plane: a point 3 mm outside a sphere at 55 degrees from the view axis lies 5.2 mm
// from the surface along z: the papers' comparison (tangent_plane = false) misses it at tol 5 mm, the
// tangent-plane refinement (the default) finds it 3 mm out
TEST(ImageSpaceDepthTest, TheOptionChoosesThePapersComparisonOrTheTangentPlane) {
  const Vec3 c(0.0f, 0.5f, 0.0f);
  const Real r = 0.3f;
  const BodyFrame s = make_sphere_body(c, r, 64, 128);
  const double t = 55 * M_PI / 180;
  Points3 p(3, 1);
  p.col(0) = c + (r + 0.003f) * Vec3(Real(std::sin(t)), 0.0f, Real(std::cos(t)));
  for (bool plane : {true, false}) {
    ColliderOptions o;
    o.tangent_plane = plane;
    auto col = make_is_cpu_collider(o);
    col->set_body(s);
    Contact k;
    col->query(PointsView(p), ContactsOut{&k, 1});
    EXPECT_EQ(k.hit, plane) << (plane ? "tangent plane" : "papers' z test");
    if (plane) {
      EXPECT_NEAR(k.depth, 0.003f, 0.001f);
    }
  }
}

// the extra views are the same cameras turned: a sphere's maps along X and Y hold the sphere
TEST(ImageSpaceViews, ExtraViewsSeeTheSphereAlongTheirAxes) {
  const Vec3 c(0.05f, 0.5f, -0.02f);
  const Real r = 0.25f;
  ColliderOptions o;
  o.views = 6;
  o.side_layer = false;
  const MapSet m = render_maps(make_sphere_body(c, r, 64, 128), "cpu", o);
  ASSERT_EQ(m.z.size(), 6 * m.view_pixels());
  const MapFrame& f = m.frame;
  long checked = 0;
  for (int view = 2; view < 6; ++view) {
    const int cu = MapFrame::column_axis(view), rv = MapFrame::row_axis(view), d = MapFrame::view_axis(view);
    for (int row = 0; row < f.size; ++row)
      for (int col = 0; col < f.size; ++col) {
        const Real a = f.origin(cu) + (col + 0.5f) * f.pixel - c[cu], b = f.origin(rv) + (row + 0.5f) * f.pixel - c[rv];
        const Real h2 = r * r - a * a - b * b;
        const std::size_t i = m.index(view, col, row);
        // coverage away from the rim (tessellation), depth within the chord sag of the 64 x 128 sphere
        if (h2 < 0.01f * r * r && h2 > -0.01f * r * r) continue;
        ASSERT_EQ(m.mask[i] == MapSet::kBody, h2 > 0) << view << " " << col << "," << row;
        if (h2 <= 0) continue;
        const Real expect = c[d] + (view % 2 == 0 ? 1 : -1) * std::sqrt(h2);
        EXPECT_NEAR(m.z[i], expect, 0.003f) << view << " " << col << "," << row;
        ++checked;
      }
  }
  EXPECT_GT(checked, 4 * 10000);
}

TEST(GlMaps, SameAsCpuWithFourAndSixViews) {
  CLOTHBENCH_REQUIRE_GL();
  const BodyModel& model = test::test_body_model();
  for (int views : {4, 6}) {
    ColliderOptions o;
    o.views = views;
    o.side_layer = false;
    test::expect_gl_matches_cpu(make_sphere_body(Vec3(0.01f, 0.4f, 0.02f), 0.25f), o, "sphere");
    test::expect_gl_matches_cpu(model.rest(), o, model.path().c_str());
    o.side_layer = true;  // the layer is added after rendering, the same way for both
    test::expect_gl_matches_cpu(model.rest(), o, model.path().c_str());
  }
}

TEST(ImageSpaceViews, SideLayerMillimetresSetTheRingWidth) {
  ColliderOptions o;
  EXPECT_EQ(side_layer_rings(o, 0.005f), 1);
  o.side_layer_mm = 3;
  EXPECT_EQ(side_layer_rings(o, 0.005f), 1);   // 3 mm within one 5 mm pixel
  EXPECT_EQ(side_layer_rings(o, 0.0017f), 2);  // 1024^2 over 1.75 m
  EXPECT_EQ(side_layer_rings(o, 0.001f), 3);
  o.side_layer = false;
  EXPECT_EQ(side_layer_rings(o, 0.001f), 0);
  // a sphere's ring is as wide as asked: 6 mm at 1 mm pixels ~ 6 rings of 2 pi R pixels each
  const BodyFrame s = make_sphere_body(Vec3(0, 0.5f, 0), 0.3f);
  ColliderOptions wide;
  wide.map_size = 600;  // 1 mm pixels
  wide.side_layer_mm = 6;
  const MapSet one = render_maps(s, "cpu", ColliderOptions{}), six = render_maps(s, "cpu", wide);
  long ring1 = 0, ring6 = 0;
  for (auto v : one.mask) ring1 += v == MapSet::kSide;
  for (auto v : six.mask) ring6 += v == MapSet::kSide;
  const double circumference = 2 * M_PI * 0.3 / six.frame.pixel;
  EXPECT_GT(ring6, 2 * 6 * circumference * 0.9);
  EXPECT_LT(ring6, 2 * 6 * circumference * 1.5);
  EXPECT_GT(ring1, 0);
}

TEST(ImageSpaceViews, BadViewCountsAndWidthsAreRejected) {
  for (int views : {0, 1, 3, 5, 8}) {
    ColliderOptions o;
    o.views = views;
    try {
      make_is_cpu_collider(o);
      ADD_FAILURE() << views << " views accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("2 (front/back), 4 (+ left/right) or 6 (+ top/bottom)"), std::string::npos)
          << e.what();
    }
    EXPECT_THROW(render_maps(make_sphere_body(Vec3::Zero(), 1), "cpu", o), std::invalid_argument);
  }
  ColliderOptions o;
  o.side_layer_mm = -1;
  EXPECT_THROW(make_is_cpu_collider(o), std::invalid_argument);
}

}  // namespace
}  // namespace clothbench
