// Pictures of dressed bodies: one orthographic camera, drawn by OpenGL through OSMesa
// (clothbench::render) or by a small CPU z-buffer rasteriser (not for collision detection:
// collide_is has its own); and the glTF export of the same scene.
#include "clothbench/bench/picture.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

#ifdef CLOTHBENCH_PICTURES_GL
#include "clothbench/render/offscreen_renderer.hpp"
#endif

namespace clothbench {

namespace {

constexpr Rgb kBodyColour{200, 190, 180};
// cloth grid lines are drawn when quad edges are at least this long on screen [pixels]
constexpr Real kMinGridPixels = 5;

struct Camera {
  Vec3 right, up, toward;  // toward the viewer
  Vec3 origin;             // world point at pixel (0, 0) plane
  Real scale;              // pixels per metre
  int width, height;       // [pixels]
};

Box3 scene_box(const BodyFrame& body, const ClothMesh& cloth) {
  Box3 box = bounding_box(body.positions);
  if (cloth.positions.cols() > 0) {
    const Box3 c = bounding_box(cloth.positions);
    box.min = box.min.cwiseMin(c.min);
    box.max = box.max.cwiseMax(c.max);
  }
  return box;
}

// the box seen from `view`, 5 % margin, `height` pixels tall
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
  c.height = height;
  c.width = static_cast<int>(std::ceil(c.scale * 2 * half_width));
  return c;
}

// light from the upper right, in front of the viewer
Vec3 light_direction(const Camera& c) { return (0.3f * c.right + 0.5f * c.up + 1.0f * c.toward).normalized(); }

// the cloth's quads as triangles (0 1 2, 0 2 3)
Tris quad_triangles(const Quads& quads) {
  Tris t(3, 2 * quads.cols());
  for (Eigen::Index q = 0; q < quads.cols(); ++q) {
    t.col(2 * q) << quads(0, q), quads(1, q), quads(2, q);
    t.col(2 * q + 1) << quads(0, q), quads(2, q), quads(3, q);
  }
  return t;
}

class Raster {
 public:
  Raster(Image& image, const Camera& cam)
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
  Camera cam_;
  std::vector<Real> z_;
  Vec3 light_;
};

Image render_cpu(const BodyFrame& body, const ClothMesh& cloth, const Camera& camera) {
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

#ifdef CLOTHBENCH_PICTURES_GL
// one context for the process, created on first use (shader compile and warm-up paid once)
OffscreenRenderer& gl_renderer() {
  static OffscreenRenderer renderer;
  return renderer;
}

Vec3 unit_colour(Rgb c) { return Vec3(c.r, c.g, c.b) / 255.0f; }

DrawMesh body_draw_mesh(const BodyFrame& body) {
  DrawMesh m;
  m.positions = body.positions;
  m.normals = body.normals.cols() == body.positions.cols() ? body.normals
                                                           : angle_weighted_normals(body.positions, body.triangles);
  m.colours = unit_colour(kBodyColour).replicate(1, body.positions.cols());
  m.triangles = body.triangles;
  return m;
}

// the cloth lit on both sides, coloured per panel, with its grid lines where cells are wide enough
DrawMesh cloth_draw_mesh(const ClothMesh& cloth, Real pixels_per_metre) {
  DrawMesh m;
  m.positions = cloth.positions;
  m.triangles = quad_triangles(cloth.quads);
  m.normals = angle_weighted_normals(m.positions, m.triangles);
  m.colours.resize(3, m.positions.cols());
  for (Eigen::Index v = 0; v < m.positions.cols(); ++v)
    m.colours.col(v) = unit_colour(panel_colour(vertex_panel(cloth, v)));
  m.two_sided = true;
  Pairs lines(2, 4 * cloth.quads.cols());
  Real length = 0;
  for (Eigen::Index q = 0; q < cloth.quads.cols(); ++q)
    for (int k = 0; k < 4; ++k) {
      lines.col(4 * q + k) << cloth.quads(k, q), cloth.quads((k + 1) % 4, q);
      length += (m.positions.col(cloth.quads(k, q)) - m.positions.col(cloth.quads((k + 1) % 4, q))).norm();
    }
  if (lines.cols() > 0 && length / Real(lines.cols()) * pixels_per_metre >= kMinGridPixels) m.lines = std::move(lines);
  return m;
}

Image render_gl(const BodyFrame& body, const ClothMesh& cloth, const Camera& camera) {
  // our camera as the renderer's: centre of the image and half extents [m]
  OrthoCamera o;
  o.right = camera.right;
  o.up = camera.up;
  o.toward = camera.toward;
  o.width = camera.width;
  o.height = camera.height;
  o.half_width = Real(camera.width) / (2 * camera.scale);
  o.half_height = Real(camera.height) / (2 * camera.scale);
  o.centre = camera.origin + camera.right * o.half_width - camera.up * o.half_height;
  Lighting lighting;
  lighting.light = light_direction(camera);
  const RgbBuffer buffer =
      gl_renderer().render({body_draw_mesh(body), cloth_draw_mesh(cloth, camera.scale)}, o, lighting);
  // into bench's Image, pixel by pixel (both are top row first)
  Image image(buffer.width, buffer.height);
  for (int y = 0; y < buffer.height; ++y)
    for (int x = 0; x < buffer.width; ++x) {
      const std::size_t i = 3 * (std::size_t(y) * std::size_t(buffer.width) + std::size_t(x));
      image.set(x, y, {buffer.rgb[i], buffer.rgb[i + 1], buffer.rgb[i + 2]});
    }
  return image;
}
#endif

}  // namespace

Rgb panel_colour(int panel) {
  static const std::array<Rgb, 6> colours{
      {{200, 60, 60}, {60, 110, 200}, {220, 160, 40}, {70, 160, 90}, {150, 80, 180}, {40, 170, 170}}};
  return colours[std::size_t(std::max(panel, 0)) % colours.size()];
}

int vertex_panel(const ClothMesh& cloth, Eigen::Index v) {
  return cloth.panel.empty() ? 0 : cloth.panel[std::size_t(v)];
}

PictureRenderer default_picture_renderer() {
#ifdef CLOTHBENCH_PICTURES_GL
  return PictureRenderer::kGl;
#else
  return PictureRenderer::kCpu;
#endif
}

bool has_picture_renderer(PictureRenderer renderer) {
  return renderer == PictureRenderer::kCpu || default_picture_renderer() == PictureRenderer::kGl;
}

std::string picture_renderer_name(PictureRenderer renderer) {
  if (renderer == PictureRenderer::kCpu) return "CPU rasteriser";
#ifdef CLOTHBENCH_PICTURES_GL
  OffscreenRenderer& r = gl_renderer();
  return "OpenGL (OSMesa, " + std::string(r.gl_renderer()) + ", " + std::to_string(r.samples()) + " samples)";
#else
  throw std::runtime_error("pictures: OpenGL renderer not built (configure with -DCLOTHBENCH_WITH_GL=ON)");
#endif
}

Image render_dressed(const BodyFrame& body, const ClothMesh& cloth, int height, View view) {
  return render_dressed(body, cloth, height, view, default_picture_renderer());
}

Image render_dressed(const BodyFrame& body, const ClothMesh& cloth, int height, View view, PictureRenderer renderer) {
  const Camera camera = make_camera(scene_box(body, cloth), height, view);
  if (renderer == PictureRenderer::kCpu) return render_cpu(body, cloth, camera);
#ifdef CLOTHBENCH_PICTURES_GL
  return render_gl(body, cloth, camera);
#else
  throw std::runtime_error("pictures: OpenGL renderer not built (configure with -DCLOTHBENCH_WITH_GL=ON)");
#endif
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
