// The OpenGL picture renderer: the body and the cloth as OffscreenRenderer meshes (OSMesa), one
// context per renderer, kept for every picture it draws.
#include <string>

#include "clothbench/render/offscreen_renderer.hpp"
#include "picture_backends.hpp"

namespace clothbench::detail {

namespace {

// cloth grid lines are drawn when quad edges are at least this long on screen [pixels]
constexpr Real kMinGridPixels = 5;

Vec3 unit_colour(Rgb c) { return Vec3(c.r, c.g, c.b) / 255.0f; }

// the cloth's quads as triangles (0 1 2, 0 2 3)
Tris quad_triangles(const Quads& quads) {
  Tris t(3, 2 * quads.cols());
  for (Eigen::Index q = 0; q < quads.cols(); ++q) {
    t.col(2 * q) << quads(0, q), quads(1, q), quads(2, q);
    t.col(2 * q + 1) << quads(0, q), quads(2, q), quads(3, q);
  }
  return t;
}

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

class GlPictureRenderer final : public PictureRenderer {
 public:
  PictureBackend backend() const override { return PictureBackend::kGl; }
  std::string name() const override {
    return "OpenGL (OSMesa, " + std::string(gl_.gl_renderer()) + ", " + std::to_string(gl_.samples()) + " samples)";
  }

  Image render(const BodyFrame& body, const ClothMesh& cloth, int height, View view) override {
    const PictureCamera camera = picture_camera(body, cloth, height, view);
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
    return gl_.render({body_draw_mesh(body), cloth_draw_mesh(cloth, camera.scale)}, o, lighting);
  }

 private:
  OffscreenRenderer gl_;
};

}  // namespace

std::unique_ptr<PictureRenderer> make_gl_picture_renderer() { return std::make_unique<GlPictureRenderer>(); }

}  // namespace clothbench::detail
