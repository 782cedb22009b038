// Builds without CLOTHBENCH_WITH_GL (no OSMesa): the OpenGL map renderer is absent, the CPU one stays.
#include <stdexcept>

#include "clothbench/collide_is/map_set.hpp"

namespace clothbench {

std::unique_ptr<MapRenderer> make_gl_map_renderer() {
  throw std::runtime_error(
      "is-gl: the OpenGL map renderer is not built (configure with -DCLOTHBENCH_WITH_GL=ON; the CPU renderer, "
      "is-cpu, needs no OpenGL)");
}

}  // namespace clothbench
