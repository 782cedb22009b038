// is-egl: the image-space maps through an OpenGL context made by EGL without a window: a device of
// EGL_EXT_platform_device (a GPU where the driver offers one, e.g. NVIDIA's), else Mesa's surfaceless platform.
// Links libEGL only: every GL function comes from eglGetProcAddress (collide_is/src/gl_api.hpp).
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <array>
#include <cstdlib>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "clothbench/collide_is/egl_collider.hpp"
#include "clothbench/collide_is/gl_context.hpp"
#include "clothbench/collide_is/image_space_collider.hpp"
#include "clothbench/sim/timer.hpp"

namespace clothbench {
namespace {

// an EGL extension function by name (null when the implementation lacks it)
template <class F>
F egl_function(const char* name) {
  return reinterpret_cast<F>(eglGetProcAddress(name));
}

bool has_extension(const char* list, const std::string& name) {
  const std::string all = list ? std::string(" ") + list + " " : std::string();
  return all.find(" " + name + " ") != std::string::npos;
}

// a display initialised, with a core 4.3 context (compute shaders: the maps stay on the device) current on no
// surface; false (and nothing held) when it fails
struct Made {
  EGLDisplay display = EGL_NO_DISPLAY;
  EGLContext context = EGL_NO_CONTEXT;
  EGLContext second = EGL_NO_CONTEXT;  // shares the first's objects: drawing on one thread, answering on another
};

bool make_context(EGLDisplay display, Made& out, std::string& why) {
  EGLint major = 0, minor = 0;
  if (display == EGL_NO_DISPLAY || !eglInitialize(display, &major, &minor)) {
    why = "eglInitialize failed";
    return false;
  }
  const char* extensions = eglQueryString(display, EGL_EXTENSIONS);
  if (!has_extension(extensions, "EGL_KHR_surfaceless_context")) {
    why = "no EGL_KHR_surfaceless_context";
    return false;
  }
  if (!eglBindAPI(EGL_OPENGL_API)) {
    why = "eglBindAPI(EGL_OPENGL_API) failed";
    return false;
  }
  EGLConfig config = nullptr;
  EGLint count = 0;
  const std::array<EGLint, 3> want = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
  if (!eglChooseConfig(display, want.data(), &config, 1, &count) || count < 1) {
    if (!has_extension(extensions, "EGL_KHR_no_config_context")) {
      why = "no OpenGL config";
      return false;
    }
    config = nullptr;  // EGL_NO_CONFIG_KHR
  }
  // clang-format off
  const std::array<EGLint, 7> attributes = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 3,
                                            EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
  // clang-format on
  const EGLContext context = eglCreateContext(display, config, EGL_NO_CONTEXT, attributes.data());
  if (context == EGL_NO_CONTEXT) {
    why = "eglCreateContext (OpenGL 4.3 core: compute shaders, which is-egl answers its queries with) failed";
    return false;
  }
  if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) {
    eglDestroyContext(display, context);
    why = "eglMakeCurrent without a surface failed";
    return false;
  }
  out = {display, context, eglCreateContext(display, config, context, attributes.data())};
  return true;
}

// "EGL device 1 of 2 (/dev/dri/renderD128; EGL_NV_device_cuda ...)"
std::string describe_device(EGLDeviceEXT device, int index, int count) {
  const auto query = egl_function<PFNEGLQUERYDEVICESTRINGEXTPROC>("eglQueryDeviceStringEXT");
  std::string text = "EGL device " + std::to_string(index) + " of " + std::to_string(count);
  if (!query) return text;
  const char* extensions = query(device, EGL_EXTENSIONS);
  std::string detail;
  if (has_extension(extensions, "EGL_EXT_device_drm"))
    if (const char* file = query(device, EGL_DRM_DEVICE_FILE_EXT)) detail = file;
  if (extensions && *extensions) detail += (detail.empty() ? "" : "; ") + std::string(extensions);
  return detail.empty() ? text : text + " (" + detail + ")";
}

class EglGlContext final : public GlContext {
 public:
  EglGlContext() {
    // a device asked for by CLOTHBENCH_EGL_DEVICE is that device or an error, never a fallback
    const char* pick = std::getenv("CLOTHBENCH_EGL_DEVICE");
    std::string why;
    if (pick && std::string(pick) == "surfaceless") {
      why = open_surfaceless();
    } else {
      why = open_device(pick);
      if (made_.context == EGL_NO_CONTEXT && !pick) why += "; " + open_surfaceless();
    }
    if (made_.context == EGL_NO_CONTEXT) throw std::runtime_error("is-egl: no OpenGL context through EGL: " + why);
  }

  ~EglGlContext() override {
    eglMakeCurrent(made_.display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    // the display stays initialised: other renderers' contexts share it
    if (made_.second != EGL_NO_CONTEXT) eglDestroyContext(made_.display, made_.second);
    eglDestroyContext(made_.display, made_.context);
  }

  bool make_current(int k) override {
    const EGLContext c = k == 1 && made_.second != EGL_NO_CONTEXT ? made_.second : made_.context;
    return eglMakeCurrent(made_.display, EGL_NO_SURFACE, EGL_NO_SURFACE, c) == EGL_TRUE;
  }
  int contexts() const override { return made_.second != EGL_NO_CONTEXT ? 2 : 1; }
  void release() override { eglMakeCurrent(made_.display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT); }
  void* proc(const char* name) override { return reinterpret_cast<void*>(eglGetProcAddress(name)); }
  std::string renderer_name() const override { return "egl"; }
  std::string provider() const override { return provider_; }
  bool compute() const override { return true; }

 private:
  // EGL_EXT_platform_device: `pick` (CLOTHBENCH_EGL_DEVICE) N picks device N, else the first that is not Mesa's
  // software device, else the software one; returns why none worked
  std::string open_device(const char* pick) {
    const auto query_devices = egl_function<PFNEGLQUERYDEVICESEXTPROC>("eglQueryDevicesEXT");
    const auto platform_display = egl_function<PFNEGLGETPLATFORMDISPLAYEXTPROC>("eglGetPlatformDisplayEXT");
    const auto query_string = egl_function<PFNEGLQUERYDEVICESTRINGEXTPROC>("eglQueryDeviceStringEXT");
    if (!query_devices || !platform_display) return "no EGL_EXT_device_enumeration / EGL_EXT_platform_device";
    std::array<EGLDeviceEXT, 16> devices{};
    EGLint count = 0;
    if (!query_devices(static_cast<EGLint>(devices.size()), devices.data(), &count) || count < 1)
      return "eglQueryDevicesEXT lists no device";
    std::vector<int> order;
    if (pick) {
      char* end = nullptr;
      const long n = std::strtol(pick, &end, 10);
      if (end == pick || *end != '\0' || n < 0 || n >= count)
        throw std::runtime_error("is-egl: CLOTHBENCH_EGL_DEVICE=" + std::string(pick) + " but EGL lists " +
                                 std::to_string(count) + " device(s): give 0.." + std::to_string(count - 1) +
                                 " or surfaceless");
      order.push_back(static_cast<int>(n));
    } else {
      const auto software = [&](int i) {
        return query_string && has_extension(query_string(devices[static_cast<std::size_t>(i)], EGL_EXTENSIONS),
                                             "EGL_MESA_device_software");
      };
      for (int i = 0; i < count; ++i)
        if (!software(i)) order.push_back(i);
      for (int i = 0; i < count; ++i)
        if (software(i)) order.push_back(i);
    }
    std::string why;
    for (int i : order) {
      const EGLDisplay d = platform_display(EGL_PLATFORM_DEVICE_EXT, devices[static_cast<std::size_t>(i)], nullptr);
      std::string failed;
      if (make_context(d, made_, failed)) {
        provider_ = describe_device(devices[static_cast<std::size_t>(i)], i, count);
        return {};
      }
      why += (why.empty() ? "" : "; ") + ("device " + std::to_string(i) + ": " + failed);
    }
    return why;
  }

  // Mesa's surfaceless platform (EGL_MESA_platform_surfaceless); returns why it did not work
  std::string open_surfaceless() {
    const auto platform_display = egl_function<PFNEGLGETPLATFORMDISPLAYEXTPROC>("eglGetPlatformDisplayEXT");
    if (!platform_display) return "surfaceless: no eglGetPlatformDisplayEXT";
    std::string failed;
    if (make_context(platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr), made_, failed)) {
      provider_ = "EGL surfaceless (EGL_MESA_platform_surfaceless)";
      return {};
    }
    return "surfaceless: " + failed;
  }

  Made made_;
  std::string provider_;
};

}  // namespace

std::unique_ptr<MapRenderer> make_egl_map_renderer() { return make_gl_map_renderer(std::make_unique<EglGlContext>()); }

std::unique_ptr<Collider> make_is_egl_collider(const ColliderOptions& options) {
  // context creation and shader compilation count as set-up
  Stopwatch watch;
  auto renderer = make_egl_map_renderer();
  return std::make_unique<ImageSpaceCollider>(std::move(renderer), options, watch.ms(),
                                              image_space_depth_test(options));
}

}  // namespace clothbench
