// Pictures of dressed bodies: the OpenGL (OSMesa) renderer against analytic coverage and against
// the CPU rasteriser, both behind PictureRenderer.
#include "clothbench/render/picture.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace clothbench {
namespace {

constexpr Real kRadius = 0.3f;
const Vec3 kCentre(0, 1, 0);

// a pixel is covered when it is clearly darker than the white background (anti-aliased edges
// count once they are about half covered)
bool covered(Rgb c) { return int(c.r) + int(c.g) + int(c.b) < 690; }
bool red(Rgb c) { return int(c.r) > int(c.g) + 40 && int(c.r) > int(c.b) + 40; }

template <class Test>
double count(const Image& im, Test test) {
  double n = 0;
  for (int y = 0; y < im.height(); ++y)
    for (int x = 0; x < im.width(); ++x) n += test(im.get(x, y)) ? 1 : 0;
  return n;
}

// intersection over union of the pixels passing `test` in two images of one size
template <class Test>
double iou(const Image& a, const Image& b, Test test) {
  double both = 0, either = 0;
  for (int y = 0; y < a.height(); ++y)
    for (int x = 0; x < a.width(); ++x) {
      const bool p = test(a.get(x, y)), q = test(b.get(x, y));
      both += p && q ? 1 : 0;
      either += p || q ? 1 : 0;
    }
  return either > 0 ? both / either : 0;
}

// mean brightness of the covered pixels of the image quadrant (right or left, top or bottom)
double quadrant_brightness(const Image& im, bool right, bool top) {
  double sum = 0, n = 0;
  for (int y = 0; y < im.height(); ++y)
    for (int x = 0; x < im.width(); ++x) {
      const Rgb c = im.get(x, y);
      if ((2 * x >= im.width()) != right || (2 * y < im.height()) != top || !covered(c)) continue;
      sum += (int(c.r) + int(c.g) + int(c.b)) / 3.0;
      ++n;
    }
  return n > 0 ? sum / n : 0;
}

// a 0.4 m square cloth hanging 5 cm in front of the sphere
ClothMesh cloth_in_front() {
  return make_grid_cloth(21, 21, 0.02f, kCentre + Vec3(-0.2f, -0.2f, kRadius + 0.05f), Vec3::UnitX(), Vec3::UnitY());
}

// why this build or this machine has no OpenGL pictures ("" when it has them)
std::string gl_unavailable() {
  if (!has_picture_backend(PictureBackend::kGl)) return "built without CLOTHBENCH_WITH_GL";
  try {
    make_picture_renderer(PictureBackend::kGl);
  } catch (const std::runtime_error& e) {
    return std::string("no OSMesa context: ") + e.what();
  }
  return "";
}

TEST(Picture, DefaultRendererIsOpenGlWhenBuilt) {
  EXPECT_TRUE(has_picture_backend(PictureBackend::kCpu));
  EXPECT_EQ(default_picture_backend() == PictureBackend::kGl, has_picture_backend(PictureBackend::kGl));
  EXPECT_EQ(make_picture_renderer(PictureBackend::kCpu)->name(), "CPU rasteriser");
  EXPECT_EQ(make_picture_renderer(PictureBackend::kCpu)->backend(), PictureBackend::kCpu);
}

TEST(Picture, SphereCoversItsDiscAndIsLitFromTheUpperRight) {
  const BodyFrame sphere = make_sphere_body(kCentre, kRadius, 48, 96);
  std::vector<PictureBackend> backends{PictureBackend::kCpu};
  if (gl_unavailable().empty()) backends.push_back(PictureBackend::kGl);
  for (PictureBackend b : backends) {
    const std::unique_ptr<PictureRenderer> r = make_picture_renderer(b);
    const Image im = r->render(sphere, ClothMesh{}, 220, View::kFront);
    // the disc: pi r^2 at 220 pixels per 1.1 diameters
    const double scale = 220.0 / (2.2 * kRadius);
    const double expected = M_PI * std::pow(kRadius * scale, 2) / (double(im.width()) * im.height());
    const double fraction = count(im, covered) / (double(im.width()) * im.height());
    EXPECT_NEAR(fraction / expected, 1.0, 0.02) << r->name() << ": " << fraction << " vs " << expected;
    EXPECT_GT(quadrant_brightness(im, true, true), quadrant_brightness(im, false, false) + 20)
        << r->name();
  }
}

TEST(Picture, OpenGlAndCpuAgreeInCoverage) {
  if (const std::string why = gl_unavailable(); !why.empty()) GTEST_SKIP() << why;
  const BodyFrame sphere = make_sphere_body(kCentre, kRadius, 48, 96);
  const ClothMesh cloth = cloth_in_front();
  const std::unique_ptr<PictureRenderer> gl_renderer = make_picture_renderer(PictureBackend::kGl);
  const std::unique_ptr<PictureRenderer> cpu_renderer = make_picture_renderer(PictureBackend::kCpu);
  for (View v : {View::kFront, View::kSide, View::kBack}) {
    const Image gl = gl_renderer->render(sphere, cloth, 240, v);
    const Image cpu = cpu_renderer->render(sphere, cloth, 240, v);
    ASSERT_EQ(gl.width(), cpu.width());
    ASSERT_EQ(gl.height(), cpu.height());
    EXPECT_GE(iou(gl, cpu, covered), 0.97) << "view " << int(v);
    if (v == View::kFront) {
      // the cloth (red, panel 0) hides the sphere behind it in both
      EXPECT_GT(count(gl, red), 0.9 * count(cpu, red));
      EXPECT_GE(iou(gl, cpu, red), 0.95);
    }
  }
}

TEST(Picture, RejectsOpenGlWhenNotBuilt) {
  if (has_picture_backend(PictureBackend::kGl)) GTEST_SKIP() << "this build has the OpenGL renderer";
  EXPECT_THROW(make_picture_renderer(PictureBackend::kGl), std::runtime_error);
}

}  // namespace
}  // namespace clothbench
