// The OpenGL renderer of the image-space maps, on any provider's context (OSMesa, EGL): one FBO holding every
// view, every call through the context's own functions (gl_api.hpp). On a context of OpenGL 4.3 the maps stay on
// the device (gl_compute_maps.hpp) and answer queries there.
#include <algorithm>
#include <array>
#include <functional>
#include <mutex>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "clothbench/collide_is/device_maps.hpp"
#include "clothbench/collide_is/gl_context.hpp"
#include "clothbench/collide_is/map_set.hpp"
#include "gl_api.hpp"
#include "gl_compute_maps.hpp"

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

class GlMapRenderer final : public MapRenderer, public DeviceMaps {
 public:
  explicit GlMapRenderer(std::unique_ptr<GlContext> context)
      : context_(std::move(context)), who_("is-" + context_->renderer_name()), name_(context_->renderer_name()) {
    make_current(Role::kDraw);
    gl_ = GlApi::load([this](const char* f) { return context_->proc(f); }, who_, context_->compute());
    set_up();
    if (context_->compute()) compute_ = std::make_unique<GlComputeMaps>(gl_, who_, clock_);
    context_->release();
  }

  ~GlMapRenderer() override {
    context_->make_current(context_index(Role::kDraw));
    if (compute_) compute_->release();
    clock_.release();
    release_targets();
    gl_.DeleteBuffers(static_cast<GLsizei>(vbo_.size()), vbo_.data());
    gl_.DeleteVertexArrays(1, &vao_);
    gl_.DeleteProgram(program_);
    context_->release();
  }

  std::string_view name() const override { return name_; }
  std::string device() const override { return device_; }
  DeviceMaps* device_maps() override { return compute_ ? this : nullptr; }

  // on the device: drawn there, then copied out; else each pass read back
  void render(const BodyFrame& body, MapSet& maps) override {
    if (compute_) {
      draw(body, maps, 0, 0);
      copy(0, maps);
      return;
    }
    const Current current(*this, Role::kDraw);
    passes(body, maps, [&](int view, int map) { read_back(maps, view, map); });
    depth_from_zbuffer(maps);
  }

  void draw(const BodyFrame& body, const MapSet& shape, int rings, int slot) override {
    const Current current(*this, Role::kDraw);
    clock_.start(gl_);
    compute_->begin(slot, shape);
    passes(body, shape, [&](int view, int map) { compute_->resolve(slot, view, map, tex_[0], tex_[1]); });
    compute_->side_layer(slot, rings);
    clock_.mark(GpuClock::kSideLayer);
    gl_.Finish();
    const auto ms = clock_.read();
    for (std::size_t k = 0; k < ms.size(); ++k) phase_total_ms_[k] += ms[k];
    ++draws_;
  }

  std::vector<std::pair<std::string, double>> draw_phases_ms() const override {
    std::vector<std::pair<std::string, double>> out;
    for (std::size_t k = 0; draws_ > 0 && k < phase_total_ms_.size(); ++k)
      out.emplace_back(GpuClock::kNames[k], phase_total_ms_[k] / double(draws_));
    return out;
  }

  void query(int slot, PointsView points, const AnswerRules& rules, Contact* out) override {
    const Current current(*this, Role::kAnswer);
    compute_->query(slot, points, rules, out);
  }

  void copy(int slot, MapSet& maps) override {
    const Current current(*this, Role::kAnswer);
    compute_->copy(slot, maps);
  }

 private:
  // What a call does: draw (targets, vertex arrays, a map set's buffers) or answer from a map set (queries, copies).
  // With two contexts (GlContext::contexts()) each role has its own, so a map set may be drawn on one thread while
  // another answers from the other set; the answering context stays current on its thread between calls (no other
  // thread needs it), the drawing one is released after each call, so any thread may draw next. With one context
  // both roles take turns on it, released after each call.
  enum class Role { kDraw, kAnswer };
  int context_index(Role role) const { return context_->contexts() == 2 && role == Role::kDraw ? 1 : 0; }
  bool kept(Role role) const { return context_->contexts() == 2 && role == Role::kAnswer; }

  // the role's context current on the calling thread for one call (one call per role at a time)
  class Current {
   public:
    Current(GlMapRenderer& r, Role role)
        : r_(r), lock_(r.kept(role) ? r.answer_mutex_ : r.draw_mutex_), keep_(r.kept(role)) {
      r_.make_current(role);
    }
    ~Current() {
      if (!keep_) r_.context_->release();
    }
    Current(const Current&) = delete;
    Current& operator=(const Current&) = delete;

   private:
    GlMapRenderer& r_;
    std::lock_guard<std::mutex> lock_;
    bool keep_;
  };

  // every view, then every peeled layer of the even views, each pass handed to `keep` (view, map) while its
  // targets hold it
  void passes(const BodyFrame& body, const MapSet& maps, const std::function<void(int, int)>& keep) {
    targets(maps);
    upload(body, maps.has_velocity);
    clock_.mark(GpuClock::kUpload);
    draw_views(body, maps);
    clock_.mark(GpuClock::kDraw);
    for (int view = 0; view < views_; ++view) keep(view, view);
    for (int layer = 2; layer <= maps.frame.layers; ++layer) {
      peel(body, maps);
      for (int view = 0; view < views_; view += 2) keep(view, maps.frame.peel_map(view, layer));
    }
  }

  // shaders, uniforms and vertex arrays in the new context
  void set_up() {
    // shaders and their uniforms
    program_ = link_program();
    u_clip_ = gl_.GetUniformLocation(program_, "clip_from_world");
    u_encode8_ = gl_.GetUniformLocation(program_, "encode8");
    u_max_speed_ = gl_.GetUniformLocation(program_, "max_speed");
    u_peel_ = gl_.GetUniformLocation(program_, "peel");
    gl_.UseProgram(program_);
    gl_.Uniform1i(gl_.GetUniformLocation(program_, "previous"), 0);
    gl_.Uniform1f(gl_.GetUniformLocation(program_, "gap"), kPeelGap);
    // vertex arrays: positions, normals, velocities, indices
    gl_.GenVertexArrays(1, &vao_);
    gl_.BindVertexArray(vao_);
    gl_.GenBuffers(static_cast<GLsizei>(vbo_.size()), vbo_.data());
    gl_.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, vbo_[3]);
    if (gl_.GetError() != GL_NO_ERROR) throw std::runtime_error(who_ + ": OpenGL set-up failed");
    const auto text = [&](GLenum what) {
      const auto* s = reinterpret_cast<const char*>(gl_.GetString(what));
      return std::string(s ? s : "?");
    };
    device_ = context_->provider() + ": " + text(GL_VENDOR) + " " + text(GL_RENDERER) + ", OpenGL " + text(GL_VERSION);
  }

  void make_current(Role role) {
    if (!context_->make_current(context_index(role)))
      throw std::runtime_error(who_ + ": the OpenGL context cannot be made current (" +
                               (kept(role) ? "queries come from one thread: another holds the answering context"
                                           : "the provider refused") +
                               ")");
  }

  // the two shaders compiled and linked
  GLuint link_program() {
    const GLuint vs = compile_shader(gl_, GL_VERTEX_SHADER, kVertexShader, who_);
    GLuint fs = 0;
    try {
      fs = compile_shader(gl_, GL_FRAGMENT_SHADER, kFragmentShader, who_);
    } catch (...) {
      gl_.DeleteShader(vs);
      throw;
    }
    return link_shaders(gl_, {vs, fs}, who_);
  }

  // (re)creates the FBO when size, view count or encoding changed: size x (views x size), front
  // below back, the extra views above them; textures (normal, velocity, depth) that shaders may read, and the
  // previous layer's depth (peel) in the depth target's format
  void targets(const MapSet& maps) {
    const bool same = fbo_ && size_ == maps.frame.size && views_ == maps.frame.views && float_ == maps.float_maps;
    if (same) return;
    release_targets();
    size_ = maps.frame.size;
    views_ = maps.frame.views;
    float_ = maps.float_maps;
    gl_.GenFramebuffers(1, &fbo_);
    gl_.BindFramebuffer(GL_FRAMEBUFFER, fbo_);
    gl_.GenTextures(static_cast<GLsizei>(tex_.size()), tex_.data());
    const GLenum colour = float_ ? GL_RGBA32F : GL_RGBA8;
    const GLenum depth = float_ ? GL_DEPTH_COMPONENT32F : GL_DEPTH_COMPONENT24;
    const std::array<GLenum, 4> formats = {colour, colour, depth, depth};
    const std::array<GLenum, 4> data = {GL_RGBA, GL_RGBA, GL_DEPTH_COMPONENT, GL_DEPTH_COMPONENT};
    const std::array<GLenum, 3> points = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_DEPTH_ATTACHMENT};
    for (std::size_t k = 0; k < tex_.size(); ++k) {
      gl_.BindTexture(GL_TEXTURE_2D, tex_[k]);
      gl_.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
      gl_.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
      gl_.TexImage2D(GL_TEXTURE_2D, 0, static_cast<GLint>(formats[k]), size_, views_ * size_, 0, data[k], GL_FLOAT,
                     nullptr);
      if (k < points.size()) gl_.FramebufferTexture2D(GL_FRAMEBUFFER, points[k], GL_TEXTURE_2D, tex_[k], 0);
    }
    if (gl_.CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
      throw std::runtime_error(who_ + ": framebuffer of " + std::to_string(views_) + " x " + std::to_string(size_) +
                               "^2 maps is incomplete");
  }

  void release_targets() {
    if (!fbo_) return;
    gl_.DeleteFramebuffers(1, &fbo_);
    gl_.DeleteTextures(static_cast<GLsizei>(tex_.size()), tex_.data());
    fbo_ = 0;
  }

  // vertex attributes straight from the frame's packed 3 x n float arrays
  void upload(const BodyFrame& body, bool velocity) {
    const auto bytes = [](const auto& m) { return static_cast<GLsizeiptr>(m.size() * sizeof(float)); };
    const std::array<const Points3*, 3> arrays = {&body.positions, &body.normals, &body.velocities};
    for (GLuint k = 0; k < 3; ++k) {
      if (k == 2 && !velocity) {
        gl_.DisableVertexAttribArray(2);
        gl_.VertexAttrib3f(2, 0.0f, 0.0f, 0.0f);
        continue;
      }
      gl_.BindBuffer(GL_ARRAY_BUFFER, vbo_[k]);
      gl_.BufferData(GL_ARRAY_BUFFER, bytes(*arrays[k]), arrays[k]->data(), GL_STREAM_DRAW);
      gl_.VertexAttribPointer(k, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
      gl_.EnableVertexAttribArray(k);
    }
    gl_.BufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(body.triangles.size() * sizeof(std::int32_t)),
                   body.triangles.data(), GL_STREAM_DRAW);
  }

  // every view, depth test keeping the surface nearest each camera; both targets always bound so
  // a moving frame after a static one needs no new shader variant (a static body's velocity
  // target gets zeros and is not read back)
  void draw_views(const BodyFrame& body, const MapSet& maps) {
    const std::array<GLenum, 2> buffers = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    gl_.DrawBuffers(2, buffers.data());
    clear();
    gl_.Enable(GL_DEPTH_TEST);
    gl_.DepthFunc(GL_LESS);
    gl_.Disable(GL_CULL_FACE);
    gl_.UseProgram(program_);
    gl_.Uniform1i(u_encode8_, maps.float_maps ? 0 : 1);
    gl_.Uniform1f(u_max_speed_, maps.max_speed);
    gl_.Uniform1i(u_peel_, 0);
    for (int view = 0; view < views_; ++view) draw_view(body, maps, view);
  }

  void clear() {
    gl_.ClearColor(0, 0, 0, 0);
    gl_.ClearDepth(1.0);
    gl_.Disable(GL_SCISSOR_TEST);
    gl_.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    gl_.Enable(GL_SCISSOR_TEST);
  }

  // one view into its rows of the target (those the maps draw)
  void draw_view(const BodyFrame& body, const MapSet& maps, int view) {
    const int first = maps.row_first[static_cast<std::size_t>(view)],
              last = maps.row_last[static_cast<std::size_t>(view)];
    if (first > last) return;
    gl_.Viewport(0, view * size_, size_, size_);
    gl_.Scissor(0, view * size_ + first, size_, last - first + 1);
    const std::array<float, 16> m = clip_from_world(maps.frame, view);
    gl_.UniformMatrix4fv(u_clip_, 1, GL_FALSE, m.data());
    gl_.DrawElements(GL_TRIANGLES, static_cast<GLsizei>(body.triangles.size()), GL_UNSIGNED_INT, nullptr);
  }

  // depth peeling: the next layer of every even view, drawn again into the view's own rows (the same window
  // coordinates, so the same depths, as the first pass and the CPU rasteriser) beyond the last pass's z-buffer
  // values, copied first into a depth texture the fragment shader reads
  void peel(const BodyFrame& body, const MapSet& maps) {
    gl_.ActiveTexture(GL_TEXTURE0);
    gl_.BindTexture(GL_TEXTURE_2D, tex_[3]);
    gl_.CopyTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 0, 0, size_, views_ * size_);
    clock_.mark(GpuClock::kDepthCopy);
    clear();
    gl_.UseProgram(program_);
    gl_.Uniform1i(u_peel_, 1);
    for (int view = 0; view < views_; view += 2) draw_view(body, maps, view);
    gl_.Uniform1i(u_peel_, 0);
    clock_.mark(GpuClock::kDraw);
  }

  // z-buffer values and colours of view `view`'s rows the maps draw into map `map` (raw z-buffer values:
  // depth_from_zbuffer turns them into coordinates once every layer is in; the other rows stay empty)
  void read_back(MapSet& maps, int view, int map) {
    const auto [begin, end] = maps.drawn(map);
    if (begin == end) return;
    const auto size = static_cast<std::size_t>(size_);
    const GLint y =
        view * size_ + static_cast<GLint>((begin - static_cast<std::size_t>(map) * maps.view_pixels()) / size);
    const auto rows = static_cast<GLsizei>((end - begin) / size);
    gl_.PixelStorei(GL_PACK_ALIGNMENT, 1);
    gl_.ReadPixels(0, y, size_, rows, GL_DEPTH_COMPONENT, GL_FLOAT, maps.z.data() + begin);
    const GLenum type = maps.float_maps ? GL_FLOAT : GL_UNSIGNED_BYTE;
    const auto colours = [&](std::vector<float>& floats, std::vector<std::uint8_t>& bytes) {
      return maps.float_maps ? static_cast<void*>(floats.data() + 4 * begin) : bytes.data() + 4 * begin;
    };
    gl_.ReadBuffer(GL_COLOR_ATTACHMENT0);
    gl_.ReadPixels(0, y, size_, rows, GL_RGBA, type, colours(maps.normal, maps.normal8));
    if (maps.has_velocity) {
      gl_.ReadBuffer(GL_COLOR_ATTACHMENT1);
      gl_.ReadPixels(0, y, size_, rows, GL_RGBA, type, colours(maps.velocity, maps.velocity8));
    }
  }

  std::unique_ptr<GlContext> context_;  // first member: destroyed after the GL objects the destructor deletes
  std::string who_, name_, device_;
  GlApi gl_;
  GpuClock clock_;                          // device maps: the device's time per phase of a draw
  std::array<double, GpuClock::kPhases> phase_total_ms_{};
  long draws_ = 0;
  std::unique_ptr<GlComputeMaps> compute_;  // OpenGL 4.3 contexts: the maps kept on the device
  std::mutex draw_mutex_, answer_mutex_;    // one call per role at a time (Current)
  GLuint program_ = 0, vao_ = 0, fbo_ = 0;
  std::array<GLuint, 4> vbo_{};  // positions, normals, velocities, indices
  std::array<GLuint, 4> tex_{};  // normal, velocity, depth targets; the previous layer's depth
  GLint u_clip_ = -1, u_encode8_ = -1, u_max_speed_ = -1, u_peel_ = -1;
  int size_ = 0;
  int views_ = 2;
  bool float_ = true;
};

}  // namespace

std::unique_ptr<MapRenderer> make_gl_map_renderer(std::unique_ptr<GlContext> context) {
  return std::make_unique<GlMapRenderer>(std::move(context));
}

}  // namespace clothbench
