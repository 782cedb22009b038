// The CPU rasteriser of the image-space maps: llvmpipe's coverage (vertices snapped to 1/256 pixel,
// pixel-centre samples, top-left rule) and llvmpipe's depth arithmetic, so both renderers give the
// same z-buffer (Mesa 22.3: draw_llvm viewport, lp_setup_tri vertex order, lp_state_setup planes,
// lp_bld_interp evaluation).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "clothbench/collide_is/map_set.hpp"

namespace clothbench {
namespace {

// sub-pixel precision of llvmpipe's rasteriser: vertices snap to 1/256 pixel
constexpr int kSubpixelBits = 8;
constexpr float kSubpixel = 1 << kSubpixelBits;

// llvmpipe's JIT fuses its multiply-adds (llvm.fmuladd) where the host has FMA instructions
bool host_fuses_multiply_add() {
#if defined(__x86_64__) || defined(__i386__)
  __builtin_cpu_init();
  return __builtin_cpu_supports("fma");
#else
  return true;
#endif
}

// a * b + c, rounded once when `fused`
inline float mul_add(bool fused, float a, float b, float c) { return fused ? std::fma(a, b, c) : a * b + c; }

// one projected vertex of one view, in the window of the size x 2 size target (back view above)
struct WindowVertex {
  float x, y;           // window coordinates [pixels], origin at the target's lower-left corner
  float zbuf;           // z-buffer depth of this view: 0 at its near plane, 1 at its far plane
  std::int64_t fx, fy;  // snapped, shifted so pixel centres lie on integers (fixed point)
};

// attributes interpolated over a triangle: normal xyz, velocity xyz
constexpr int kAttributes = 6;
using Attributes = std::array<float, kAttributes>;

// a triangle's planes in window coordinates. Attributes: a(x, y) = a0 + dadx (x - x0) + dady (y - y0).
// Depth as llvmpipe: zbuf(col, row) = z_origin + dzdx col + dzdy row, anchored at the origin
struct Planes {
  float x0, y0;
  Attributes a0, dadx, dady;
  float z_origin, dzdx, dzdy;
};

// edge function of the snapped edge a -> b at sample s (> 0 left of the edge)
inline std::int64_t edge(const WindowVertex& a, const WindowVertex& b, std::int64_t sx, std::int64_t sy) {
  return (b.fx - a.fx) * (sy - a.fy) - (b.fy - a.fy) * (sx - a.fx);
}

// top-left rule in y-up window coordinates for a counter-clockwise triangle: samples exactly on
// an edge belong to it when the edge is a left edge (going down) or a top edge (going left)
inline bool owns_ties(const WindowVertex& a, const WindowVertex& b) {
  const std::int64_t dy = b.fy - a.fy;
  return dy < 0 || (dy == 0 && b.fx < a.fx);
}

class CpuMapRenderer final : public MapRenderer {
 public:
  std::string_view name() const override { return "cpu"; }
  std::string device() const override { return "our CPU rasteriser"; }

  void render(const BodyFrame& body, MapSet& maps) override {
    // window coordinates and z-buffer depth of every view, as GL computes them
    project(body, maps.frame);
    // z-buffer cleared to the far plane in the rows drawn, turned into geometry space at the end (as GL's read-back)
    for (int map = 0; map < maps.frame.map_count(); ++map) {
      const auto [begin, end] = maps.drawn(map);
      std::fill(maps.z.begin() + static_cast<std::ptrdiff_t>(begin), maps.z.begin() + static_cast<std::ptrdiff_t>(end),
                1.0f);
    }
    // view by view (each keeps to its own maps), the triangles in order
    for (int view = 0; view < maps.frame.views; ++view) {
      const auto& w = window_[view];
      for (Eigen::Index t = 0; t < body.triangles.cols(); ++t) {
        const int i0 = body.triangles(0, t), i1 = body.triangles(1, t), i2 = body.triangles(2, t);
        attributes(body, maps.has_velocity, i0, a_[0]);
        attributes(body, maps.has_velocity, i1, a_[1]);
        attributes(body, maps.has_velocity, i2, a_[2]);
        draw(maps, view, {w[i0], w[i1], w[i2]}, a_);
      }
    }
    depth_from_zbuffer(maps);
  }

 private:
  // clip coordinates as the vertex shader computes them (w = 1; each clip coordinate has one
  // non-zero matrix entry, on the view's column, row or depth axis), then llvmpipe's viewport
  // transform (draw_llvm) into the size x (views x size) target, the back view above the front
  void project(const BodyFrame& body, const MapFrame& f) {
    const int nv = body.vertex_count();
    const float half = 0.5f * static_cast<float>(f.size);
    for (int view = 0; view < f.views; ++view) {
      const std::array<float, 16> m = clip_from_world(f, view);
      const int cu = MapFrame::column_axis(view), rv = MapFrame::row_axis(view), d = MapFrame::view_axis(view);
      const float y_translate = half + static_cast<float>(view * f.size);
      auto& w = window_[view];
      w.resize(nv);
      for (int v = 0; v < nv; ++v) {
        const float xc = m[4 * cu] * body.positions(cu, v) + m[12];
        const float yc = m[4 * rv + 1] * body.positions(rv, v) + m[13];
        const float zc = m[4 * d + 2] * body.positions(d, v) + m[14];
        w[v].x = mul_add(fused_, xc, half, half);
        w[v].y = mul_add(fused_, yc, half, y_translate);
        w[v].zbuf = mul_add(fused_, zc, 0.5f, 0.5f);
        // pixel centres at +0.5 become integer sample positions (llvmpipe's pixel offset)
        w[v].fx = std::llrint((w[v].x - 0.5f) * kSubpixel);
        w[v].fy = std::llrint((w[v].y - 0.5f) * kSubpixel);
      }
    }
  }

  static void attributes(const BodyFrame& body, bool velocity, int v, Attributes& a) {
    a[0] = body.normals(0, v);
    a[1] = body.normals(1, v);
    a[2] = body.normals(2, v);
    a[3] = velocity ? body.velocities(0, v) : 0.0f;
    a[4] = velocity ? body.velocities(1, v) : 0.0f;
    a[5] = velocity ? body.velocities(2, v) : 0.0f;
  }

  // llvmpipe's depth plane (lp_state_setup: init_args, calc_coef4): float set-up from the
  // unsnapped vertices, 1 / area folded into the edge deltas, value anchored at the origin
  static bool depth_plane(const std::array<WindowVertex, 3>& w, Planes& p) {
    float dx01 = w[0].x - w[1].x, dy01 = w[0].y - w[1].y;
    float dx20 = w[2].x - w[0].x, dy20 = w[2].y - w[0].y;
    const float area = dx01 * dy20 - dy01 * dx20;
    if (area == 0.0f) return false;
    const float ooa = 1.0f / area;
    dx01 *= ooa, dy01 *= ooa, dx20 *= ooa, dy20 *= ooa;
    const float dz01 = w[0].zbuf - w[1].zbuf, dz20 = w[2].zbuf - w[0].zbuf;
    p.dzdx = dz01 * dy20 - dz20 * dy01;
    p.dzdy = dz20 * dx01 - dz01 * dx20;
    p.z_origin = w[0].zbuf - (p.dzdx * (w[0].x - 0.5f) + p.dzdy * (w[0].y - 0.5f));
    return true;
  }

  // attribute planes from the unsnapped window positions, anchored at the first vertex
  static bool attribute_planes(const std::array<WindowVertex, 3>& w, const std::array<Attributes, 3>& a, Planes& p) {
    const float dx1 = w[1].x - w[0].x, dy1 = w[1].y - w[0].y;
    const float dx2 = w[2].x - w[0].x, dy2 = w[2].y - w[0].y;
    const float area = dx1 * dy2 - dx2 * dy1;
    if (area == 0.0f) return false;
    const float inv = 1.0f / area;
    p.x0 = w[0].x;
    p.y0 = w[0].y;
    for (int k = 0; k < kAttributes; ++k) {
      const float da1 = a[1][k] - a[0][k], da2 = a[2][k] - a[0][k];
      p.a0[k] = a[0][k];
      p.dadx[k] = (da1 * dy2 - da2 * dy1) * inv;
      p.dady[k] = (da2 * dx1 - da1 * dx2) * inv;
    }
    return true;
  }

  // rasterises one triangle into one view: coverage, depth test, attributes (the planes are set up at the first
  // sample covered: most of a fine body's triangles cover none in most views)
  void draw(MapSet& maps, int view, std::array<WindowVertex, 3> w, std::array<Attributes, 3> a) const {
    // zero snapped area draws nothing
    const std::int64_t area = edge(w[0], w[1], w[2].fx, w[2].fy);
    if (area == 0) return;
    // integer sample range of the snapped bounding box, clipped to this view's rows of the target (those it draws)
    const int n = maps.frame.size, row_offset = view * n;
    const auto lo = [](std::int64_t v) { return static_cast<int>(-((-v) >> kSubpixelBits)); };
    const auto hi = [](std::int64_t v) { return static_cast<int>(v >> kSubpixelBits); };
    const int c0 = std::max(0, lo(std::min({w[0].fx, w[1].fx, w[2].fx})));
    const int c1 = std::min(n - 1, hi(std::max({w[0].fx, w[1].fx, w[2].fx})));
    const auto v = static_cast<std::size_t>(view);
    const int r0 = std::max(row_offset + maps.row_first[v], lo(std::min({w[0].fy, w[1].fy, w[2].fy})));
    const int r1 = std::min(row_offset + maps.row_last[v], hi(std::max({w[0].fy, w[1].fy, w[2].fy})));
    if (c0 > c1 || r0 > r1) return;
    // depth in llvmpipe's vertex order: a counter-clockwise triangle (y up) has its first two
    // vertices swapped (lp_setup_tri, provoking vertex last)
    const std::array<WindowVertex, 3> depth_order = area > 0 ? std::array<WindowVertex, 3>{w[1], w[0], w[2]} : w;
    // coverage and attributes counter-clockwise
    if (area < 0) {
      std::swap(w[1], w[2]);
      std::swap(a[1], a[2]);
    }
    const bool tie0 = owns_ties(w[1], w[2]), tie1 = owns_ties(w[2], w[0]), tie2 = owns_ties(w[0], w[1]);
    // the edge functions step exactly (integers) from one sample to the next along a row
    const std::int64_t step = std::int64_t(1) << kSubpixelBits;
    const std::int64_t dx0 = -(w[2].fy - w[1].fy) * step, dx1 = -(w[0].fy - w[2].fy) * step,
                       dx2 = -(w[1].fy - w[0].fy) * step;
    Planes p;
    bool planes = false;
    for (int row = r0; row <= r1; ++row) {
      const std::int64_t sy = static_cast<std::int64_t>(row) << kSubpixelBits;
      const std::int64_t sx0 = static_cast<std::int64_t>(c0) << kSubpixelBits;
      std::int64_t e0 = edge(w[1], w[2], sx0, sy), e1 = edge(w[2], w[0], sx0, sy), e2 = edge(w[0], w[1], sx0, sy);
      for (int col = c0; col <= c1; ++col, e0 += dx0, e1 += dx1, e2 += dx2) {
        // inside all three edges, ties by the top-left rule
        if (e0 < 0 || e1 < 0 || e2 < 0) continue;
        if ((e0 == 0 && !tie0) || (e1 == 0 && !tie1) || (e2 == 0 && !tie2)) continue;
        if (!planes && !(planes = depth_plane(depth_order, p) && attribute_planes(w, a, p))) return;
        shade(maps, view, static_cast<std::size_t>(row - row_offset) * n + col, col, row, p);
      }
    }
  }

  static constexpr std::size_t kNoSlot = ~std::size_t(0);

  // the element a fragment at `zbuf` takes among an even view's layers at `pixel`, the deeper ones moved down
  // (kNoSlot: none). The layers keep the nearest distinct depths in order, as depth peeling finds them
  // (layer l: the nearest fragment beyond layer l - 1 + kPeelGap, the first drawn of equals)
  static std::size_t peel_slot(MapSet& maps, int view, std::size_t pixel, float zbuf) {
    const MapFrame& f = maps.frame;
    const int layers = f.layers;
    const auto element = [&](int layer) { return f.peel_map(view, layer) * maps.view_pixels() + pixel; };
    const auto depth = [&](int layer) { return maps.z[element(layer)]; };
    int slot = 1;
    while (slot <= layers && !(zbuf < depth(slot))) ++slot;
    // beyond every layer kept, or not beyond the layer above by the peeling gap
    if (slot > layers || (slot > 1 && zbuf <= depth(slot - 1) + kPeelGap)) return kNoSlot;
    // layers the new one hides (within the gap beyond it) go; else the deeper ones move down one
    int hidden = 0;
    while (slot + hidden <= layers && depth(slot + hidden) <= zbuf + kPeelGap) ++hidden;
    if (hidden == 0) {
      for (int layer = layers; layer > slot; --layer) maps.copy_element(element(layer - 1), element(layer));
    } else {
      for (int layer = slot + 1; layer + hidden - 1 <= layers; ++layer)
        maps.copy_element(element(layer + hidden - 1), element(layer));
      for (int layer = layers - hidden + 2; layer <= layers; ++layer) maps.z[element(layer)] = 1.0f;
    }
    return element(slot);
  }

  // depth test (GL_LESS on the z-buffer) and attribute write at the target's pixel (col, row), `pixel`
  // within the view; an even view with layers keeps several (peel_slot)
  void shade(MapSet& maps, int view, std::size_t pixel, int col, int row, const Planes& p) const {
    // llvmpipe's interpolation (lp_bld_interp): z_origin + dzdx col, then + dzdy row, clamped to [0, 1]
    const float x = static_cast<float>(col), y = static_cast<float>(row);
    const float zbuf = std::clamp(mul_add(fused_, p.dzdy, y, mul_add(fused_, p.dzdx, x, p.z_origin)), 0.0f, 1.0f);
    std::size_t i = static_cast<std::size_t>(view) * maps.view_pixels() + pixel;
    if (view % 2 == 0 && maps.frame.layers > 1) {
      i = peel_slot(maps, view, pixel, zbuf);
      if (i == kNoSlot) return;
    } else if (!(zbuf < maps.z[i])) {
      return;
    }
    maps.z[i] = zbuf;
    const float dx = x + 0.5f - p.x0, dy = y + 0.5f - p.y0;
    Attributes nv;
    for (int k = 0; k < kAttributes; ++k) nv[k] = p.a0[k] + p.dadx[k] * dx + p.dady[k] * dy;
    if (maps.float_maps) {
      float* n = &maps.normal[4 * i];
      n[0] = nv[0], n[1] = nv[1], n[2] = nv[2], n[3] = 1.0f;
      if (maps.has_velocity) {
        float* v = &maps.velocity[4 * i];
        v[0] = nv[3], v[1] = nv[4], v[2] = nv[5], v[3] = 1.0f;
      }
      return;
    }
    // 8-bit colours: dressing Eq. 6 and walking Eq. 9, unorm rounding as GL
    const auto unorm = [](float c) {
      return static_cast<std::uint8_t>(std::lrint(std::clamp(c, 0.0f, 1.0f) * 255.0f));
    };
    std::uint8_t* n = &maps.normal8[4 * i];
    for (int k = 0; k < 3; ++k) n[k] = unorm(0.5f * nv[k] + 0.5f);
    n[3] = 255;
    if (maps.has_velocity) {
      std::uint8_t* v = &maps.velocity8[4 * i];
      for (int k = 0; k < 3; ++k) v[k] = unorm(0.5f * nv[k + 3] / maps.max_speed + 0.5f);
      v[3] = 255;
    }
  }

  bool fused_ = host_fuses_multiply_add();           // fuse multiply-adds as llvmpipe does on this host
  std::array<std::vector<WindowVertex>, 6> window_;  // per view, one per body vertex
  std::array<Attributes, 3> a_;                      // the current triangle's vertex attributes
};

}  // namespace

std::unique_ptr<MapRenderer> make_cpu_map_renderer() { return std::make_unique<CpuMapRenderer>(); }

bool cpu_device(std::string_view device) {
  return device.find("llvmpipe") != std::string_view::npos || device == CpuMapRenderer().device();
}

}  // namespace clothbench
