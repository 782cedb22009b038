// The CPU rasteriser of the image-space maps: the same coverage as llvmpipe (vertices snapped to
// 1/256 pixel, pixel-centre samples, top-left rule) and its depths within a few micrometres.
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

// one projected vertex of one view
struct WindowVertex {
  float x, y;           // window coordinates [pixels], origin at the lower-left corner
  std::int64_t fx, fy;  // snapped, shifted so pixel centres lie on integers (fixed point)
};

// attributes interpolated over a triangle: z-buffer depth of the view, normal xyz, velocity xyz
constexpr int kAttributes = 7;
using Attributes = std::array<float, kAttributes>;

// a triangle's attribute planes in window coordinates: a(x, y) = a0 + dadx (x - x0) + dady (y - y0);
// depth as llvmpipe evaluates it, from its value at the sample origin: z_origin + dzdx col + dzdy row
struct Planes {
  float x0, y0;
  Attributes a0, dadx, dady;
  float z_origin;
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

  void render(const BodyFrame& body, MapSet& maps) override {
    const MapFrame& f = maps.frame;
    // world -> window per view (dressing Eq. 8): back columns are mirrored
    project(body, f);
    const float inv_range = 1.0f / f.depth_range();
    // one pass over the triangles, both views
    for (Eigen::Index t = 0; t < body.triangles.cols(); ++t) {
      const int i0 = body.triangles(0, t), i1 = body.triangles(1, t), i2 = body.triangles(2, t);
      attributes(body, maps.has_velocity, i0, a_[0]);
      attributes(body, maps.has_velocity, i1, a_[1]);
      attributes(body, maps.has_velocity, i2, a_[2]);
      for (int view = 0; view < 2; ++view) {
        const auto& w = window_[view];
        // z-buffer depth of this view: 0 at its near plane, 1 at its far plane
        std::array<Attributes, 3> a = a_;
        for (auto& v : a) v[0] = view == MapSet::kFront ? (f.z_max - v[0]) * inv_range : (v[0] - f.z_min) * inv_range;
        draw(maps, view, {w[i0], w[i1], w[i2]}, a);
      }
    }
  }

 private:
  // window coordinates of every vertex in both views
  void project(const BodyFrame& body, const MapFrame& f) {
    const int nv = body.vertex_count();
    for (auto& w : window_) w.resize(nv);
    const float inv = 1.0f / f.pixel;
    for (int v = 0; v < nv; ++v) {
      const float u = (body.positions(0, v) - f.x0) * inv;
      const float y = (body.positions(1, v) - f.y0) * inv;
      window_[MapSet::kFront][v] = snap(u, y);
      window_[MapSet::kBack][v] = snap(static_cast<float>(f.size) - u, y);
    }
  }

  static WindowVertex snap(float x, float y) {
    // pixel centres at +0.5 become integer sample positions (llvmpipe's pixel offset)
    return {x, y, std::llrint((x - 0.5f) * kSubpixel), std::llrint((y - 0.5f) * kSubpixel)};
  }

  static void attributes(const BodyFrame& body, bool velocity, int v, Attributes& a) {
    a[0] = body.positions(2, v);
    a[1] = body.normals(0, v);
    a[2] = body.normals(1, v);
    a[3] = body.normals(2, v);
    a[4] = velocity ? body.velocities(0, v) : 0.0f;
    a[5] = velocity ? body.velocities(1, v) : 0.0f;
    a[6] = velocity ? body.velocities(2, v) : 0.0f;
  }

  // attribute planes from the unsnapped window positions (as llvmpipe's set-up does)
  static bool planes(const std::array<WindowVertex, 3>& w, const std::array<Attributes, 3>& a, Planes& p) {
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
    p.z_origin = p.a0[0] - p.dadx[0] * (w[0].x - 0.5f) - p.dady[0] * (w[0].y - 0.5f);
    return true;
  }

  // rasterises one triangle into one view: coverage, depth test, attributes
  static void draw(MapSet& maps, int view, std::array<WindowVertex, 3> w, std::array<Attributes, 3> a) {
    // counter-clockwise in y-up window coordinates; zero snapped area draws nothing
    const std::int64_t area = edge(w[0], w[1], w[2].fx, w[2].fy);
    if (area == 0) return;
    if (area < 0) {
      std::swap(w[1], w[2]);
      std::swap(a[1], a[2]);
    }
    Planes p;
    if (!planes(w, a, p)) return;
    // integer sample range of the snapped bounding box, clipped to the map
    const int n = maps.frame.size;
    const auto lo = [](std::int64_t v) { return static_cast<int>(-((-v) >> kSubpixelBits)); };
    const auto hi = [](std::int64_t v) { return static_cast<int>(v >> kSubpixelBits); };
    const int c0 = std::max(0, lo(std::min({w[0].fx, w[1].fx, w[2].fx})));
    const int c1 = std::min(n - 1, hi(std::max({w[0].fx, w[1].fx, w[2].fx})));
    const int r0 = std::max(0, lo(std::min({w[0].fy, w[1].fy, w[2].fy})));
    const int r1 = std::min(n - 1, hi(std::max({w[0].fy, w[1].fy, w[2].fy})));
    const bool tie0 = owns_ties(w[1], w[2]), tie1 = owns_ties(w[2], w[0]), tie2 = owns_ties(w[0], w[1]);
    for (int row = r0; row <= r1; ++row) {
      const std::int64_t sy = static_cast<std::int64_t>(row) << kSubpixelBits;
      for (int col = c0; col <= c1; ++col) {
        const std::int64_t sx = static_cast<std::int64_t>(col) << kSubpixelBits;
        // inside all three edges, ties by the top-left rule
        const std::int64_t e0 = edge(w[1], w[2], sx, sy), e1 = edge(w[2], w[0], sx, sy), e2 = edge(w[0], w[1], sx, sy);
        if (e0 < 0 || e1 < 0 || e2 < 0) continue;
        if ((e0 == 0 && !tie0) || (e1 == 0 && !tie1) || (e2 == 0 && !tie2)) continue;
        shade(maps, view, col, row, p);
      }
    }
  }

  // depth test (nearer to this view's camera wins) and attribute write at one pixel centre
  static void shade(MapSet& maps, int view, int col, int row, const Planes& p) {
    const float dx = static_cast<float>(col) + 0.5f - p.x0, dy = static_cast<float>(row) + 0.5f - p.y0;
    const float dorg = p.z_origin + p.dadx[0] * static_cast<float>(col) + p.dady[0] * static_cast<float>(row);
    // z-buffer value to geometry space (dressing Eq. 5, tol applied at the query)
    const MapFrame& f = maps.frame;
    const float z = view == MapSet::kFront ? f.z_max - dorg * f.depth_range() : f.z_min + dorg * f.depth_range();
    const std::size_t i = maps.index(view, col, row);
    const bool nearer = view == MapSet::kFront ? z > maps.z[i] : z < maps.z[i];
    if (!nearer) return;
    maps.z[i] = z;
    maps.mask[i] = MapSet::kBody;
    std::array<float, 6> nv;
    for (int k = 0; k < 6; ++k) nv[k] = p.a0[k + 1] + p.dadx[k + 1] * dx + p.dady[k + 1] * dy;
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

  std::array<std::vector<WindowVertex>, 2> window_;  // per view, one per body vertex
  std::array<Attributes, 3> a_;                      // the current triangle's vertex attributes
};

}  // namespace

std::unique_ptr<MapRenderer> make_cpu_map_renderer() { return std::make_unique<CpuMapRenderer>(); }

}  // namespace clothbench
