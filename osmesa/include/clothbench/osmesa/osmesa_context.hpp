#pragma once
/// The OpenGL set-up shared by collide_is (is-gl maps) and render (pictures): an OSMesa context,
/// core profile 3.3, made current on its own small client buffer (every draw goes to an FBO), and
/// a shader program compiled and linked from two sources. Headers of GL stay out of this one:
/// program names are GLuint, which is unsigned int.
#include <string>
#include <vector>

namespace clothbench::osmesa {

/// Owns one OSMesa context (RGBA, 24-bit depth, core profile 3.3). Non-copyable, non-movable;
/// use it from the thread that created it.
class Context {
 public:
  /// Creates the context and makes it current; throws std::runtime_error "WHO: no OpenGL context: ..."
  /// or "WHO: OSMesaMakeCurrent failed". `who` prefixes every message ("is-gl", "render").
  explicit Context(std::string who);
  ~Context();
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  /// Makes this context current again (after another context was); returns false when OSMesa refuses.
  bool make_current();
  /// No OSMesa context current on the calling thread.
  static void release();

 private:
  std::string who_;
  void* ctx_ = nullptr;                // OSMesaContext
  std::vector<unsigned char> client_;  // RGBA client buffer (kClientSide^2)
};

/// The address of OpenGL function `name` in libOSMesa (OSMesaGetProcAddress), or null.
void* proc_address(const char* name);

/// Compiles a vertex and a fragment shader and links them into a program (the shaders are deleted
/// once linked). Throws std::runtime_error "WHO: shader does not compile: LOG" or "WHO: shader
/// program does not link". Needs a current context.
unsigned int link_program(const char* vertex_source, const char* fragment_source, const std::string& who);

}  // namespace clothbench::osmesa
