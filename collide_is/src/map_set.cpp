#include "clothbench/collide_is/map_set.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace clothbench {

void check_view_options(const ColliderOptions& options) {
  if (options.views != 2 && options.views != 4 && options.views != 6)
    throw std::invalid_argument("image-space maps: views must be 2 (front/back), 4 (+ left/right) or 6 (+ top/bottom), got " +
                                std::to_string(options.views));
  if (options.layers < 1 || options.layers > 8)
    throw std::invalid_argument("image-space maps: layers must be 1 (the nearest surface) to 8, got " +
                                std::to_string(options.layers));
  if (!(options.side_layer_mm >= 0) || !std::isfinite(options.side_layer_mm))
    throw std::invalid_argument("image-space maps: side_layer_mm must be a finite number >= 0 (0: one pixel), got " +
                                std::to_string(options.side_layer_mm));
}

MapFrame make_map_frame(const Box3& box, const ColliderOptions& options) {
  check_view_options(options);
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
    // (with the views along X and Y, the box's depth too, so their squares hold it as well)
    const Real extent = options.views > 2 ? size.maxCoeff() : std::max(size.x(), size.y());
    f.pixel = extent / static_cast<Real>(f.size - 4);
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
  // the views along X and Y (beyond the papers): the same pixel, the square centred on the box in z
  f.views = options.views;
  f.layers = options.layers;
  f.z0 = c.z() - 0.5f * f.size * f.pixel;
  f.x_min = box.min.x() - options.tol;
  f.x_max = box.max.x() + options.tol;
  f.y_min = box.min.y() - options.tol;
  f.y_max = box.max.y() + options.tol;
  return f;
}

namespace {

// the views along X and Y: column and row axes over the square, not mirrored; the depth axis to -1
// at the near plane (the + face for even views, the - face for odd ones)
std::array<float, 16> extra_view_clip(const MapFrame& f, int view) {
  const float side = f.size * f.pixel;
  const float sx = 2.0f / side;
  const int cu = MapFrame::column_axis(view), rv = MapFrame::row_axis(view), d = MapFrame::view_axis(view);
  const float lo = f.plane_min(d), hi = f.plane_max(d), sz = 2.0f / (hi - lo);
  std::array<float, 16> m{};
  m[4 * cu + 0] = sx, m[12] = -1.0f - sx * f.origin(cu);
  m[4 * rv + 1] = sx, m[13] = -1.0f - sx * f.origin(rv);
  if (view % 2 == 0) {
    m[4 * d + 2] = -sz, m[14] = sz * hi - 1.0f;
  } else {
    m[4 * d + 2] = sz, m[14] = -sz * lo - 1.0f;
  }
  m[15] = 1.0f;
  return m;
}

}  // namespace

std::array<float, 16> clip_from_world(const MapFrame& f, int view) {
  if (view >= 2) return extra_view_clip(f, view);
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

void MapSet::set_shape(const MapFrame& new_frame, bool floats, bool with_velocity, Real maxv) {
  frame = new_frame;
  float_maps = floats;
  has_velocity = with_velocity;
  max_speed = maxv;
  row_first.fill(0);
  row_last.fill(new_frame.size - 1);
}

void MapSet::reset(const MapFrame& new_frame, bool floats, bool with_velocity, Real maxv) {
  set_shape(new_frame, floats, with_velocity, maxv);
  const std::size_t n = view_pixels();
  const float inf = std::numeric_limits<float>::infinity();
  const std::size_t views = static_cast<std::size_t>(new_frame.map_count());
  // depth: front (even views and their layers) empty = -inf, back (odd) empty = +inf, so the
  // comparison of Eq. 9 always fails there
  z.resize(views * n);
  for (std::size_t k = 0; k < views; ++k)
    std::fill_n(z.begin() + k * n, n, new_frame.view_of(static_cast<int>(k)) % 2 == 0 ? -inf : inf);
  mask.assign(views * n, kEmpty);
  // attributes in the chosen encoding only
  normal.resize(floats ? 4 * views * n : 0);
  normal8.resize(floats ? 0 : 4 * views * n);
  velocity.resize(floats && with_velocity ? 4 * views * n : 0);
  velocity8.resize(!floats && with_velocity ? 4 * views * n : 0);
}

void MapSet::limit_rows(const Box3& region) {
  for (int view = 0; view < frame.views; ++view) {
    const int axis = MapFrame::row_axis(view);
    const Real o = frame.origin(axis);
    const int first = static_cast<int>(std::floor((region.min[axis] - o) / frame.pixel)) - 1;
    const int last = static_cast<int>(std::ceil((region.max[axis] - o) / frame.pixel)) + 1;
    row_first[static_cast<std::size_t>(view)] = std::max(first, 0);
    row_last[static_cast<std::size_t>(view)] = std::min(last, frame.size - 1);
  }
}

std::pair<std::size_t, std::size_t> MapSet::drawn(int map) const {
  const auto v = static_cast<std::size_t>(frame.view_of(map));
  const std::size_t at = static_cast<std::size_t>(map) * view_pixels(), size = static_cast<std::size_t>(frame.size);
  if (row_first[v] > row_last[v]) return {at, at};
  return {at + static_cast<std::size_t>(row_first[v]) * size, at + static_cast<std::size_t>(row_last[v] + 1) * size};
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

// one ring of the layer in one view: every empty 8-neighbour of a `source` pixel joins ring `ring`
// with the values of the nearest such source (ring[] holds each pixel's ring, 0 for body pixels)
void grow_ring(MapSet& maps, int view, std::vector<std::uint8_t>& rings, int ring) {
  const int n = maps.frame.size;
  // front camera (even views): nearer is the larger coordinate; back camera (odd): the smaller
  const auto nearer = [view](float a, float b) { return view % 2 == 0 ? a > b : a < b; };
  const std::uint8_t source_mask = ring == 1 ? MapSet::kBody : MapSet::kSide;
  // the body is drawn only in the view's rows (limit_rows), so ring `ring`'s sources lie within ring - 1 of them
  const auto v = static_cast<std::size_t>(view);
  const int first = std::max(0, maps.row_first[v] - (ring - 1)), last = std::min(n - 1, maps.row_last[v] + (ring - 1));
  for (int row = first; row <= last; ++row) {
    for (int col = 0; col < n; ++col) {
      const std::size_t i = maps.index(view, col, row);
      if (maps.mask[i] != source_mask || (ring > 1 && rings[i] != ring - 1)) continue;
      // dressing 5.4: each empty 8-neighbour joins the layer with the nearest source pixel's values
      for (int dr = -1; dr <= 1; ++dr) {
        for (int dc = -1; dc <= 1; ++dc) {
          const int c = col + dc, r = row + dr;
          if (c < 0 || r < 0 || c >= n || r >= n) continue;
          const std::size_t j = maps.index(view, c, r);
          const bool take = maps.mask[j] == MapSet::kEmpty ||
                            (maps.mask[j] == MapSet::kSide && rings[j] == ring && nearer(maps.z[i], maps.z[j]));
          if (!take) continue;
          maps.copy_element(i, j);
          maps.mask[j] = MapSet::kSide;
          rings[j] = static_cast<std::uint8_t>(ring);
        }
      }
    }
  }
}

}  // namespace

void add_side_layer(MapSet& maps, int rings) {
  std::vector<std::uint8_t> ring_of(maps.mask.size(), 0);
  for (int view = 0; view < maps.frame.views; ++view)
    for (int ring = 1; ring <= std::clamp(rings, 1, 255); ++ring) grow_ring(maps, view, ring_of, ring);
}

int side_layer_rings(const ColliderOptions& options, Real pixel) {
  if (!options.side_layer) return 0;
  if (!(options.side_layer_mm > 0)) return 1;
  const double rings = std::ceil(1e-3 * double(options.side_layer_mm) / double(pixel) - 1e-6);
  return static_cast<int>(std::clamp(rings, 1.0, 255.0));
}

void depth_from_zbuffer(MapSet& maps) {
  const MapFrame& f = maps.frame;
  const float inf = std::numeric_limits<float>::infinity();
  for (int map = 0; map < f.map_count(); ++map) {
    const int view = f.view_of(map);
    const bool front = view % 2 == 0;
    // dressing Eq. 5: z-buffer to geometry space (along the view's axis for the extra views)
    const int axis = MapFrame::view_axis(view);
    const Real lo = f.plane_min(axis), hi = f.plane_max(axis);
    // the rows drawn (the others keep reset()'s empty values)
    const auto [begin, end] = maps.drawn(map);
    for (std::size_t i = begin; i < end; ++i) {
      const float zbuf = maps.z[i];
      // nothing drawn: the comparison of Eq. 9 must fail there
      if (zbuf >= 1.0f) {
        maps.z[i] = front ? -inf : inf;
        maps.mask[i] = MapSet::kEmpty;
        continue;
      }
      if (view < 2) {
        maps.z[i] = front ? f.z_max - zbuf * f.depth_range() : f.z_min + zbuf * f.depth_range();
      } else {
        maps.z[i] = front ? hi - zbuf * (hi - lo) : lo + zbuf * (hi - lo);
      }
      maps.mask[i] = MapSet::kBody;
    }
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
    throw std::invalid_argument("render_maps: unknown renderer '" + std::string(renderer) +
                                "' (gl, cpu; egl through make_egl_map_renderer())");
  }
  return render_maps(body, *r, options);
}

MapSet render_maps(const BodyFrame& body, MapRenderer& renderer, const ColliderOptions& options) {
  validate_body(body, "render_maps");
  MapSet maps;
  render_maps_into(body, renderer, options, maps);
  return maps;
}

void shape_maps(const BodyFrame& body, const ColliderOptions& options, MapSet& maps, const std::optional<Box3>& rows) {
  maps.set_shape(make_map_frame(bounding_box(body.positions), options), options.float_maps, body.moving,
                 options.max_speed);
  if (rows) maps.limit_rows(*rows);
}

void render_maps_into(const BodyFrame& body, MapRenderer& renderer, const ColliderOptions& options, MapSet& maps,
                      const std::optional<Box3>& rows) {
  maps.reset(make_map_frame(bounding_box(body.positions), options), options.float_maps, body.moving, options.max_speed);
  if (rows) maps.limit_rows(*rows);
  renderer.render(body, maps);
  if (const int rings = side_layer_rings(options, maps.frame.pixel)) add_side_layer(maps, rings);
}

}  // namespace clothbench
