// OffscreenRenderer: OSMesa context (core 3.3), a multisampled FBO resolved into a plain one,
// per-vertex normals and colours lit by one directional light.
#define GL_GLEXT_PROTOTYPES 1
#include "clothbench/render/offscreen_renderer.hpp"

#include <GL/gl.h>
#include <GL/glext.h>

#include "clothbench/osmesa/osmesa_context.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

namespace clothbench {

namespace {

constexpr const char* kVertexShader = R"(#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec3 colour;
uniform mat4 clip_from_world;
out vec3 n_world;
out vec3 albedo;
void main() {
  gl_Position = clip_from_world * vec4(position, 1.0);
  n_world = normal;
  albedo = colour;
}
)";

// Lambert with ambient; two-sided surfaces turn their normal toward the camera first; lines are
// drawn unlit in their colour x shade
constexpr const char* kFragmentShader = R"(#version 330 core
in vec3 n_world;
in vec3 albedo;
uniform vec3 light;
uniform vec3 toward;
uniform float ambient;
uniform float diffuse;
uniform int two_sided;
uniform int unlit;
uniform float shade;
out vec4 colour_out;
void main() {
  if (unlit != 0) {
    colour_out = vec4(shade * albedo, 1.0);
    return;
  }
  float len = length(n_world);
  vec3 n = len > 0.0 ? n_world / len : toward;
  if (two_sided != 0 && dot(n, toward) < 0.0) n = -n;
  float lit = ambient + diffuse * max(dot(n, light), 0.0);
  colour_out = vec4(min(lit * albedo, vec3(1.0)), 1.0);
}
)";

// colour samples per pixel asked for (fewer when the context offers fewer)
constexpr GLint kWantedSamples = 4;

void check_mesh(const DrawMesh& m, std::size_t index) {
  const Eigen::Index nv = m.positions.cols();
  const std::string what = "render: mesh " + std::to_string(index) + ": ";
  if (m.normals.cols() != nv || m.colours.cols() != nv)
    throw std::invalid_argument(what + "normals and colours need one column per vertex (" + std::to_string(nv) + ")");
  const auto in_range = [nv](const auto& idx) {
    return idx.size() == 0 || (idx.minCoeff() >= 0 && idx.maxCoeff() < nv);
  };
  if (!in_range(m.triangles) || !in_range(m.lines)) throw std::invalid_argument(what + "vertex index out of range");
}

// extent of every vertex along the camera's `toward` axis, relative to its centre [m]
std::pair<Real, Real> depth_extent(const std::vector<DrawMesh>& meshes, const OrthoCamera& c) {
  Real lo = std::numeric_limits<Real>::infinity(), hi = -lo;
  for (const auto& m : meshes)
    if (m.positions.cols() > 0) {
      const Eigen::Matrix<Real, 1, Eigen::Dynamic> d = c.toward.transpose() * (m.positions.colwise() - c.centre);
      lo = std::min(lo, d.minCoeff());
      hi = std::max(hi, d.maxCoeff());
    }
  if (!(lo <= hi)) return {-1, 1};
  const Real margin = 0.01f * (hi - lo) + 1e-3f;
  return {lo - margin, hi + margin};
}

// column-major clip-from-world matrix: orthographic, nearest depth (largest toward) at ndc -1
std::array<float, 16> clip_from_world(const OrthoCamera& c, Real d_min, Real d_max) {
  const Real range = d_max - d_min;
  const std::array<Vec3, 3> rows = {c.right / c.half_width, c.up / c.half_height, -2 * c.toward / range};
  const std::array<Real, 3> offsets = {-c.right.dot(c.centre) / c.half_width, -c.up.dot(c.centre) / c.half_height,
                                       2 * c.toward.dot(c.centre) / range + 1 + 2 * d_min / range};
  std::array<float, 16> m{};
  for (int r = 0; r < 3; ++r) {
    for (int k = 0; k < 3; ++k) m[static_cast<std::size_t>(4 * k + r)] = rows[static_cast<std::size_t>(r)][k];
    m[static_cast<std::size_t>(12 + r)] = offsets[static_cast<std::size_t>(r)];
  }
  m[15] = 1;
  return m;
}

}  // namespace

struct OffscreenRenderer::Impl {
  osmesa::Context context{"render"};  // first member: destroyed after the GL objects ~OffscreenRenderer deletes
  GLuint program = 0, vao = 0;
  std::array<GLuint, 4> vbo{};  // positions, normals, colours, indices
  std::array<GLuint, 2> fbo{};  // multisampled draw target, resolved target
  std::array<GLuint, 3> rbo{};  // multisampled colour, multisampled depth, resolved colour
  GLint samples = 0;
  int width = 0, height = 0;
  std::string renderer_name;
  GLint u_clip = -1, u_light = -1, u_toward = -1, u_ambient = -1, u_diffuse = -1, u_two_sided = -1, u_unlit = -1,
        u_shade = -1;

  void make_current() { context.make_current(); }

  // shaders, uniforms, vertex arrays and the sample count in the new context
  void set_up() {
    program = osmesa::link_program(kVertexShader, kFragmentShader, "render");
    u_clip = glGetUniformLocation(program, "clip_from_world");
    u_light = glGetUniformLocation(program, "light");
    u_toward = glGetUniformLocation(program, "toward");
    u_ambient = glGetUniformLocation(program, "ambient");
    u_diffuse = glGetUniformLocation(program, "diffuse");
    u_two_sided = glGetUniformLocation(program, "two_sided");
    u_unlit = glGetUniformLocation(program, "unlit");
    u_shade = glGetUniformLocation(program, "shade");
    // vertex arrays: positions, normals, colours, indices
    glGenVertexArrays(1, &vao);
    glBindVertexArray(vao);
    glGenBuffers(static_cast<GLsizei>(vbo.size()), vbo.data());
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, vbo[3]);
    // as many samples as asked for, or as the context offers
    GLint max_samples = 0;
    glGetIntegerv(GL_MAX_SAMPLES, &max_samples);
    samples = std::max<GLint>(0, std::min(kWantedSamples, max_samples));
    const auto* name = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    renderer_name = name ? name : "unknown";
    if (glGetError() != GL_NO_ERROR) throw std::runtime_error("render: OpenGL set-up failed");
  }

  // (re)creates both framebuffers when the picture size changed
  void targets(int w, int h) {
    if (fbo[0] && w == width && h == height) return;
    release_targets();
    width = w;
    height = h;
    glGenFramebuffers(static_cast<GLsizei>(fbo.size()), fbo.data());
    glGenRenderbuffers(static_cast<GLsizei>(rbo.size()), rbo.data());
    glBindFramebuffer(GL_FRAMEBUFFER, fbo[0]);
    const std::array<GLenum, 2> formats = {GL_RGBA8, GL_DEPTH_COMPONENT24};
    const std::array<GLenum, 2> points = {GL_COLOR_ATTACHMENT0, GL_DEPTH_ATTACHMENT};
    for (std::size_t k = 0; k < 2; ++k) {
      glBindRenderbuffer(GL_RENDERBUFFER, rbo[k]);
      glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, formats[k], w, h);
      glFramebufferRenderbuffer(GL_FRAMEBUFFER, points[k], GL_RENDERBUFFER, rbo[k]);
    }
    const bool draw_ok = glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
    glBindFramebuffer(GL_FRAMEBUFFER, fbo[1]);
    glBindRenderbuffer(GL_RENDERBUFFER, rbo[2]);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, w, h);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rbo[2]);
    const bool resolve_ok = glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
    if (!draw_ok || !resolve_ok)
      throw std::runtime_error("render: framebuffer of " + std::to_string(w) + " x " + std::to_string(h) + " pixels (" +
                               std::to_string(samples) + " samples) is incomplete");
  }

  void release_targets() {
    if (!fbo[0]) return;
    glDeleteFramebuffers(static_cast<GLsizei>(fbo.size()), fbo.data());
    glDeleteRenderbuffers(static_cast<GLsizei>(rbo.size()), rbo.data());
    fbo = {};
  }

  // one mesh: attributes straight from its packed 3 x n float arrays, triangles then lines
  void draw(const DrawMesh& m) {
    const std::array<const Points3*, 3> arrays = {&m.positions, &m.normals, &m.colours};
    for (GLuint k = 0; k < 3; ++k) {
      glBindBuffer(GL_ARRAY_BUFFER, vbo[k]);
      glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(arrays[k]->size() * sizeof(float)), arrays[k]->data(),
                   GL_STREAM_DRAW);
      glVertexAttribPointer(k, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
      glEnableVertexAttribArray(k);
    }
    glUniform1i(u_two_sided, m.two_sided ? 1 : 0);
    glUniform1i(u_unlit, 0);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(m.triangles.size() * sizeof(std::int32_t)),
                 m.triangles.data(), GL_STREAM_DRAW);
    glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(m.triangles.size()), GL_UNSIGNED_INT, nullptr);
    if (m.lines.size() == 0) return;
    glUniform1i(u_unlit, 1);
    glUniform1f(u_shade, m.line_shade);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(m.lines.size() * sizeof(std::int32_t)),
                 m.lines.data(), GL_STREAM_DRAW);
    glDrawElements(GL_LINES, static_cast<GLsizei>(m.lines.size()), GL_UNSIGNED_INT, nullptr);
  }

  // resolve the samples, read back bottom-up and flip to top row first
  Image read_back() {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo[0]);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fbo[1]);
    glBlitFramebuffer(0, 0, width, height, 0, 0, width, height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo[1]);
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    Image out(width, height);
    std::vector<std::uint8_t> bottom_up(std::size_t(3) * std::size_t(width) * std::size_t(height));
    glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, bottom_up.data());
    const std::size_t row = std::size_t(3) * std::size_t(width);
    for (int y = 0; y < height; ++y)
      std::copy_n(bottom_up.begin() + static_cast<std::ptrdiff_t>(row * std::size_t(height - 1 - y)), row,
                  out.data() + static_cast<std::ptrdiff_t>(row * std::size_t(y)));
    return out;
  }
};

OffscreenRenderer::OffscreenRenderer() : impl_(std::make_unique<Impl>()) { impl_->set_up(); }

OffscreenRenderer::~OffscreenRenderer() {
  impl_->make_current();
  impl_->release_targets();
  glDeleteBuffers(static_cast<GLsizei>(impl_->vbo.size()), impl_->vbo.data());
  glDeleteVertexArrays(1, &impl_->vao);
  glDeleteProgram(impl_->program);
}

int OffscreenRenderer::samples() const { return std::max(1, static_cast<int>(impl_->samples)); }

std::string_view OffscreenRenderer::gl_renderer() const { return impl_->renderer_name; }

Image OffscreenRenderer::render(const std::vector<DrawMesh>& meshes, const OrthoCamera& camera,
                                    const Lighting& lighting) {
  if (camera.width <= 0 || camera.height <= 0 || !(camera.half_width > 0) || !(camera.half_height > 0))
    throw std::invalid_argument("render: image size and camera extent must be positive (" +
                                std::to_string(camera.width) + " x " + std::to_string(camera.height) + " pixels)");
  for (std::size_t i = 0; i < meshes.size(); ++i) check_mesh(meshes[i], i);
  Impl& g = *impl_;
  g.make_current();
  g.targets(camera.width, camera.height);
  // clear, depth test on, culling off (cloth is seen from both sides), fill behind the lines
  glBindFramebuffer(GL_FRAMEBUFFER, g.fbo[0]);
  glViewport(0, 0, camera.width, camera.height);
  const auto& bg = lighting.background;
  glClearColor(bg[0], bg[1], bg[2], 1.0f);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  glDisable(GL_CULL_FACE);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(1.0f, 1.0f);
  // camera and light uniforms
  glUseProgram(g.program);
  const auto [d_min, d_max] = depth_extent(meshes, camera);
  const std::array<float, 16> m = clip_from_world(camera, d_min, d_max);
  glUniformMatrix4fv(g.u_clip, 1, GL_FALSE, m.data());
  const Vec3 light = lighting.light.normalized();
  glUniform3f(g.u_light, light.x(), light.y(), light.z());
  glUniform3f(g.u_toward, camera.toward.x(), camera.toward.y(), camera.toward.z());
  glUniform1f(g.u_ambient, lighting.ambient);
  glUniform1f(g.u_diffuse, lighting.diffuse);
  for (const auto& mesh : meshes) g.draw(mesh);
  return g.read_back();
}

}  // namespace clothbench
