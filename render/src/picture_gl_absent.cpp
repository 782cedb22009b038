// Builds without CLOTHBENCH_WITH_GL (no OSMesa): the OpenGL picture renderer is absent, the CPU one stays.
#include <stdexcept>

#include "picture_backends.hpp"

namespace clothbench::detail {

std::unique_ptr<PictureRenderer> make_gl_picture_renderer() {
  throw std::runtime_error("pictures: OpenGL renderer not built (configure with -DCLOTHBENCH_WITH_GL=ON)");
}

}  // namespace clothbench::detail
