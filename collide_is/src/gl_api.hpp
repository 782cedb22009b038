#pragma once
// The OpenGL functions the map renderer calls, loaded from its context's provider (OSMesaGetProcAddress or
// eglGetProcAddress) into a table: no gl* symbol is linked, so the OSMesa and the EGL renderer each call
// their own library's functions, even with both loaded in one process (libOSMesa and libOpenGL both export
// gl*, and a link against both binds every call to whichever comes first).
// the prototypes are declared for their types only (decltype): nothing here is linked
#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>

#include <array>
#include <initializer_list>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace clothbench {

// X(name) for every function, gl<name> in GL's headers
#define CLOTHBENCH_GL_FUNCTIONS(X)                                                                                     \
  X(ActiveTexture)                                                                                                     \
  X(CopyTexSubImage2D) X(FramebufferTexture2D) X(AttachShader) X(BindBuffer) X(BindFramebuffer) X(BindRenderbuffer) X(BindTexture) X(BindVertexArray) X(BufferData) \
      X(CheckFramebufferStatus) X(Clear) X(ClearColor) X(ClearDepth) X(CompileShader) X(CreateProgram) X(CreateShader) \
          X(DeleteBuffers) X(DeleteFramebuffers) X(DeleteProgram) X(DeleteRenderbuffers) X(DeleteShader)               \
              X(DeleteTextures) X(DeleteVertexArrays) X(DepthFunc) X(Disable) X(DisableVertexAttribArray)              \
                  X(DrawBuffers) X(DrawElements) X(Enable) X(EnableVertexAttribArray) X(FramebufferRenderbuffer)       \
                      X(GenBuffers) X(GenFramebuffers) X(GenRenderbuffers) X(GenTextures) X(GenVertexArrays)           \
                          X(GetError) X(GetProgramiv) X(GetShaderInfoLog) X(GetShaderiv) X(GetString)                  \
                              X(GetUniformLocation) X(LinkProgram) X(PixelStorei) X(ReadBuffer) X(ReadPixels)          \
                                  X(RenderbufferStorage) X(Scissor) X(ShaderSource) X(TexImage2D) X(TexParameteri)     \
                                      X(Uniform1f) X(Uniform1i) X(UniformMatrix4fv) X(UseProgram) X(VertexAttrib3f)    \
                                          X(VertexAttribPointer) X(Viewport)

// OpenGL 4.3 (compute shaders, shader storage buffers): the maps kept on the device (gl_device_maps.cpp)
#define CLOTHBENCH_GL_COMPUTE_FUNCTIONS(X)                                                                   \
  X(BindBufferBase) X(BufferSubData) X(DeleteQueries) X(DispatchCompute) X(Finish) X(GenQueries) X(GetBufferSubData)   \
      X(GetIntegerv) X(GetQueryObjectui64v) X(MemoryBarrier) X(QueryCounter) X(Uniform3f)

// the gl<name> prototypes of GL's headers, as pointer types (GL 1.x functions have no PFN... typedef there)
#define CLOTHBENCH_GL_TYPE(name) using name##_fn = std::remove_pointer_t<decltype(&::gl##name)>*;
namespace gl_types {
CLOTHBENCH_GL_FUNCTIONS(CLOTHBENCH_GL_TYPE)
CLOTHBENCH_GL_COMPUTE_FUNCTIONS(CLOTHBENCH_GL_TYPE)
}
#undef CLOTHBENCH_GL_TYPE

struct GlApi {
#define CLOTHBENCH_GL_MEMBER(name) gl_types::name##_fn name = nullptr;
  CLOTHBENCH_GL_FUNCTIONS(CLOTHBENCH_GL_MEMBER)
  CLOTHBENCH_GL_COMPUTE_FUNCTIONS(CLOTHBENCH_GL_MEMBER)
#undef CLOTHBENCH_GL_MEMBER

  // every function from `proc` (a name -> address lookup of the current context's provider), the OpenGL 4.3 ones
  // too when `compute`; throws std::runtime_error "WHO: OpenGL function glNAME not found" for one it lacks
  template <class Proc>
  static GlApi load(Proc&& proc, const std::string& who, bool compute = false) {
    GlApi gl;
#define CLOTHBENCH_GL_LOAD(name)                                     \
  gl.name = reinterpret_cast<gl_types::name##_fn>(proc("gl" #name)); \
  if (!gl.name) throw std::runtime_error(who + ": OpenGL function gl" #name " not found");
    CLOTHBENCH_GL_FUNCTIONS(CLOTHBENCH_GL_LOAD)
    if (compute) {
      CLOTHBENCH_GL_COMPUTE_FUNCTIONS(CLOTHBENCH_GL_LOAD)
    }
#undef CLOTHBENCH_GL_LOAD
    return gl;
  }
};

// The device's own time of a draw's phases: a GL_TIMESTAMP query at the end of each stretch of commands, the
// stretch's time added to the phase named there (read once the device has finished).
class GpuClock {
 public:
  enum Phase { kUpload, kDraw, kDepthCopy, kResolve, kSideLayer, kPhases };
  static constexpr std::array<const char*, kPhases> kNames = {"upload", "draw", "depth_copy", "resolve", "side_layer"};

  void start(const GlApi& gl) {
    gl_ = &gl;
    used_ = 0;
    mark(kPhases);
  }
  // the commands since the last mark belong to `phase`
  void mark(int phase) {
    if (!gl_) return;
    if (used_ == ids_.size()) {
      ids_.resize(ids_.size() + 32);
      gl_->GenQueries(32, ids_.data() + used_);
    }
    gl_->QueryCounter(ids_[used_], GL_TIMESTAMP);
    phases_.resize(ids_.size());
    phases_[used_++] = phase;
  }
  // after glFinish: each phase's time [ms]
  std::array<double, kPhases> read() const {
    std::array<double, kPhases> ms{};
    GLuint64 last = 0;
    for (std::size_t k = 0; k < used_; ++k) {
      GLuint64 t = 0;
      gl_->GetQueryObjectui64v(ids_[k], GL_QUERY_RESULT, &t);
      if (k > 0 && phases_[k] < kPhases) ms[static_cast<std::size_t>(phases_[k])] += 1e-6 * double(t - last);
      last = t;
    }
    return ms;
  }
  void release() {
    if (gl_ && !ids_.empty()) gl_->DeleteQueries(static_cast<GLsizei>(ids_.size()), ids_.data());
    ids_.clear();
  }

 private:
  const GlApi* gl_ = nullptr;
  std::vector<GLuint> ids_;
  std::vector<int> phases_;
  std::size_t used_ = 0;
};

// a shader of `type` compiled from `source`; throws std::runtime_error "WHO: shader does not compile: LOG"
inline GLuint compile_shader(const GlApi& gl, GLenum type, const char* source, const std::string& who) {
  const GLuint s = gl.CreateShader(type);
  gl.ShaderSource(s, 1, &source, nullptr);
  gl.CompileShader(s);
  GLint ok = 0;
  gl.GetShaderiv(s, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    std::array<char, 4096> log{};
    gl.GetShaderInfoLog(s, static_cast<GLsizei>(log.size()), nullptr, log.data());
    gl.DeleteShader(s);
    throw std::runtime_error(who + ": shader does not compile: " + log.data());
  }
  return s;
}

// a program of the compiled `shaders` (deleted here, linked or not); throws std::runtime_error when it does not link
inline GLuint link_shaders(const GlApi& gl, std::initializer_list<GLuint> shaders, const std::string& who) {
  const GLuint program = gl.CreateProgram();
  for (GLuint s : shaders) gl.AttachShader(program, s);
  gl.LinkProgram(program);
  for (GLuint s : shaders) gl.DeleteShader(s);
  GLint ok = 0;
  gl.GetProgramiv(program, GL_LINK_STATUS, &ok);
  if (!ok) {
    gl.DeleteProgram(program);
    throw std::runtime_error(who + ": shader program does not link");
  }
  return program;
}

}  // namespace clothbench
