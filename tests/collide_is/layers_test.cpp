// Image space beyond the papers: surfaces peeled along each pair's axis (ColliderOptions::layers), so a
// point inside a body part that other parts hide from every camera is answered by that part's surface.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <stdexcept>
#include <vector>

#include "clothbench/collide_is/image_space_collider.hpp"
#include "clothbench/io/body_loader.hpp"
#include "is_test_bodies.hpp"
#include "test_support.hpp"

namespace clothbench {
namespace {

// one closed body of several spheres (separate components) of radius r at `centres`
BodyFrame spheres(const std::vector<Vec3>& centres, Real r) {
  BodyFrame all;
  std::vector<BodyFrame> parts;
  Eigen::Index nv = 0, nt = 0;
  for (const Vec3& c : centres) {
    parts.push_back(make_sphere_body(c, r, 48, 96));
    nv += parts.back().vertex_count(), nt += parts.back().triangle_count();
  }
  all.positions.resize(3, nv), all.triangles.resize(3, nt);
  Eigen::Index v = 0, t = 0;
  for (const BodyFrame& p : parts) {
    all.positions.middleCols(v, p.vertex_count()) = p.positions;
    all.triangles.middleCols(t, p.triangle_count()) = p.triangles.array() + static_cast<int>(v);
    v += p.vertex_count(), t += p.triangle_count();
  }
  finish_static_body(all);
  return all;
}

// the is-cpu answer at one point, with 6 views and `layers`, the square fitted to the body (the papers'
// square, side = body height, would not hold the spheres spread along X)
Contact answer(const BodyFrame& body, int layers, const Vec3& p, bool overlapping_parts = true) {
  ColliderOptions o;
  o.views = 6;
  o.layers = layers;
  o.overlapping_parts = overlapping_parts;
  o.fit_extent = true;
  auto c = make_is_cpu_collider(o);
  c->set_body(body);
  Points3 q(3, 1);
  q.col(0) = p;
  Contact k;
  c->query(PointsView(q), ContactsOut{&k, 1});
  return k;
}

// two spheres one behind the other: the front view's layers are the four surfaces along the line
TEST(ImageSpaceLayers, PeeledMapsListEverySurfaceAlongTheLine) {
  const Real r = 0.15f;
  const BodyFrame body = spheres({Vec3(0, 0.5f, 0.2f), Vec3(0, 0.5f, -0.2f)}, r);
  ColliderOptions o;
  o.layers = 5;
  o.side_layer = false;
  for (const char* renderer : {"cpu", "gl"}) {
    if (std::string(renderer) == "gl" && !test::gl_unavailable().empty()) continue;
    const MapSet m = render_maps(body, renderer, o);
    const MapFrame& f = m.frame;
    ASSERT_EQ(f.map_count(), 2 + 4);
    ASSERT_EQ(m.z.size(), 6 * m.view_pixels());
    // the pixel whose centre is nearest the spheres' axis
    const int col = static_cast<int>(f.front_u(0)), row = static_cast<int>(f.map_v(0.5f));
    const Real expect[] = {0.35f, 0.05f, -0.05f, -0.35f};
    for (int layer = 1; layer <= 4; ++layer) {
      const std::size_t i = m.index(f.peel_map(MapSet::kFront, layer), col, row);
      ASSERT_EQ(m.mask[i], MapSet::kBody) << renderer << " layer " << layer;
      EXPECT_NEAR(m.z[i], expect[layer - 1], 0.002f) << renderer << " layer " << layer;
      EXPECT_EQ(f.view_of(f.peel_map(MapSet::kFront, layer)), MapSet::kFront);
      EXPECT_EQ(f.layer_of(f.peel_map(MapSet::kFront, layer)), layer);
    }
    // nothing beyond the fourth surface
    EXPECT_EQ(m.mask[m.index(f.peel_map(MapSet::kFront, 5), col, row)], MapSet::kEmpty) << renderer;
  }
}

// an "arm" sphere beside a "torso" one, with spheres in front of it, behind it, above and below it:
// a point 2 mm inside the arm next to the side facing the torso is hidden from every camera (along X
// by the torso and the arm's outer side, along Y and Z by the other spheres). The papers' single
// surface per view answers it by the arm's outer side, 23 cm away; peeled layers by the side it is
// nearest to, along -X
TEST(ImageSpaceLayers, APointHiddenFromEveryCameraIsAnsweredByTheSurfaceItIsNearest) {
  const Real r = 0.12f, d = 0.26f;
  const Vec3 arm(0.3f, 0.5f, 0.0f);
  const BodyFrame body = spheres(
      {Vec3(0.0f, 0.5f, 0.0f), arm, arm + Vec3(0, 0, d), arm - Vec3(0, 0, d), arm + Vec3(0, d, 0), arm - Vec3(0, d, 0)},
      r);
  const Vec3 p = arm - Vec3(r - 0.002f, 0, 0);
  for (int layers : {1, 3}) {
    const Contact k = answer(body, layers, p);
    std::cout << "[ layers ] " << layers << ": depth " << 1e3 * k.depth << " mm (exact -2 mm), normal ("
              << k.normal.transpose() << ")\n";
    ASSERT_TRUE(k.hit) << layers;
    if (layers == 1) {
      EXPECT_LT(k.depth, -0.1f);
      EXPECT_GT(k.normal.x(), 0.9f);  // pushed out through the outer side
    } else {
      EXPECT_NEAR(k.depth, -0.002f, 0.001f);
      EXPECT_LT(k.normal.x(), -0.95f);
    }
  }
}

// a point in the gap between two parts that every camera sees covered (a body on both sides along
// each axis) is outside with layers, inside the visual hull without
TEST(ImageSpaceLayers, AGapEveryCameraSeesCoveredIsOutsideWithLayers) {
  const Real r = 0.12f;
  // a ring of four spheres around the point in the x-z plane, and one above and below it
  const Vec3 p(0.0f, 0.5f, 0.0f);
  const Real d = 0.16f;
  const BodyFrame body = spheres({p + Vec3(d, 0, 0), p - Vec3(d, 0, 0), p + Vec3(0, 0, d), p - Vec3(0, 0, d),
                                  p + Vec3(0, d, 0), p - Vec3(0, d, 0)},
                                 r);
  for (int layers : {1, 3}) {
    const Contact k = answer(body, layers, p);
    EXPECT_EQ(k.hit, layers == 1) << layers << " layers, depth " << k.depth;
  }
}

// two overlapping spheres (an arm pressed into the torso, as skinning makes them): along X the line
// enters one, enters the other, leaves the first and leaves the second; a point where they overlap is
// inside both, which alternating in and out along the line would call a gap. It is where cloth caught
// between the parts is pinched: held there (depth 0), not pushed 66 mm out of the union
TEST(ImageSpaceLayers, WhereTwoPartsOverlapThePointIsInsideAndHeld) {
  const Real r = 0.12f;
  const BodyFrame body = spheres({Vec3(0.0f, 0.5f, 0.0f), Vec3(0.2f, 0.5f, 0.0f)}, r);
  const Contact k = answer(body, 4, Vec3(0.1f, 0.5f, 0.0f));
  EXPECT_TRUE(k.hit);
  EXPECT_LE(k.depth, 0.0f);
  EXPECT_GT(k.depth, -0.002f);
}

// a point inside one of them 40 mm from the middle of their overlap along X, farther from any way out of
// the union (104 mm along Y or Z, 180 mm along X): it is sent to where the parts meet, along -X, not out
// through the far side of its part (which, for cloth between an arm and the torso, carries it across the
// arm and stretches its springs around it)
TEST(ImageSpaceLayers, APointNearAnOverlapIsSentWhereThePartsMeet) {
  const Real r = 0.12f;
  const BodyFrame body = spheres({Vec3(0.0f, 0.5f, 0.0f), Vec3(0.2f, 0.5f, 0.0f)}, r);
  const Contact k = answer(body, 4, Vec3(0.14f, 0.5f, 0.0f));
  ASSERT_TRUE(k.hit);
  EXPECT_NEAR(k.depth, -0.04f, 0.004f);
  EXPECT_LT(k.normal.x(), -0.9f) << k.normal.transpose();
}

// the same point where the surfaces are a sheet of cloth standing in for a body (ColliderOptions::overlapping_parts
// false: cloth lying on itself overlaps without pinching anything): answered by the nearest way out of the union,
// 104 mm along Y or Z (90 mm from that surface's tangent plane), not sent 40 mm along -X to where the parts meet
TEST(ImageSpaceLayers, ASheetStandingInForABodyPinchesNothing) {
  const Real r = 0.12f;
  const BodyFrame body = spheres({Vec3(0.0f, 0.5f, 0.0f), Vec3(0.2f, 0.5f, 0.0f)}, r);
  const Contact k = answer(body, 4, Vec3(0.14f, 0.5f, 0.0f), false);
  ASSERT_TRUE(k.hit);
  EXPECT_LT(k.depth, -0.08f);
  EXPECT_GT(k.normal.x(), -0.9f) << k.normal.transpose();
}

// the walking body on walk_08_02 at 2.60 s (in place): a point in the right armpit 6 mm inside the arm (its
// inner surface along X), which the front/back pair sees inside too; the vertical line through it crosses the
// armpit's crease, where the skin folds through itself, and leaves the body twice in a row. Its count called
// the point outside, and that outside answer won: the cloth there was not answered at all
TEST(ImageSpaceLayers, ALineThroughAFoldDoesNotCallAPointInsideTheArmOutside) {
  const std::string path = test::walking_body_path();
  if (path.empty()) GTEST_SKIP() << "the walking body is not in the data root";
  const BodyModel model = load_body(path);
  ColliderOptions o;
  o.views = 6;
  o.layers = 5;
  auto c = make_is_cpu_collider(o);
  c->set_body(model.frame(model.animation_index("walk_08_02"), 2.60, true));
  Points3 q(3, 1);
  q.col(0) = Vec3(-0.1183f, 1.1919f, 0.0064f);
  Contact k;
  c->query(PointsView(q), ContactsOut{&k, 1});
  EXPECT_TRUE(k.hit);
  EXPECT_LT(k.depth, -0.004f);
}

TEST(GlMaps, SameAsCpuWithPeeledLayers) {
  CLOTHBENCH_REQUIRE_GL();
  const BodyModel& model = test::test_body_model();
  for (int views : {2, 6}) {
    ColliderOptions o;
    o.views = views;
    o.layers = 4;
    o.side_layer = false;
    test::expect_gl_matches_cpu(model.rest(), o, model.path().c_str());
  }
}

// MapSet::limit_rows: the rows a region spans are the full maps' (every view, peeled layers too), the others empty
void expect_rows_of_region(const MapSet& full, const MapSet& part, const Box3& region, const char* what) {
  const MapFrame& f = full.frame;
  long drawn = 0;
  for (int map = 0; map < f.map_count(); ++map) {
    const int view = f.view_of(map), axis = MapFrame::row_axis(view);
    for (int row = 0; row < f.size; ++row) {
      const Real lo = f.origin(axis) + Real(row) * f.pixel, hi = lo + f.pixel;
      const bool inside = hi > region.min[axis] && lo < region.max[axis];
      const bool listed =
          row >= part.row_first[static_cast<std::size_t>(view)] && row <= part.row_last[static_cast<std::size_t>(view)];
      EXPECT_TRUE(listed || !inside) << what << ": map " << map << " row " << row << " in the region is not drawn";
      for (int col = 0; col < f.size; ++col) {
        const std::size_t i = full.index(map, col, row);
        if (listed) {
          drawn += part.mask[i] == MapSet::kBody;
          ASSERT_EQ(part.mask[i], full.mask[i]) << what << " map " << map << " (" << col << ", " << row << ")";
          ASSERT_EQ(part.z[i], full.z[i]) << what << " map " << map << " (" << col << ", " << row << ")";
          ASSERT_EQ(part.normal_at(i), full.normal_at(i)) << what;
        } else {
          ASSERT_NE(part.mask[i], MapSet::kBody) << what << " map " << map << " (" << col << ", " << row << ")";
        }
      }
    }
  }
  EXPECT_GT(drawn, 1000) << what;
}

TEST(ImageSpaceLayers, MapsOfARegionsRowsAreTheFullMapsThere) {
  const BodyModel& model = test::test_body_model();
  const BodyFrame body = model.rest();
  Box3 region = bounding_box(body.positions);
  region.max.y() = region.min.y() + 0.6f * region.size().y();  // from the soles to the hips: a skirt's rows
  region.min.y() += 0.3f * region.size().y();
  region.max.z() = region.min.z() + 0.5f * region.size().z();  // the top and bottom views' rows: the back half
  for (const std::string renderer : {"cpu", "gl"}) {
    if (renderer == "gl" && !test::gl_unavailable().empty()) continue;
    ColliderOptions o;
    o.views = 6;
    o.layers = 3;
    o.side_layer = false;
    const auto full = renderer == "gl" ? make_gl_map_renderer() : make_cpu_map_renderer();
    const auto part = renderer == "gl" ? make_gl_map_renderer() : make_cpu_map_renderer();
    MapSet a, b;
    for (MapSet* m : {&a, &b})
      m->reset(make_map_frame(bounding_box(body.positions), o), o.float_maps, body.moving, o.max_speed);
    b.limit_rows(region);
    full->render(body, a);
    part->render(body, b);
    expect_rows_of_region(a, b, region, renderer.c_str());
  }
}

TEST(ImageSpaceLayers, BadLayerCountsAreRejected) {
  for (int layers : {0, -1, 9}) {
    ColliderOptions o;
    o.layers = layers;
    try {
      make_is_cpu_collider(o);
      ADD_FAILURE() << layers << " layers accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("layers must be 1"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace clothbench
