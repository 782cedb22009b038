// The OpenGL renderer of the image-space maps: OSMesa (llvmpipe), one FBO holding every view.
#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>

#include <algorithm>
#include <array>
#include <stdexcept>
#include <string>
#include <vector>

#include "clothbench/collide_is/map_set.hpp"
#include "clothbench/osmesa/osmesa_context.hpp"

namespace clothbench {
namespace {

constexpr const char* kVertexShader = R"(#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec3 velocity;
uniform mat4 clip_from_world;
noperspective out vec3 body_normal;
noperspective out vec3 body_velocity;
void main() {
  gl_Position = clip_from_world * vec4(position, 1.0);
  body_normal = normal;
  body_velocity = velocity;
}
)";

// float targets keep the interpolated vectors; 8-bit targets get dressing Eq. 6 and walking Eq. 9
// (the printed Eq. 9 reads 0.5 v + 0.5 / maxv; its inverse, Eq. 10, fixes it as 0.5 v / maxv + 0.5)
// depth peeling (peel != 0): only fragments beyond the previous layer's z-buffer value at the pixel
// by more than `gap` (kPeelGap), read from `previous` (that layer, laid out as the target)
constexpr const char* kFragmentShader = R"(#version 330 core
noperspective in vec3 body_normal;
noperspective in vec3 body_velocity;
uniform int encode8;
uniform float max_speed;
uniform int peel;
uniform sampler2D previous;
uniform float gap;
layout(location = 0) out vec4 normal_out;
layout(location = 1) out vec4 velocity_out;
void main() {
  if (peel != 0 && gl_FragCoord.z <= texelFetch(previous, ivec2(gl_FragCoord.xy), 0).r + gap)
    discard;
  if (encode8 != 0) {
    normal_out = vec4(0.5 * body_normal + 0.5, 1.0);
    velocity_out = vec4(0.5 * body_velocity / max_speed + 0.5, 1.0);
  } else {
    normal_out = vec4(body_normal, 1.0);
    velocity_out = vec4(body_velocity, 1.0);
  }
}
)";

class GlMapRenderer final : public MapRenderer {
 public:
  GlMapRenderer() : context_("is-gl") { set_up(); }

  ~GlMapRenderer() override {
    make_current();
    release_targets();
    glDeleteTextures(1, &previous_);
    glDeleteBuffers(static_cast<GLsizei>(vbo_.size()), vbo_.data());
    glDeleteVertexArrays(1, &vao_);
    glDeleteProgram(program_);
  }

  std::string_view name() const override { return "gl"; }

  void render(const BodyFrame& body, MapSet& maps) override {
    make_current();
    targets(maps);
    upload(body, maps.has_velocity);
    draw(body, maps);
    read_back(maps, 0, views_, 0);
    for (int layer = 2; layer <= maps.frame.layers; ++layer) peel(body, maps, layer);
    depth_from_zbuffer(maps);
  }

 private:
  // shaders, uniforms and vertex arrays in the new context
  void set_up() {
    // shaders and their uniforms
    program_ = osmesa::link_program(kVertexShader, kFragmentShader, "is-gl");
    u_clip_ = glGetUniformLocation(program_, "clip_from_world");
    u_encode8_ = glGetUniformLocation(program_, "encode8");
    u_max_speed_ = glGetUniformLocation(program_, "max_speed");
    u_peel_ = glGetUniformLocation(program_, "peel");
    glUseProgram(program_);
    glUniform1i(glGetUniformLocation(program_, "previous"), 0);
    glUniform1f(glGetUniformLocation(program_, "gap"), kPeelGap);
    // the previous layer's z-buffer values, fetched texel by texel
    glGenTextures(1, &previous_);
    glBindTexture(GL_TEXTURE_2D, previous_);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    // vertex arrays: positions, normals, velocities, indices
    glGenVertexArrays(1, &vao_);
    glBindVertexArray(vao_);
    glGenBuffers(static_cast<GLsizei>(vbo_.size()), vbo_.data());
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, vbo_[3]);
    if (glGetError() != GL_NO_ERROR) throw std::runtime_error("is-gl: OpenGL set-up failed");
  }

  void make_current() { context_.make_current(); }

  // (re)creates the FBO when size, view count or encoding changed: size x (views x size), front
  // below back, the extra views above them
  void targets(const MapSet& maps) {
    const bool same = fbo_ && size_ == maps.frame.size && views_ == maps.frame.views && float_ == maps.float_maps;
    if (same) return;
    release_targets();
    size_ = maps.frame.size;
    views_ = maps.frame.views;
    float_ = maps.float_maps;
    glGenFramebuffers(1, &fbo_);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
    glGenRenderbuffers(static_cast<GLsizei>(rbo_.size()), rbo_.data());
    const GLenum colour = float_ ? GL_RGBA32F : GL_RGBA8;
    const GLenum depth = float_ ? GL_DEPTH_COMPONENT32F : GL_DEPTH_COMPONENT24;
    const std::array<GLenum, 3> formats = {colour, colour, depth};
    const std::array<GLenum, 3> points = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_DEPTH_ATTACHMENT};
    for (std::size_t k = 0; k < rbo_.size(); ++k) {
      glBindRenderbuffer(GL_RENDERBUFFER, rbo_[k]);
      glRenderbufferStorage(GL_RENDERBUFFER, formats[k], size_, views_ * size_);
      glFramebufferRenderbuffer(GL_FRAMEBUFFER, points[k], GL_RENDERBUFFER, rbo_[k]);
    }
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
      throw std::runtime_error("is-gl: framebuffer of " + std::to_string(views_) + " x " + std::to_string(size_) +
                               "^2 maps is incomplete");
  }

  void release_targets() {
    if (!fbo_) return;
    glDeleteFramebuffers(1, &fbo_);
    glDeleteRenderbuffers(static_cast<GLsizei>(rbo_.size()), rbo_.data());
    fbo_ = 0;
  }

  // vertex attributes straight from the frame's packed 3 x n float arrays
  void upload(const BodyFrame& body, bool velocity) {
    const auto bytes = [](const auto& m) { return static_cast<GLsizeiptr>(m.size() * sizeof(float)); };
    const std::array<const Points3*, 3> arrays = {&body.positions, &body.normals, &body.velocities};
    for (GLuint k = 0; k < 3; ++k) {
      if (k == 2 && !velocity) {
        glDisableVertexAttribArray(2);
        glVertexAttrib3f(2, 0.0f, 0.0f, 0.0f);
        continue;
      }
      glBindBuffer(GL_ARRAY_BUFFER, vbo_[k]);
      glBufferData(GL_ARRAY_BUFFER, bytes(*arrays[k]), arrays[k]->data(), GL_STREAM_DRAW);
      glVertexAttribPointer(k, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
      glEnableVertexAttribArray(k);
    }
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(body.triangles.size() * sizeof(std::int32_t)),
                 body.triangles.data(), GL_STREAM_DRAW);
  }

  // every view, depth test keeping the surface nearest each camera; both targets always bound so
  // a moving frame after a static one needs no new shader variant (a static body's velocity
  // target gets zeros and is not read back)
  void draw(const BodyFrame& body, const MapSet& maps) {
    const std::array<GLenum, 2> buffers = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    glDrawBuffers(2, buffers.data());
    clear();
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_CULL_FACE);
    glUseProgram(program_);
    glUniform1i(u_encode8_, maps.float_maps ? 0 : 1);
    glUniform1f(u_max_speed_, maps.max_speed);
    glUniform1i(u_peel_, 0);
    for (int view = 0; view < views_; ++view) draw_view(body, maps.frame, view);
  }

  void clear() {
    glClearColor(0, 0, 0, 0);
    glClearDepth(1.0);
    glDisable(GL_SCISSOR_TEST);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_SCISSOR_TEST);
  }

  // one view into its rows of the target
  void draw_view(const BodyFrame& body, const MapFrame& frame, int view) {
    glViewport(0, view * size_, size_, size_);
    glScissor(0, view * size_, size_, size_);
    const std::array<float, 16> m = clip_from_world(frame, view);
    glUniformMatrix4fv(u_clip_, 1, GL_FALSE, m.data());
    glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(body.triangles.size()), GL_UNSIGNED_INT, nullptr);
  }

  // depth peeling: layer `layer` of every even view, drawn again into the view's own rows (the
  // same window coordinates, so the same depths, as the first pass and the CPU rasteriser) beyond
  // layer - 1's z-buffer values, uploaded as a texture laid out as the target; read back into the layer's maps
  void peel(const BodyFrame& body, MapSet& maps, int layer) {
    const MapFrame& f = maps.frame;
    const std::size_t n = maps.view_pixels();
    previous_depth_.assign(views_ * n, 1.0f);
    for (int view = 0; view < views_; view += 2)
      std::copy_n(maps.z.begin() + f.peel_map(view, layer - 1) * n, n, previous_depth_.begin() + view * n);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, previous_);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_R32F, size_, views_ * size_, 0, GL_RED, GL_FLOAT, previous_depth_.data());
    clear();
    glUniform1i(u_peel_, 1);
    for (int view = 0; view < views_; view += 2) draw_view(body, f, view);
    glUniform1i(u_peel_, 0);
    for (int view = 0; view < views_; view += 2) read_back(maps, view, 1, f.peel_map(view, layer));
  }

  // z-buffer values and colours of `count` views from `view` into maps `map`, map + 1, ... (raw
  // z-buffer values: depth_from_zbuffer turns them into coordinates once every layer is in)
  void read_back(MapSet& maps, int view, int count, int map) {
    const std::size_t at = static_cast<std::size_t>(map) * maps.view_pixels();
    const GLint y = view * size_;
    const GLsizei rows = count * size_;
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, y, size_, rows, GL_DEPTH_COMPONENT, GL_FLOAT, maps.z.data() + at);
    const GLenum type = maps.float_maps ? GL_FLOAT : GL_UNSIGNED_BYTE;
    const auto colours = [&](std::vector<float>& floats, std::vector<std::uint8_t>& bytes) {
      return maps.float_maps ? static_cast<void*>(floats.data() + 4 * at) : bytes.data() + 4 * at;
    };
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glReadPixels(0, y, size_, rows, GL_RGBA, type, colours(maps.normal, maps.normal8));
    if (maps.has_velocity) {
      glReadBuffer(GL_COLOR_ATTACHMENT1);
      glReadPixels(0, y, size_, rows, GL_RGBA, type, colours(maps.velocity, maps.velocity8));
    }
  }

  osmesa::Context context_;  // first member: destroyed after the GL objects the destructor deletes
  GLuint program_ = 0, vao_ = 0, fbo_ = 0, previous_ = 0;
  std::array<GLuint, 4> vbo_{};  // positions, normals, velocities, indices
  std::array<GLuint, 3> rbo_{};  // normal, velocity, depth
  GLint u_clip_ = -1, u_encode8_ = -1, u_max_speed_ = -1, u_peel_ = -1;
  std::vector<float> previous_depth_;  // the previous layer's z-buffer values, laid out as the target
  int size_ = 0;
  int views_ = 2;
  bool float_ = true;
};

}  // namespace

std::unique_ptr<MapRenderer> make_gl_map_renderer() { return std::make_unique<GlMapRenderer>(); }

}  // namespace clothbench
