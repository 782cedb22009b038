#pragma once
/// An OpenGL context for the image-space map renderer, whoever provides it: OSMesa (is-gl, in this library)
/// or EGL (is-egl, clothbench::collide_is_egl). The renderer (make_gl_map_renderer(context)) draws through the
/// functions the context's provider hands out, so one process may hold contexts of both.
#include <memory>
#include <string>

#include "clothbench/collide_is/map_set.hpp"

namespace clothbench {

class GlContext {
 public:
  GlContext() = default;
  GlContext(const GlContext&) = delete;
  GlContext& operator=(const GlContext&) = delete;
  virtual ~GlContext() = default;
  /// Makes context `k` current on the calling thread; false when the provider refuses. k is 0, or 1 where
  /// contexts() is 2.
  virtual bool make_current(int k = 0) = 0;
  /// Makes no context current on the calling thread, so that another thread may make the one it held current next.
  virtual void release() = 0;
  /// 2 where the provider made a second context sharing the first's objects (buffers, textures, programs), so
  /// that drawing (context 1) and answering (context 0) may run on two threads at once; else 1.
  virtual int contexts() const { return 1; }
  /// The address of OpenGL function `name` ("glDrawElements") from this context's provider, or null.
  virtual void* proc(const char* name) = 0;
  /// The renderer's name ("gl", "egl"); its errors are reported as "is-" + the name.
  virtual std::string renderer_name() const = 0;
  /// How the context was made, for the device string ("OSMesa", "EGL device 0 (EGL_MESA_device_software)").
  virtual std::string provider() const = 0;
  /// Whether the context offers OpenGL 4.3 (compute shaders, shader storage) and the renderer keeps its maps on
  /// the device, answering queries there (DeviceMaps).
  virtual bool compute() const { return false; }
};

/// The OpenGL map renderer on `context` (made current at construction and before every render, released after
/// it, so that renders may come from any thread, one at a time): one FBO with
/// two colour targets (normal, velocity; RGBA32F or RGBA8) and a depth target of size x (views x size), the
/// views stacked upwards, peeled layers drawn again with a shader discarding what is not beyond the last,
/// read back with glReadPixels; on a context whose compute() is true, kept on the device instead (device_maps():
/// compute shaders turn each pass into maps, grow the side layer and answer queries; render() copies them out).
/// Its device() names the provider, GL_VENDOR and GL_RENDERER. Throws std::runtime_error when a function is
/// missing or a shader does not compile.
std::unique_ptr<MapRenderer> make_gl_map_renderer(std::unique_ptr<GlContext> context);

}  // namespace clothbench
