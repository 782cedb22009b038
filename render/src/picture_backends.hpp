#pragma once
// What the two picture renderers share: the camera framing a dressed body, the light and the body's
// colour; and the factories make_picture_renderer dispatches to.
#include <memory>

#include "clothbench/render/picture.hpp"

namespace clothbench::detail {

inline constexpr Rgb kBodyColour{200, 190, 180};

struct PictureCamera {
  Vec3 right, up, toward;  // toward the viewer
  Vec3 origin;             // world point at pixel (0, 0) plane
  Real scale;              // pixels per metre
  int width, height;       // [pixels]
};

// the bounding box of body and cloth seen from `view`, 5 % margin, `height` pixels tall
PictureCamera picture_camera(const BodyFrame& body, const ClothMesh& cloth, int height, View view);
// light from the upper right, in front of the viewer
Vec3 light_direction(const PictureCamera& c);

std::unique_ptr<PictureRenderer> make_cpu_picture_renderer();
// throws std::runtime_error in builds without CLOTHBENCH_WITH_GL (picture_gl_absent.cpp)
std::unique_ptr<PictureRenderer> make_gl_picture_renderer();

}  // namespace clothbench::detail
