// Pictures of dressed bodies: the camera both renderers share, the renderer factory, panel colours.
#include "clothbench/render/picture.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "clothbench/config.h"
#include "picture_backends.hpp"

namespace clothbench {

namespace detail {

namespace {

Box3 scene_box(const BodyFrame& body, const ClothMesh& cloth) {
  Box3 box = bounding_box(body.positions);
  if (cloth.positions.cols() > 0) {
    const Box3 c = bounding_box(cloth.positions);
    box.min = box.min.cwiseMin(c.min);
    box.max = box.max.cwiseMax(c.max);
  }
  return box;
}

}  // namespace

PictureCamera picture_camera(const BodyFrame& body, const ClothMesh& cloth, int height, View view) {
  const Box3 box = scene_box(body, cloth);
  PictureCamera c;
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

Vec3 light_direction(const PictureCamera& c) { return (0.3f * c.right + 0.5f * c.up + 1.0f * c.toward).normalized(); }

}  // namespace detail

Rgb panel_colour(int panel) {
  static const std::array<Rgb, 6> colours{
      {{200, 60, 60}, {60, 110, 200}, {220, 160, 40}, {70, 160, 90}, {150, 80, 180}, {40, 170, 170}}};
  return colours[std::size_t(std::max(panel, 0)) % colours.size()];
}

int vertex_panel(const ClothMesh& cloth, Eigen::Index v) {
  return cloth.panel.empty() ? 0 : cloth.panel[std::size_t(v)];
}

PictureBackend default_picture_backend() {
#ifdef CLOTHBENCH_WITH_GL
  return PictureBackend::kGl;
#else
  return PictureBackend::kCpu;
#endif
}

bool has_picture_backend(PictureBackend backend) {
  return backend == PictureBackend::kCpu || default_picture_backend() == PictureBackend::kGl;
}

std::unique_ptr<PictureRenderer> make_picture_renderer(PictureBackend backend) {
  return backend == PictureBackend::kCpu ? detail::make_cpu_picture_renderer() : detail::make_gl_picture_renderer();
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
