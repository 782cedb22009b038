// One OSMesa context on a small client buffer, and shader compile/link (collide_is, render).
#define GL_GLEXT_PROTOTYPES 1
#include "clothbench/osmesa/osmesa_context.hpp"

#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>

#include <array>
#include <stdexcept>
#include <utility>

namespace clothbench::osmesa {

namespace {

// the client buffer OSMesaMakeCurrent needs even when every draw goes to an FBO [pixels]
constexpr int kClientSide = 16;

GLuint compile(GLenum type, const char* source, const std::string& who) {
  const GLuint s = glCreateShader(type);
  glShaderSource(s, 1, &source, nullptr);
  glCompileShader(s);
  GLint ok = 0;
  glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    std::array<char, 2048> log{};
    glGetShaderInfoLog(s, static_cast<GLsizei>(log.size()), nullptr, log.data());
    glDeleteShader(s);
    throw std::runtime_error(who + ": shader does not compile: " + log.data());
  }
  return s;
}

}  // namespace

Context::Context(std::string who) : who_(std::move(who)), client_(4 * kClientSide * kClientSide) {
  // context (core profile 3.3) made current on its own small client buffer
  // clang-format off
  const int attributes[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 24,
                            OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                            OSMESA_CONTEXT_MAJOR_VERSION, 3, OSMESA_CONTEXT_MINOR_VERSION, 3, 0};
  // clang-format on
  OSMesaContext ctx = OSMesaCreateContextAttribs(attributes, nullptr);
  if (!ctx) throw std::runtime_error(who_ + ": no OpenGL context: OSMesaCreateContextAttribs (core 3.3) failed");
  ctx_ = ctx;
  if (!make_current()) {
    OSMesaDestroyContext(ctx);
    throw std::runtime_error(who_ + ": OSMesaMakeCurrent failed");
  }
}

Context::~Context() { OSMesaDestroyContext(static_cast<OSMesaContext>(ctx_)); }

bool Context::make_current() {
  return OSMesaMakeCurrent(static_cast<OSMesaContext>(ctx_), client_.data(), GL_UNSIGNED_BYTE, kClientSide,
                           kClientSide) != 0;
}

void Context::release() { OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0); }

void* proc_address(const char* name) { return reinterpret_cast<void*>(OSMesaGetProcAddress(name)); }

unsigned int link_program(const char* vertex_source, const char* fragment_source, const std::string& who) {
  const GLuint vs = compile(GL_VERTEX_SHADER, vertex_source, who);
  GLuint fs = 0;
  try {
    fs = compile(GL_FRAGMENT_SHADER, fragment_source, who);
  } catch (...) {
    glDeleteShader(vs);
    throw;
  }
  const GLuint program = glCreateProgram();
  glAttachShader(program, vs);
  glAttachShader(program, fs);
  glLinkProgram(program);
  glDeleteShader(vs);
  glDeleteShader(fs);
  GLint ok = 0;
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (!ok) {
    glDeleteProgram(program);
    throw std::runtime_error(who + ": shader program does not link");
  }
  return program;
}

}  // namespace clothbench::osmesa
