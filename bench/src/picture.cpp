// A small z-buffer rasteriser for pictures (not for collision detection: collide_is has its own).
#include "picture.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "clothbench/io/gltf_export.hpp"

namespace clothbench {

namespace {

struct Camera {
  Vec3 right, up, toward;  // toward the viewer
  Vec3 origin;             // world point at pixel (0, 0) plane
  Real scale;              // pixels per metre
};

Camera make_camera(const Box3& box, int height, View view) {
  Camera c;
  c.up = Vec3::UnitY();
  c.toward = view == View::kFront ? Vec3::UnitZ() : view == View::kBack ? Vec3(-Vec3::UnitZ()) : Vec3::UnitX();
  c.right = c.up.cross(c.toward);
  const Real margin = 0.05f * box.size().y();
  c.scale = Real(height) / (box.size().y() + 2 * margin);
  const Vec3 centre = box.center();
  const Real half_width = 0.5f * std::max(box.size().x(), box.size().z()) + margin;
  c.origin = centre - c.right * half_width + c.up * (0.5f * box.size().y() + margin);
  return c;
}

int image_width(const Box3& box, int height) {
  const Real margin = 0.05f * box.size().y();
  return static_cast<int>(std::ceil(Real(height) * (std::max(box.size().x(), box.size().z()) + 2 * margin) /
                                    (box.size().y() + 2 * margin)));
}

class Raster {
 public:
  Raster(Image& image, const Camera& cam)
      : img_(image), cam_(cam), z_(size_t(image.width()) * image.height(), -std::numeric_limits<Real>::infinity()) {
    // light from the upper right, in front of the viewer
    light_ = (0.3f * cam.right + 0.5f * cam.up + 1.0f * cam.toward).normalized();
  }

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
  Camera cam_;
  std::vector<Real> z_;
  Vec3 light_;
};

Rgb panel_colour(int panel) {
  static const std::array<Rgb, 6> colours{{{200, 60, 60}, {60, 110, 200}, {220, 160, 40}, {70, 160, 90}, {150, 80, 180}, {40, 170, 170}}};
  return colours[std::size_t(std::max(panel, 0)) % colours.size()];
}

}  // namespace

Image render_dressed(const BodyFrame& body, const ClothMesh& cloth, int height, View view) {
  Box3 box = bounding_box(body.positions);
  if (cloth.positions.cols() > 0) {
    const Box3 c = bounding_box(cloth.positions);
    box.min = box.min.cwiseMin(c.min);
    box.max = box.max.cwiseMax(c.max);
  }
  Image image(image_width(box, height), height, {255, 255, 255});
  Raster raster(image, make_camera(box, height, view));
  for (Eigen::Index t = 0; t < body.triangles.cols(); ++t)
    raster.triangle(body.positions.col(body.triangles(0, t)), body.positions.col(body.triangles(1, t)),
                    body.positions.col(body.triangles(2, t)), {200, 190, 180});
  for (Eigen::Index q = 0; q < cloth.quads.cols(); ++q) {
    const auto& x = cloth.positions;
    const Rgb c = panel_colour(cloth.panel.empty() ? 0 : cloth.panel[cloth.quads(0, q)]);
    raster.triangle(x.col(cloth.quads(0, q)), x.col(cloth.quads(1, q)), x.col(cloth.quads(2, q)), c);
    raster.triangle(x.col(cloth.quads(0, q)), x.col(cloth.quads(2, q)), x.col(cloth.quads(3, q)), c);
  }
  return image;
}

void export_dressed(const std::string& path, const BodyFrame& body, const ClothMesh& cloth) {
  std::vector<ExportMesh> meshes{{"body", body.positions, body.triangles, {0.78f, 0.75f, 0.71f}}};
  const int panels = std::max<int>(1, static_cast<int>(cloth.panel_names.size()));
  for (int p = 0; p < panels; ++p) {
    // the panel's quads as triangles, vertices renumbered
    std::vector<int> index(static_cast<std::size_t>(cloth.positions.cols()), -1);
    std::vector<int> used, tris;
    for (Eigen::Index q = 0; q < cloth.quads.cols(); ++q) {
      if (!cloth.panel.empty() && cloth.panel[cloth.quads(0, q)] != p) continue;
      for (int k : {0, 1, 2, 0, 2, 3}) {
        int& i = index[static_cast<std::size_t>(cloth.quads(k, q))];
        if (i < 0) {
          i = static_cast<int>(used.size());
          used.push_back(cloth.quads(k, q));
        }
        tris.push_back(i);
      }
    }
    ExportMesh m;
    m.name = p < static_cast<int>(cloth.panel_names.size()) ? cloth.panel_names[p] : "cloth";
    m.positions.resize(3, static_cast<Eigen::Index>(used.size()));
    for (std::size_t i = 0; i < used.size(); ++i) m.positions.col(static_cast<Eigen::Index>(i)) = cloth.positions.col(used[i]);
    m.triangles = Eigen::Map<const Tris>(tris.data(), 3, static_cast<Eigen::Index>(tris.size() / 3));
    const Rgb c = panel_colour(p);
    m.colour = {c.r / 255.f, c.g / 255.f, c.b / 255.f};
    meshes.push_back(std::move(m));
  }
  export_gltf(path, meshes);
}

Image side_by_side(const std::vector<Image>& images) {
  int width = 0, height = 0;
  for (const auto& im : images) {
    width += im.width() + 4;
    height = std::max(height, im.height());
  }
  Image out(std::max(1, width - 4), std::max(1, height));
  int x0 = 0;
  for (const auto& im : images) {
    for (int y = 0; y < im.height(); ++y)
      for (int x = 0; x < im.width(); ++x) out.set(x0 + x, y, im.get(x, y));
    x0 += im.width() + 4;
  }
  return out;
}

}  // namespace clothbench
