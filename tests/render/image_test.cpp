// Image (render/src/image.cpp): pixels, lines, dots, the colour map, PNG written whole.
#include "clothbench/render/image.hpp"

#include <gtest/gtest.h>

#include "test_support.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

namespace clothbench {
namespace {

bool same(Rgb a, Rgb b) { return a.r == b.r && a.g == b.g && a.b == b.b; }

TEST(Image, PixelsOutsideAreIgnoredAndReadBlack) {
  Image im(4, 3, {10, 20, 30});
  EXPECT_TRUE(same(im.get(3, 2), {10, 20, 30}));
  im.set(1, 2, {1, 2, 3});
  EXPECT_TRUE(same(im.get(1, 2), {1, 2, 3}));
  EXPECT_EQ(im.data()[3 * (2 * 4 + 1)], 1);  // row-major, top row first
  im.set(-1, 0, {9, 9, 9});
  im.set(4, 0, {9, 9, 9});
  EXPECT_TRUE(same(im.get(7, 7), {}));
  EXPECT_THROW(Image(0, 5), std::invalid_argument);
}

TEST(Image, LinesAndDotsCoverTheirPixels) {
  Image im(10, 10);
  im.line(0, 0, 9, 9, {0, 0, 0});
  for (int i = 0; i < 10; ++i) EXPECT_TRUE(same(im.get(i, i), {0, 0, 0})) << i;
  EXPECT_TRUE(same(im.get(1, 0), {255, 255, 255}));
  im.dot(5, 2, 1, {200, 0, 0});
  for (int y = 1; y <= 3; ++y)
    for (int x = 4; x <= 6; ++x) EXPECT_TRUE(same(im.get(x, y), {200, 0, 0}));
}

TEST(Image, ColourMapRunsFromDarkToLightAndNanIsGrey) {
  const Rgb lo = colormap(0), hi = colormap(1);
  EXPECT_LT(int(lo.r) + lo.g + lo.b, int(hi.r) + hi.g + hi.b);
  EXPECT_TRUE(same(colormap(-3), lo));
  EXPECT_TRUE(same(colormap(std::nan("")), {128, 128, 128}));
}

TEST(Image, WritesAPngAndNoTemporaryFile) {
  const std::string path = test::temp_path("image_test.png");
  Image(8, 4, {1, 2, 3}).write_png(path);
  std::ifstream in(path, std::ios::binary);
  char magic[8] = {};
  in.read(magic, 8);
  EXPECT_EQ(std::string(magic + 1, 3), "PNG");
  EXPECT_FALSE(std::filesystem::exists(path + ".tmp"));
  EXPECT_THROW(Image(2, 2).write_png("/nonexistent-folder/x.png"), std::runtime_error);
}

}  // namespace
}  // namespace clothbench
