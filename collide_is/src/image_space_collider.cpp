#include "clothbench/collide_is/image_space_collider.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "clothbench/sim/timer.hpp"

namespace clothbench {

ImageSpaceCollider::ImageSpaceCollider(std::unique_ptr<MapRenderer> renderer, const ColliderOptions& options,
                                       double setup_ms)
    : renderer_(std::move(renderer)), options_(options) {
  if (!renderer_) throw std::invalid_argument("ImageSpaceCollider: no renderer");
  if (!(options.max_speed > 0)) throw std::invalid_argument("ImageSpaceCollider: max_speed must be > 0");
  stats_.setup_ms = setup_ms;
}

std::string_view ImageSpaceCollider::name() const { return renderer_->name() == "gl" ? "is-gl" : "is-cpu"; }

void ImageSpaceCollider::render(const BodyFrame& body) {
  // cameras on this frame's bounding box, velocity maps only for moving bodies
  maps_.reset(make_map_frame(bounding_box(body.positions), options_), options_.float_maps, body.moving,
              options_.max_speed);
  renderer_->render(body, maps_);
  if (options_.side_layer) add_side_layer(maps_);
}

void ImageSpaceCollider::set_body(const BodyFrame& body) {
  validate_body(body, std::string(name()) + " set_body");
  Stopwatch watch;
  render(body);
  vertex_count_ = body.vertex_count();
  stats_.setup_ms += watch.ms();
}

void ImageSpaceCollider::update_body(const BodyFrame& body) {
  if (vertex_count_ == 0) throw std::logic_error(std::string(name()) + ": update_body before set_body");
  if (body.vertex_count() != vertex_count_)
    throw std::invalid_argument(std::string(name()) + ": update_body with a different vertex count");
  Stopwatch watch;
  render(body);
  stats_.update_ms += watch.ms();
  ++stats_.updates;
}

void ImageSpaceCollider::query(PointsView points, ContactsOut out) {
  Stopwatch watch;
  const MapFrame& f = maps_.frame;
  const Real tol = options_.tol;
  const int n = f.size;
  const std::size_t back = maps_.view_pixels();
  std::int64_t hits = 0, degenerate = 0;
  for (std::size_t p = 0; p < points.count; ++p) {
    Contact& c = out[p];
    c = Contact{};
    const Real x = points.xyz[3 * p], y = points.xyz[3 * p + 1], z = points.xyz[3 * p + 2];
    if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z)) {
      ++degenerate;
      c.depth = std::numeric_limits<float>::infinity();
      continue;
    }
    // world -> map (dressing Eq. 8): front column u, back column size - 1 - u
    const Real u = f.front_u(x), v = f.map_v(y);
    if (!(u >= 0 && v >= 0 && u < n && v < n)) {
      c.depth = std::numeric_limits<float>::infinity();
      continue;
    }
    const int col = static_cast<int>(u), row = static_cast<int>(v);
    const std::size_t fi = static_cast<std::size_t>(row) * n + col;
    const std::size_t bi = back + static_cast<std::size_t>(row) * n + (n - 1 - col);
    // between the front and back surfaces within tol (dressing Eq. 5/9, walking Eq. 12)
    const Real d_front = z - maps_.z[fi], d_back = maps_.z[bi] - z;
    c.depth = std::max(d_front, d_back);
    if (!(c.depth < tol)) continue;
    // the nearer surface's map answers normal and velocity
    const std::size_t i = d_front >= d_back ? fi : bi;
    if (maps_.mask[i] == MapSet::kSide) c.depth = std::max(c.depth, 0.0f);
    c.hit = true;
    c.normal = maps_.normal_at(i);
    c.body_velocity = maps_.velocity_at(i);
    ++hits;
  }
  stats_.query_ms += watch.ms();
  ++stats_.queries;
  stats_.points += static_cast<std::int64_t>(points.count);
  stats_.hits += hits;
  stats_.degenerate += degenerate;
}

std::unique_ptr<Collider> make_is_gl_collider(const ColliderOptions& options) {
  // context creation and shader compilation count as set-up
  Stopwatch watch;
  auto renderer = make_gl_map_renderer();
  return std::make_unique<ImageSpaceCollider>(std::move(renderer), options, watch.ms());
}

std::unique_ptr<Collider> make_is_cpu_collider(const ColliderOptions& options) {
  return std::make_unique<ImageSpaceCollider>(make_cpu_map_renderer(), options, 0.0);
}

}  // namespace clothbench
