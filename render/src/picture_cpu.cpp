// The CPU picture renderer: a small z-buffer rasteriser, flat shading, one sample per pixel (the
// fallback of builds without OpenGL; not for collision detection: collide_is has its own).
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "picture_backends.hpp"

namespace clothbench::detail {

namespace {

class Raster {
 public:
  Raster(Image& image, const PictureCamera& cam)
      : img_(image),
        cam_(cam),
        z_(size_t(image.width()) * image.height(), -std::numeric_limits<Real>::infinity()),
        light_(light_direction(cam)) {}

  // one flat-shaded triangle (both sides lit)
  void triangle(const Vec3& a, const Vec3& b, const Vec3& c, Rgb colour) {
    const Vec3 n = (b - a).cross(c - a);
    const Real len = n.norm();
    if (!(len > 0)) return;
    const Real light = 0.25f + 0.75f * std::abs(n.dot(light_)) / len;
    const Rgb shaded{std::uint8_t(colour.r * light), std::uint8_t(colour.g * light), std::uint8_t(colour.b * light)};
    const std::array<Vec3, 3> p{project(a), project(b), project(c)};
    const int x0 = std::max(0, int(std::floor(std::min({p[0].x(), p[1].x(), p[2].x()}))));
    const int x1 = std::min(img_.width() - 1, int(std::ceil(std::max({p[0].x(), p[1].x(), p[2].x()}))));
    const int y0 = std::max(0, int(std::floor(std::min({p[0].y(), p[1].y(), p[2].y()}))));
    const int y1 = std::min(img_.height() - 1, int(std::ceil(std::max({p[0].y(), p[1].y(), p[2].y()}))));
    const Real area = edge(p[0], p[1], p[2]);
    if (std::abs(area) < 1e-12f) return;
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) {
        const Vec3 q(Real(x) + 0.5f, Real(y) + 0.5f, 0);
        const Real w0 = edge(p[1], p[2], q) / area, w1 = edge(p[2], p[0], q) / area, w2 = 1 - w0 - w1;
        if (w0 < 0 || w1 < 0 || w2 < 0) continue;
        const Real z = w0 * p[0].z() + w1 * p[1].z() + w2 * p[2].z();
        Real& depth = z_[size_t(y) * img_.width() + x];
        if (z <= depth) continue;
        depth = z;
        img_.set(x, y, shaded);
      }
  }

 private:
  Vec3 project(const Vec3& w) const {
    const Vec3 d = w - cam_.origin;
    return Vec3(d.dot(cam_.right) * cam_.scale, -d.dot(cam_.up) * cam_.scale, d.dot(cam_.toward));
  }
  static Real edge(const Vec3& a, const Vec3& b, const Vec3& p) {
    return (b.x() - a.x()) * (p.y() - a.y()) - (b.y() - a.y()) * (p.x() - a.x());
  }

  Image& img_;
  PictureCamera cam_;
  std::vector<Real> z_;
  Vec3 light_;
};

class CpuPictureRenderer final : public PictureRenderer {
 public:
  PictureBackend backend() const override { return PictureBackend::kCpu; }
  std::string name() const override { return "CPU rasteriser"; }

  Image render(const BodyFrame& body, const ClothMesh& cloth, int height, View view) override {
    const PictureCamera camera = picture_camera(body, cloth, height, view);
    Image image(camera.width, camera.height, {255, 255, 255});
    Raster raster(image, camera);
    for (Eigen::Index t = 0; t < body.triangles.cols(); ++t)
      raster.triangle(body.positions.col(body.triangles(0, t)), body.positions.col(body.triangles(1, t)),
                      body.positions.col(body.triangles(2, t)), kBodyColour);
    for (Eigen::Index q = 0; q < cloth.quads.cols(); ++q) {
      const auto& x = cloth.positions;
      const Rgb c = panel_colour(vertex_panel(cloth, cloth.quads(0, q)));
      raster.triangle(x.col(cloth.quads(0, q)), x.col(cloth.quads(1, q)), x.col(cloth.quads(2, q)), c);
      raster.triangle(x.col(cloth.quads(0, q)), x.col(cloth.quads(2, q)), x.col(cloth.quads(3, q)), c);
    }
    return image;
  }
};

}  // namespace

std::unique_ptr<PictureRenderer> make_cpu_picture_renderer() { return std::make_unique<CpuPictureRenderer>(); }

}  // namespace clothbench::detail
