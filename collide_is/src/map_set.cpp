#include "clothbench/collide_is/map_set.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>

namespace clothbench {

MapFrame make_map_frame(const Box3& box, const ColliderOptions& options) {
  if (options.map_size < 8)
    throw std::invalid_argument("image-space maps: map_size must be >= 8, got " + std::to_string(options.map_size));
  const Vec3 size = box.size();
  if (!(size.y() > 0) || !(size.x() > 0) || !(options.tol >= 0))
    throw std::invalid_argument("image-space maps: body bounding box is flat or tol is negative");
  MapFrame f;
  f.size = options.map_size;
  const Vec3 c = box.center();
  if (options.fit_extent) {
    // the box's larger side plus two pixels each way, centred on the box
    f.pixel = std::max(size.x(), size.y()) / static_cast<Real>(f.size - 4);
    f.x0 = c.x() - 0.5f * f.size * f.pixel;
    f.y0 = c.y() - 0.5f * f.size * f.pixel;
  } else {
    // the papers' square: side = body height, soles on the bottom row, centred in x (dressing Eq. 8)
    f.pixel = size.y() / static_cast<Real>(f.size);
    f.x0 = c.x() - 0.5f * size.y();
    f.y0 = box.min.y();
  }
  // near/far planes on the box's z faces, moved out by tol so no surface is clipped
  f.z_min = box.min.z() - options.tol;
  f.z_max = box.max.z() + options.tol;
  if (!(f.z_max > f.z_min)) throw std::invalid_argument("image-space maps: body bounding box has no depth");
  return f;
}

std::array<float, 16> clip_from_world(const MapFrame& f, int view) {
  const float side = f.size * f.pixel;
  const float sx = 2.0f / side, sz = 2.0f / f.depth_range();
  std::array<float, 16> m{};
  if (view == MapSet::kFront) {
    // x -> [-1, 1] left to right; near (ndc -1) at z_max
    m[0] = sx, m[12] = -1.0f - sx * f.x0;
    m[10] = -sz, m[14] = sz * f.z_max - 1.0f;
  } else {
    // mirrored x (dressing Eq. 8, X_back); near at z_min
    m[0] = -sx, m[12] = 1.0f + sx * f.x0;
    m[10] = sz, m[14] = -sz * f.z_min - 1.0f;
  }
  m[5] = sx, m[13] = -1.0f - sx * f.y0;
  m[15] = 1.0f;
  return m;
}

void MapSet::reset(const MapFrame& new_frame, bool floats, bool with_velocity, Real maxv) {
  frame = new_frame;
  float_maps = floats;
  has_velocity = with_velocity;
  max_speed = maxv;
  const std::size_t n = view_pixels();
  const float inf = std::numeric_limits<float>::infinity();
  // depth: front empty = -inf, back empty = +inf, so the comparison of Eq. 9 always fails there
  z.resize(2 * n);
  std::fill(z.begin(), z.begin() + n, -inf);
  std::fill(z.begin() + n, z.end(), inf);
  mask.assign(2 * n, kEmpty);
  // attributes in the chosen encoding only
  normal.resize(floats ? 8 * n : 0);
  normal8.resize(floats ? 0 : 8 * n);
  velocity.resize(floats && with_velocity ? 8 * n : 0);
  velocity8.resize(!floats && with_velocity ? 8 * n : 0);
}

Vec3 MapSet::raw_normal_at(std::size_t i) const {
  if (float_maps) return Vec3(normal[4 * i], normal[4 * i + 1], normal[4 * i + 2]);
  // dressing Eq. 7: n = 2 (R, G, B) - 1
  const std::uint8_t* c = &normal8[4 * i];
  return Vec3(c[0], c[1], c[2]) * (2.0f / 255.0f) - Vec3::Ones();
}

Vec3 MapSet::normal_at(std::size_t i) const {
  const Vec3 n = raw_normal_at(i);
  const Real len = n.norm();
  return len > 0 ? Vec3(n / len) : Vec3::Zero();
}

Vec3 MapSet::velocity_at(std::size_t i) const {
  if (!has_velocity) return Vec3::Zero();
  if (float_maps) return Vec3(velocity[4 * i], velocity[4 * i + 1], velocity[4 * i + 2]);
  // walking Eq. 10: v = maxv (2 (R, G, B) - 1)
  const std::uint8_t* c = &velocity8[4 * i];
  return max_speed * (Vec3(c[0], c[1], c[2]) * (2.0f / 255.0f) - Vec3::Ones());
}

namespace {

// copies every attribute of element `from` to element `to`
void copy_pixel(MapSet& m, std::size_t from, std::size_t to) {
  m.z[to] = m.z[from];
  if (m.float_maps) {
    std::copy_n(&m.normal[4 * from], 4, &m.normal[4 * to]);
    if (m.has_velocity) std::copy_n(&m.velocity[4 * from], 4, &m.velocity[4 * to]);
  } else {
    std::copy_n(&m.normal8[4 * from], 4, &m.normal8[4 * to]);
    if (m.has_velocity) std::copy_n(&m.velocity8[4 * from], 4, &m.velocity8[4 * to]);
  }
}

}  // namespace

void add_side_layer(MapSet& maps) {
  const int n = maps.frame.size;
  for (int view = 0; view < 2; ++view) {
    // front camera: nearer is the larger z; back camera: the smaller
    const auto nearer = [view](float a, float b) { return view == MapSet::kFront ? a > b : a < b; };
    for (int row = 0; row < n; ++row) {
      for (int col = 0; col < n; ++col) {
        const std::size_t i = maps.index(view, col, row);
        if (maps.mask[i] != MapSet::kBody) continue;
        // dressing 5.4: each empty 8-neighbour joins the layer with the nearest body pixel's values
        for (int dr = -1; dr <= 1; ++dr) {
          for (int dc = -1; dc <= 1; ++dc) {
            const int c = col + dc, r = row + dr;
            if (c < 0 || r < 0 || c >= n || r >= n) continue;
            const std::size_t j = maps.index(view, c, r);
            const bool take =
                maps.mask[j] == MapSet::kEmpty || (maps.mask[j] == MapSet::kSide && nearer(maps.z[i], maps.z[j]));
            if (!take) continue;
            copy_pixel(maps, i, j);
            maps.mask[j] = MapSet::kSide;
          }
        }
      }
    }
  }
}

void depth_from_zbuffer(MapSet& maps) {
  const MapFrame& f = maps.frame;
  const std::size_t n = maps.view_pixels();
  const float inf = std::numeric_limits<float>::infinity();
  for (std::size_t i = 0; i < 2 * n; ++i) {
    const float zbuf = maps.z[i];
    const bool front = i < n;
    // nothing drawn: the comparison of Eq. 9 must fail there
    if (zbuf >= 1.0f) {
      maps.z[i] = front ? -inf : inf;
      maps.mask[i] = MapSet::kEmpty;
      continue;
    }
    // dressing Eq. 5: z-buffer to geometry space
    maps.z[i] = front ? f.z_max - zbuf * f.depth_range() : f.z_min + zbuf * f.depth_range();
    maps.mask[i] = MapSet::kBody;
  }
}

MapSet render_maps(const BodyFrame& body, std::string_view renderer, const ColliderOptions& options) {
  validate_body(body, "render_maps");
  std::unique_ptr<MapRenderer> r;
  if (renderer == "gl") {
    r = make_gl_map_renderer();
  } else if (renderer == "cpu") {
    r = make_cpu_map_renderer();
  } else {
    throw std::invalid_argument("render_maps: unknown renderer '" + std::string(renderer) + "' (gl, cpu)");
  }
  MapSet maps;
  maps.reset(make_map_frame(bounding_box(body.positions), options), options.float_maps, body.moving, options.max_speed);
  r->render(body, maps);
  if (options.side_layer) add_side_layer(maps);
  return maps;
}

}  // namespace clothbench
