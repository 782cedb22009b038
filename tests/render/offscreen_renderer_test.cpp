// OffscreenRenderer (render/src/offscreen_renderer.cpp): a flat square seen head-on covers its pixels
// in its lit colour, lines are drawn over the fill, the background stays, bad input is refused.
// Skipped when no OSMesa context can be created.
#include "clothbench/render/offscreen_renderer.hpp"

#include <gtest/gtest.h>

#include <memory>
#include <stdexcept>
#include <string>

namespace clothbench {
namespace {

// a unit square in the z = 0 plane facing +z, one colour, as two triangles
DrawMesh square(const Vec3& colour) {
  DrawMesh m;
  m.positions.resize(3, 4);
  m.positions << -0.5f, 0.5f, 0.5f, -0.5f,  //
      -0.5f, -0.5f, 0.5f, 0.5f,             //
      0, 0, 0, 0;
  m.normals = Vec3::UnitZ().replicate(1, 4);
  m.colours = colour.replicate(1, 4);
  m.triangles.resize(3, 2);
  m.triangles << 0, 0, 1, 2, 2, 3;
  return m;
}

// a camera looking down -z at a 2 m x 2 m window, `pixels` square
OrthoCamera camera(int pixels) {
  OrthoCamera c;
  c.half_width = c.half_height = 1;
  c.width = c.height = pixels;
  return c;
}

std::unique_ptr<OffscreenRenderer> renderer_or_skip(std::string& why) {
  try {
    return std::make_unique<OffscreenRenderer>();
  } catch (const std::runtime_error& e) {
    why = e.what();
    return nullptr;
  }
}

TEST(OffscreenRenderer, SquareCoversItsPixelsInItsLitColour) {
  std::string why;
  const auto r = renderer_or_skip(why);
  if (!r) GTEST_SKIP() << "no OSMesa context: " << why;
  EXPECT_GE(r->samples(), 1);
  EXPECT_FALSE(r->gl_renderer().empty());
  Lighting lighting;
  lighting.light = Vec3::UnitZ();  // head-on: ambient + diffuse = 1
  const Image im = r->render({square(Vec3(1, 0, 0))}, camera(100), lighting);
  ASSERT_EQ(im.width(), 100);
  ASSERT_EQ(im.height(), 100);
  // the square spans the middle half of the picture; the corners are background
  int red = 0;
  for (int y = 0; y < 100; ++y)
    for (int x = 0; x < 100; ++x) {
      const Rgb c = im.get(x, y);
      red += c.r > 250 && c.g < 5 && c.b < 5 ? 1 : 0;
    }
  EXPECT_NEAR(red, 50 * 50, 2 * 50 + 4);  // one row or column of partial pixels on each side
  const Rgb corner = im.get(2, 2);
  EXPECT_EQ(int(corner.r) + int(corner.g) + int(corner.b), 3 * 255);
  const Rgb centre = im.get(50, 50);
  EXPECT_GT(centre.r, 250);
}

TEST(OffscreenRenderer, LinesAreDrawnOverTheFillInTheirShade) {
  std::string why;
  const auto r = renderer_or_skip(why);
  if (!r) GTEST_SKIP() << "no OSMesa context: " << why;
  DrawMesh m = square(Vec3(1, 1, 1));
  m.lines.resize(2, 1);
  m.lines << 0, 2;  // the diagonal
  m.line_shade = 0.0f;
  Lighting lighting;
  lighting.light = Vec3::UnitZ();
  const Image im = r->render({m}, camera(101), lighting);
  const Rgb on_line = im.get(50, 50), off_line = im.get(35, 60);
  EXPECT_LT(int(on_line.r), 128) << "the diagonal is dark";
  EXPECT_GT(int(off_line.r), 200) << "the fill is white";
}

TEST(OffscreenRenderer, RefusesBadSizesAndIndices) {
  std::string why;
  const auto r = renderer_or_skip(why);
  if (!r) GTEST_SKIP() << "no OSMesa context: " << why;
  EXPECT_THROW(r->render({square(Vec3(1, 0, 0))}, camera(0)), std::invalid_argument);
  DrawMesh bad = square(Vec3(1, 0, 0));
  bad.triangles(0, 0) = 7;
  EXPECT_THROW(r->render({bad}, camera(16)), std::invalid_argument);
  bad = square(Vec3(1, 0, 0));
  bad.colours.resize(3, 3);
  EXPECT_THROW(r->render({bad}, camera(16)), std::invalid_argument);
}

}  // namespace
}  // namespace clothbench
