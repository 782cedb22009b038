#pragma once
/// is-egl (library clothbench::collide_is_egl, CMake option CLOTHBENCH_WITH_EGL): the image-space maps drawn
/// by OpenGL in a context EGL makes without a window. EGL_EXT_platform_device first (CLOTHBENCH_EGL_DEVICE=N
/// picks device N; otherwise the first that is not Mesa's software device, so a GPU where the driver lists
/// one), else Mesa's surfaceless platform (EGL_MESA_platform_surfaceless; CLOTHBENCH_EGL_DEVICE=surfaceless
/// asks for it alone). A device or platform asked for by CLOTHBENCH_EGL_DEVICE is used or is an error. The library
/// links libEGL only: every GL call goes through eglGetProcAddress, so is-egl and is-gl (OSMesa) live in one process.
/// The same shaders, FBO and read-back as is-gl (make_gl_map_renderer(context), gl_context.hpp).
#include <memory>

#include "clothbench/collide_is/map_set.hpp"
#include "clothbench/sim/collider.hpp"

namespace clothbench {

/// The EGL map renderer; name() "egl". Throws std::runtime_error "is-egl: no OpenGL context through EGL: ..."
/// (every device and platform tried, with why each failed) or for a CLOTHBENCH_EGL_DEVICE out of range.
std::unique_ptr<MapRenderer> make_egl_map_renderer();

/// The image-space collider on make_egl_map_renderer(); name() "is-egl", device() the provider, GL_VENDOR and
/// GL_RENDERER.
std::unique_ptr<Collider> make_is_egl_collider(const ColliderOptions& options);

}  // namespace clothbench
