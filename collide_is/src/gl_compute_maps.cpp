// Compute shaders over the maps kept on the device: each repeats, in `precise` arithmetic (no fused multiply-adds,
// as the CPU code), what the CPU path computes from a MapSet.
#include "gl_compute_maps.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <utility>

namespace clothbench {
namespace {

// MapSet's arrays as shader storage: z, mask (kEmpty / kBody / kSide in the low byte, the side layer's ring in
// the next), normal and velocity as vec4 (float maps: the values; 8-bit maps: the bytes 0..255 as floats)
constexpr const char* kBuffers = R"(
layout(std430, binding = 0) buffer Z { float z[]; };
layout(std430, binding = 1) buffer Mask { uint mask[]; };
layout(std430, binding = 2) buffer Normal { vec4 normal[]; };
layout(std430, binding = 3) buffer Velocity { vec4 velocity[]; };
uniform int size;
uniform int has_velocity;
)";

// one pass's targets into a map (depth_from_zbuffer, dressing Eq. 5): z-buffer value to the coordinate along the
// view's axis; nothing drawn (or a row not drawn) leaves the map empty. The z-buffer values come as glReadPixels
// hands them out (into a buffer on the device), so that a 24-bit z-buffer converts as it does for the CPU
constexpr const char* kResolve = R"(
layout(local_size_x = 8, local_size_y = 8) in;
layout(std430, binding = 6) readonly buffer ZBuffer { float zbuffer[]; };
uniform sampler2D normal_target;
uniform sampler2D velocity_target;
uniform int map, view, row_first, row_last, floats;
uniform float hi, lo, range;
void main() {
  const ivec2 px = ivec2(gl_GlobalInvocationID.xy);
  if (px.x >= size || px.y >= size) return;
  const uint i = uint(map) * uint(size * size) + uint(px.y * size + px.x);
  const bool front = view % 2 == 0;
  const bool drawn = px.y >= row_first && px.y <= row_last;
  const ivec2 t = ivec2(px.x, view * size + px.y);
  const float zbuf = drawn ? zbuffer[t.y * size + t.x] : 1.0;
  vec4 n = drawn ? texelFetch(normal_target, t, 0) : vec4(0.0);
  vec4 v = drawn && has_velocity != 0 ? texelFetch(velocity_target, t, 0) : vec4(0.0);
  if (floats == 0) {
    n = round(n * 255.0);
    v = round(v * 255.0);
  }
  normal[i] = n;
  if (has_velocity != 0) velocity[i] = v;
  if (zbuf >= 1.0) {
    z[i] = uintBitsToFloat(front ? 0xff800000u : 0x7f800000u);
    mask[i] = 0u;
    return;
  }
  precise float d = zbuf * range;
  precise float g = front ? hi - d : lo + d;
  z[i] = g;
  mask[i] = 1u;
}
)";

// one ring of dressing 5.4's side layer on one view (add_side_layer): an empty pixel next to a source (a body
// pixel for ring 1, a pixel of ring - 1 after) takes the values of the one nearest the camera, the first in the
// CPU's row-major order among equals
constexpr const char* kSide = R"(
layout(local_size_x = 8, local_size_y = 8) in;
uniform int ring;
void main() {
  const ivec2 px = ivec2(gl_GlobalInvocationID.xy);
  const int view = int(gl_GlobalInvocationID.z);
  if (px.x >= size || px.y >= size) return;
  const uint base = uint(view) * uint(size * size);
  const uint j = base + uint(px.y * size + px.x);
  if (mask[j] != 0u) return;
  const uint source = ring == 1 ? 1u : (2u | (uint(ring - 1) << 8));
  int best = -1;
  for (int dr = -1; dr <= 1; ++dr)
    for (int dc = -1; dc <= 1; ++dc) {
      const ivec2 q = px + ivec2(dc, dr);
      if ((dr == 0 && dc == 0) || q.x < 0 || q.y < 0 || q.x >= size || q.y >= size) continue;
      const uint i = base + uint(q.y * size + q.x);
      if (mask[i] != source) continue;
      if (best < 0 || (view % 2 == 0 ? z[i] > z[uint(best)] : z[i] < z[uint(best)])) best = int(i);
    }
  if (best < 0) return;
  const uint b = uint(best);
  z[j] = z[b];
  normal[j] = normal[b];
  if (has_velocity != 0) velocity[j] = velocity[b];
  mask[j] = 2u | (uint(ring) << 8);
}
)";

// ImageSpaceCollider's answer (image_space_collider.cpp), line by line
constexpr const char* kQuery = R"(
layout(local_size_x = 64) in;
layout(std430, binding = 4) readonly buffer Points { float xyz[]; };
layout(std430, binding = 5) writeonly buffer Contacts { vec4 contact[]; };
uniform int views, layers, count, floats, plane, rule, parts;
uniform float pixel, tol, max_speed;
uniform vec3 origin;
const uint kBody = 1u, kSide = 2u;
const float kInf = uintBitsToFloat(0x7f800000u);

int column_axis(int view) { return view == 2 || view == 3 ? 2 : 0; }
int row_axis(int view) { return view >= 4 ? 2 : 1; }
int view_axis(int view) { return view < 2 ? 2 : view < 4 ? 0 : 1; }
int peel_map(int view, int layer) { return layer == 1 ? view : views + (layer - 2) * (views / 2) + view / 2; }
int view_of(int map) { return map < views ? map : 2 * ((map - views) % (views / 2)); }
uint element(int map, int col, int row) {
  return uint(map) * uint(size * size) + uint(row * size + (map == 1 ? size - 1 - col : col));
}
uint mask_at(uint i) { return mask[i] & 0xffu; }
vec3 raw_normal(uint i) {
  if (floats != 0) return normal[i].xyz;
  precise vec3 n = normal[i].xyz * (2.0 / 255.0) - vec3(1.0);  // dressing Eq. 7
  return n;
}
float norm(vec3 n) {
  precise float s = n.x * n.x + n.y * n.y + n.z * n.z;
  return sqrt(s);
}
vec3 normal_at(uint i) {
  const vec3 n = raw_normal(i);
  precise float len = norm(n);
  return len > 0.0 ? n / len : vec3(0.0);
}
vec3 velocity_at(uint i) {
  if (has_velocity == 0) return vec3(0.0);
  if (floats != 0) return velocity[i].xyz;
  precise vec3 v = max_speed * (velocity[i].xyz * (2.0 / 255.0) - vec3(1.0));  // walking Eq. 10
  return v;
}

bool blend(int view, float a_world, float b_world, inout vec3 n_out, inout vec3 v_out) {
  precise float u = (a_world - origin[column_axis(view)]) / pixel - 0.5;
  precise float v = (b_world - origin[row_axis(view)]) / pixel - 0.5;
  if (!(u >= 0.0 && v >= 0.0 && u < float(size - 1) && v < float(size - 1))) return false;
  const int col = int(u), row = int(v);
  precise float a = u - float(col), b = v - float(row);
  precise vec3 n = vec3(0.0), vel = vec3(0.0);
  for (int k = 0; k < 4; ++k) {
    const uint j = element(view, col + (k & 1), row + (k >> 1));
    if (mask_at(j) != kBody) return false;
    precise float w = ((k & 1) != 0 ? a : 1.0 - a) * ((k >> 1) != 0 ? b : 1.0 - b);
    n += w * raw_normal(j);
    if (has_velocity != 0) vel += w * velocity_at(j);
  }
  precise float len = norm(n);
  if (!(len > 0.0)) return false;
  n_out = n / len;
  v_out = vel;
  return true;
}

struct PairAnswer {
  float depth;
  int map, col, row;
  bool side, folded;
};
bool outside(PairAnswer a) { return a.depth > 0.0 || a.side; }

// a point inside the union between above_z and below_z: to the middle of an overlap there when nearer
void send_to_pinch(float top_z[4], int top_map[4], float bottom_z[4], int bottom_map[4], int overlaps, float x,
                   float above_z, float below_z, inout PairAnswer a) {
  for (int o = 0; o < overlaps; ++o) {
    precise float middle = 0.5 * (top_z[o] + bottom_z[o]);
    precise float to_middle = abs(x - middle);
    if (top_z[o] > above_z || bottom_z[o] < below_z || !(to_middle < -a.depth)) continue;
    a.depth = -to_middle;
    a.map = x < middle ? top_map[o] : bottom_map[o];
  }
}

void between_layers(int front, int col, int row, float x, inout PairAnswer a) {
  const int axis = view_axis(front);
  float cz[8], top_z[4], bottom_z[4];
  int cm[8], top_map[4], bottom_map[4];
  int crossings = 0, winding = 0, overlaps = 0;
  bool folded = false;
  float last_z = 0.0;
  int last_map = 0;
  for (int layer = 1; layer <= layers; ++layer) {
    const int map = peel_map(front, layer);
    const uint i = element(map, col, row);
    if (mask_at(i) != kBody) break;
    last_z = z[i];
    last_map = map;
    const bool enters = layer == 1 || raw_normal(i)[axis] > 0.0;
    const int before = winding;
    if (before == 0 && !enters) folded = true;
    winding = max(0, winding + (enters ? 1 : -1));
    if ((before == 0) != (winding == 0)) {
      cz[crossings] = last_z;
      cm[crossings] = last_map;
      ++crossings;
    }
    if (before < 2 && winding == 2 && overlaps < 4) {
      top_z[overlaps] = last_z;
      top_map[overlaps] = last_map;
    }
    if (before == 2 && winding < 2 && overlaps < 4) {
      bottom_z[overlaps] = last_z;
      bottom_map[overlaps] = last_map;
      ++overlaps;
    }
  }
  for (int k = 1; k < crossings; ++k) {
    if (x < cz[k]) continue;
    precise float to_above = cz[k - 1] - x, to_below = x - cz[k];
    a.depth = k % 2 == 1 ? -min(to_above, to_below) : min(to_above, to_below);
    a.map = to_above <= to_below ? cm[k - 1] : cm[k];
    if (k % 2 == 1 && parts == 1) send_to_pinch(top_z, top_map, bottom_z, bottom_map, overlaps, x, cz[k - 1], cz[k], a);
    a.folded = parts == 1 && folded && a.depth > 0.0;
    return;
  }
  const bool whole = layers == 1 || mask_at(element(peel_map(front, layers), col, row)) != kBody;
  if (whole) return;
  const float above_z = winding > 0 ? cz[crossings - 1] : last_z;
  const int above_map = winding > 0 ? cm[crossings - 1] : last_map;
  const float back = z[element(front + 1, col, row)];
  precise float d_back = back - x;
  precise float d_above = x - above_z;
  a.depth = max(d_above, d_back);
  a.map = d_above >= d_back ? above_map : front + 1;
  if (a.depth < 0.0 && parts == 1) send_to_pinch(top_z, top_map, bottom_z, bottom_map, overlaps, x, above_z, back, a);
}

bool pair_answer(int pair, vec3 p, out PairAnswer a) {
  a = PairAnswer(0.0, 0, 0, 0, false, false);
  const int front = 2 * pair, cu = column_axis(front), rv = row_axis(front), axis = view_axis(front);
  precise float u = (p[cu] - origin[cu]) / pixel, v = (p[rv] - origin[rv]) / pixel;
  if (!(u >= 0.0 && v >= 0.0 && u < float(size) && v < float(size))) return false;
  a.col = int(u);
  a.row = int(v);
  const uint fi = element(front, a.col, a.row), bi = element(front + 1, a.col, a.row);
  precise float d_front = p[axis] - z[fi], d_back = z[bi] - p[axis];
  a.depth = max(d_front, d_back);
  a.map = d_front >= d_back ? front : front + 1;
  a.side = mask_at(fi) == kSide;
  if (layers > 1 && d_front < 0.0 && mask_at(fi) == kBody) between_layers(front, a.col, a.row, p[axis], a);
  return true;
}

float key(PairAnswer x) { return x.side ? 1e30 : x.depth; }
bool replaces(PairAnswer a, PairAnswer b) {
  if (rule == 1) return b.depth > a.depth;  // ViewRule::kAllPairs
  if (rule == 2) return b.depth < a.depth;  // ViewRule::kAnyPair
  const int rank_a = outside(a) ? (a.folded ? 0 : 2) : 1, rank_b = outside(b) ? (b.folded ? 0 : 2) : 1;
  if (rank_a != rank_b) return rank_b > rank_a;
  if (outside(a)) return outside(b) && key(b) < key(a);
  return outside(b) || b.depth > a.depth;
}

bool choose(vec3 p, out PairAnswer best) {
  if (views == 2) return pair_answer(0, p, best);
  bool any = false;
  PairAnswer a;
  best = PairAnswer(0.0, 0, 0, 0, false, false);
  for (int pair = 0; pair < views / 2; ++pair)
    if (pair_answer(pair, p, a) && (!any || replaces(best, a))) {
      best = a;
      any = true;
    }
  return any;
}

void answer(uint k, bool hit, float depth, vec3 n, vec3 v) {
  contact[2u * k] = vec4(n, depth);
  contact[2u * k + 1u] = vec4(v, hit ? 1.0 : 0.0);
}

void main() {
  const uint k = gl_GlobalInvocationID.x;
  if (k >= uint(count)) return;
  const vec3 p = vec3(xyz[3u * k], xyz[3u * k + 1u], xyz[3u * k + 2u]);
  PairAnswer a;
  if (!choose(p, a)) {
    answer(k, false, kInf, vec3(0.0), vec3(0.0));
    return;
  }
  const float depth_z = a.depth;
  precise float limit = plane != 0 ? tol + pixel : tol;
  if (!(depth_z < limit)) {
    answer(k, false, max(depth_z, tol), vec3(0.0), vec3(0.0));
    return;
  }
  const int view = view_of(a.map), cu = column_axis(view), rv = row_axis(view);
  const uint i = element(a.map, a.col, a.row);
  float depth = depth_z;
  vec3 n = normal_at(i), vel = vec3(0.0);
  bool blended = false;
  if (plane != 0) {
    // signed distance to the tangent plane at the pixel centre's surface point
    precise vec3 s;
    s[cu] = origin[cu] + (float(a.col) + 0.5) * pixel;
    s[rv] = origin[rv] + (float(a.row) + 0.5) * pixel;
    s[view_axis(view)] = z[i];
    precise vec3 e = p - s;
    precise float d = e.x * n.x + e.y * n.y + e.z * n.z;
    depth = depth_z > 0.0 ? d : clamp(d, depth_z, 0.0);
    if (!(depth < tol)) {
      answer(k, false, max(d, tol), vec3(0.0), vec3(0.0));
      return;
    }
    precise vec3 foot = p - d * n;
    blended = a.map == view && blend(view, foot[cu], foot[rv], n, vel);
  }
  if (!blended) vel = velocity_at(i);
  if (mask_at(i) == kSide) depth = max(depth, 0.0);
  answer(k, true, depth, n, vel);
}
)";

std::string source(const char* body) { return std::string("#version 430 core\n") + kBuffers + body; }

}  // namespace

GlComputeMaps::GlComputeMaps(const GlApi& gl, std::string who, GpuClock& clock)
    : gl_(gl), who_(std::move(who)), clock_(clock) {
  resolve_ = program(kResolve);
  side_ = program(kSide);
  query_ = program(kQuery);
  for (Slot& s : slots_) gl_.GenBuffers(static_cast<GLsizei>(s.buf.size()), s.buf.data());
  gl_.GenBuffers(1, &points_);
  gl_.GenBuffers(1, &contacts_);
  gl_.GenBuffers(1, &zbuffer_);
  gl_.UseProgram(resolve_);
  gl_.Uniform1i(gl_.GetUniformLocation(resolve_, "normal_target"), 1);
  gl_.Uniform1i(gl_.GetUniformLocation(resolve_, "velocity_target"), 2);
  if (gl_.GetError() != GL_NO_ERROR) throw std::runtime_error(who_ + ": OpenGL compute set-up failed");
}

void GlComputeMaps::release() {
  for (Slot& s : slots_) gl_.DeleteBuffers(static_cast<GLsizei>(s.buf.size()), s.buf.data());
  gl_.DeleteBuffers(1, &points_);
  gl_.DeleteBuffers(1, &contacts_);
  gl_.DeleteBuffers(1, &zbuffer_);
  for (GLuint p : {resolve_, side_, query_}) gl_.DeleteProgram(p);
}

GLuint GlComputeMaps::program(const char* body) {
  const std::string text = source(body);
  return link_shaders(gl_, {compile_shader(gl_, GL_COMPUTE_SHADER, text.c_str(), who_ + " (compute)")}, who_);
}

void GlComputeMaps::bind(const Slot& s) {
  for (GLuint k = 0; k < 4; ++k) gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, k, s.buf[k]);
}

void GlComputeMaps::begin(int slot, const MapSet& shape) {
  Slot& s = slots_[static_cast<std::size_t>(slot)];
  s.shape = shape;
  const std::size_t pixels = static_cast<std::size_t>(shape.frame.map_count()) * shape.view_pixels();
  if (pixels == s.pixels) return;
  GLint limit = 0;
  gl_.GetIntegerv(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &limit);
  if (limit <= 0 || 16 * pixels > static_cast<std::size_t>(limit))
    throw std::runtime_error(who_ + ": " + std::to_string(shape.frame.map_count()) + " maps of " +
                             std::to_string(shape.frame.size) + "^2 need " + std::to_string(16 * pixels >> 20) +
                             " MiB of shader storage, the device allows " + std::to_string(limit >> 20) + " MiB");
  const std::array<std::size_t, 4> bytes = {4 * pixels, 4 * pixels, 16 * pixels, 16 * pixels};
  for (std::size_t k = 0; k < 4; ++k) {
    gl_.BindBuffer(GL_SHADER_STORAGE_BUFFER, s.buf[k]);
    gl_.BufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(bytes[k]), nullptr, GL_DYNAMIC_COPY);
  }
  if (gl_.GetError() != GL_NO_ERROR)
    throw std::runtime_error(who_ + ": no device memory for " + std::to_string(shape.frame.map_count()) +
                             " maps of " + std::to_string(shape.frame.size) + "^2");
  s.pixels = pixels;
}

void GlComputeMaps::resolve(int slot, int view, int map, GLuint normal, GLuint velocity) {
  const Slot& s = slots_[static_cast<std::size_t>(slot)];
  const MapFrame& f = s.shape.frame;
  // the pass's z-buffer values of the view's rows, read into a buffer on the device once per pass (its first view)
  if (view == 0) {
    read_zbuffer(f);
    clock_.mark(GpuClock::kDepthCopy);
  }
  const int axis = MapFrame::view_axis(view);
  // depth_from_zbuffer's planes: views 0-1 on z_min / z_max, the others on their own axis's
  const float hi = f.plane_max(axis), lo = f.plane_min(axis), range = view < 2 ? f.depth_range() : hi - lo;
  gl_.UseProgram(resolve_);
  bind(s);
  const auto u = [&](const char* name) { return gl_.GetUniformLocation(resolve_, name); };
  gl_.Uniform1i(u("size"), f.size);
  gl_.Uniform1i(u("has_velocity"), s.shape.has_velocity ? 1 : 0);
  gl_.Uniform1i(u("map"), map);
  gl_.Uniform1i(u("view"), view);
  gl_.Uniform1i(u("row_first"), s.shape.row_first[static_cast<std::size_t>(view)]);
  gl_.Uniform1i(u("row_last"), s.shape.row_last[static_cast<std::size_t>(view)]);
  gl_.Uniform1i(u("floats"), s.shape.float_maps ? 1 : 0);
  gl_.Uniform1f(u("hi"), hi);
  gl_.Uniform1f(u("lo"), lo);
  gl_.Uniform1f(u("range"), range);
  gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 6, zbuffer_);
  const std::array<GLuint, 2> textures = {normal, velocity};
  for (GLuint k = 0; k < 2; ++k) {
    gl_.ActiveTexture(GL_TEXTURE1 + k);
    gl_.BindTexture(GL_TEXTURE_2D, textures[k]);
  }
  gl_.ActiveTexture(GL_TEXTURE0);
  const auto groups = static_cast<GLuint>((f.size + 7) / 8);
  gl_.DispatchCompute(groups, groups, 1);
  gl_.MemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  clock_.mark(GpuClock::kResolve);
}

void GlComputeMaps::read_zbuffer(const MapFrame& f) {
  const auto bytes = static_cast<GLsizeiptr>(4) * f.size * f.views * f.size;
  gl_.BindBuffer(GL_PIXEL_PACK_BUFFER, zbuffer_);
  if (bytes != zbuffer_bytes_) {
    gl_.BufferData(GL_PIXEL_PACK_BUFFER, bytes, nullptr, GL_STREAM_COPY);
    zbuffer_bytes_ = bytes;
  }
  gl_.PixelStorei(GL_PACK_ALIGNMENT, 1);
  gl_.ReadPixels(0, 0, f.size, f.views * f.size, GL_DEPTH_COMPONENT, GL_FLOAT, nullptr);
  gl_.BindBuffer(GL_PIXEL_PACK_BUFFER, 0);
}

void GlComputeMaps::side_layer(int slot, int rings) {
  const Slot& s = slots_[static_cast<std::size_t>(slot)];
  const MapFrame& f = s.shape.frame;
  gl_.UseProgram(side_);
  bind(s);
  gl_.Uniform1i(gl_.GetUniformLocation(side_, "size"), f.size);
  gl_.Uniform1i(gl_.GetUniformLocation(side_, "has_velocity"), s.shape.has_velocity ? 1 : 0);
  const auto groups = static_cast<GLuint>((f.size + 7) / 8);
  for (int ring = 1; ring <= std::clamp(rings, 0, 255); ++ring) {
    gl_.Uniform1i(gl_.GetUniformLocation(side_, "ring"), ring);
    gl_.DispatchCompute(groups, groups, static_cast<GLuint>(f.views));
    gl_.MemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  }
}

void GlComputeMaps::query(int slot, PointsView points, const AnswerRules& rules, Contact* out) {
  if (points.count == 0) return;
  const Slot& s = slots_[static_cast<std::size_t>(slot)];
  const MapFrame& f = s.shape.frame;
  // the batch: points up, answers down (8 floats a point)
  if (points.count > points_capacity_) {
    points_capacity_ = points.count;
    gl_.BindBuffer(GL_SHADER_STORAGE_BUFFER, points_);
    gl_.BufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(12 * points.count), nullptr, GL_STREAM_DRAW);
    gl_.BindBuffer(GL_SHADER_STORAGE_BUFFER, contacts_);
    gl_.BufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(32 * points.count), nullptr, GL_STREAM_READ);
  }
  gl_.BindBuffer(GL_SHADER_STORAGE_BUFFER, points_);
  gl_.BufferSubData(GL_SHADER_STORAGE_BUFFER, 0, static_cast<GLsizeiptr>(12 * points.count), points.xyz);
  gl_.UseProgram(query_);
  bind(s);
  gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 4, points_);
  gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 5, contacts_);
  const auto u = [&](const char* name) { return gl_.GetUniformLocation(query_, name); };
  gl_.Uniform1i(u("size"), f.size);
  gl_.Uniform1i(u("has_velocity"), s.shape.has_velocity ? 1 : 0);
  gl_.Uniform1i(u("views"), f.views);
  gl_.Uniform1i(u("layers"), f.layers);
  gl_.Uniform1i(u("count"), static_cast<GLint>(points.count));
  gl_.Uniform1i(u("floats"), s.shape.float_maps ? 1 : 0);
  gl_.Uniform1i(u("plane"), rules.test == DepthTest::kTangentPlane ? 1 : 0);
  gl_.Uniform1i(u("rule"), rules.rule == ViewRule::kAllPairs ? 1 : rules.rule == ViewRule::kAnyPair ? 2 : 0);
  gl_.Uniform1i(u("parts"), rules.overlapping_parts ? 1 : 0);
  gl_.Uniform1f(u("pixel"), f.pixel);
  gl_.Uniform1f(u("tol"), rules.tol);
  gl_.Uniform1f(u("max_speed"), s.shape.max_speed);
  gl_.Uniform3f(u("origin"), f.x0, f.y0, f.z0);
  gl_.DispatchCompute(static_cast<GLuint>((points.count + 63) / 64), 1, 1);
  gl_.MemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  answers_.resize(8 * points.count);
  gl_.BindBuffer(GL_SHADER_STORAGE_BUFFER, contacts_);
  gl_.GetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, static_cast<GLsizeiptr>(4 * answers_.size()), answers_.data());
  for (std::size_t k = 0; k < points.count; ++k) {
    const float* a = &answers_[8 * k];
    Contact& c = out[k];
    c.normal = Vec3(a[0], a[1], a[2]);
    c.depth = a[3];
    c.body_velocity = Vec3(a[4], a[5], a[6]);
    c.hit = a[7] != 0.0f;
  }
}

void GlComputeMaps::copy(int slot, MapSet& maps) {
  const Slot& s = slots_[static_cast<std::size_t>(slot)];
  maps.reset(s.shape.frame, s.shape.float_maps, s.shape.has_velocity, s.shape.max_speed);
  maps.row_first = s.shape.row_first;
  maps.row_last = s.shape.row_last;
  const std::size_t n = s.pixels;
  if (n == 0) return;
  gl_.MemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  const auto read = [&](GLuint buffer, std::size_t floats) {
    scratch_.resize(floats);
    gl_.BindBuffer(GL_SHADER_STORAGE_BUFFER, buffer);
    gl_.GetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, static_cast<GLsizeiptr>(4 * floats), scratch_.data());
  };
  read(s.buf[0], n);
  std::copy_n(scratch_.begin(), n, maps.z.begin());
  read(s.buf[1], n);
  for (std::size_t i = 0; i < n; ++i) {
    std::uint32_t m = 0;
    std::memcpy(&m, &scratch_[i], 4);
    maps.mask[i] = static_cast<std::uint8_t>(m & 0xffu);
  }
  const auto attribute = [&](GLuint buffer, std::vector<float>& floats, std::vector<std::uint8_t>& bytes) {
    read(buffer, 4 * n);
    if (maps.float_maps)
      std::copy_n(scratch_.begin(), 4 * n, floats.begin());
    else
      std::transform(scratch_.begin(), scratch_.begin() + 4 * n, bytes.begin(),
                     [](float b) { return static_cast<std::uint8_t>(b); });
  };
  attribute(s.buf[2], maps.normal, maps.normal8);
  if (maps.has_velocity) attribute(s.buf[3], maps.velocity, maps.velocity8);
}

}  // namespace clothbench
