#include "clothbench/collide_os/embree_collider.hpp"

#include <algorithm>
#include <system_error>
#include <thread>
#include <vector>

#include "clothbench/sim/timer.hpp"
#include "embree_scene.hpp"
#include "object_space.hpp"

namespace clothbench {

struct EmbreeCollider::Impl {
  ColliderOptions options;
  detail::EmbreeScene scene;
  BodyFrame body;        // the current frame (normals and velocities interpolated from it)
  PseudoNormals pseudo;  // sign of the depth; points into body.triangles
  Box3 box;              // bounding box of body.positions [m]
  bool has_body = false;
  CollideStats stats;

  explicit Impl(const ColliderOptions& o) : options(o), scene(std::max(1, o.threads)) {
    stats.threads = std::max(1, o.threads);
  }

  // answers points [begin, end); returns hits and degenerate points
  std::pair<std::int64_t, std::int64_t> answer(PointsView points, ContactsOut out, std::size_t begin,
                                               std::size_t end) const {
    std::int64_t hits = 0, degenerate = 0;
    const auto find = [this](const Vec3& p, Real radius) { return scene.closest(p, radius); };
    for (std::size_t i = begin; i < end; ++i) {
      const Vec3 p = points[i];
      if (!has_body || !p.allFinite()) {
        out[i] = Contact{};
        ++degenerate;
        continue;
      }
      out[i] = detail::answer_point(body, pseudo, box, p, options, find);
      hits += out[i].hit;
    }
    return {hits, degenerate};
  }
};

EmbreeCollider::EmbreeCollider(const ColliderOptions& options) : impl_(std::make_unique<Impl>(options)) {}

EmbreeCollider::~EmbreeCollider() = default;

void EmbreeCollider::set_body(const BodyFrame& body) {
  Stopwatch sw;
  validate_body(body, "embree collider");
  impl_->has_body = false;
  impl_->body = body;
  impl_->pseudo = PseudoNormals(impl_->body);
  impl_->box = bounding_box(impl_->body.positions);
  impl_->scene.build(impl_->body);
  impl_->has_body = true;
  impl_->stats.setup_ms += sw.ms();
}

void EmbreeCollider::update_body(const BodyFrame& body) {
  Stopwatch sw;
  detail::check_update(impl_->body, impl_->has_body, body, "embree collider");
  detail::adopt_frame(impl_->body, body);
  impl_->pseudo = PseudoNormals(impl_->body);
  impl_->box = bounding_box(impl_->body.positions);
  impl_->scene.refit(impl_->body.positions);
  impl_->stats.update_ms += sw.ms();
  ++impl_->stats.updates;
}

void EmbreeCollider::query(PointsView points, ContactsOut out) {
  Stopwatch sw;
  // contiguous chunks, one per worker; the calling thread takes the first
  const std::size_t workers = std::min<std::size_t>(impl_->stats.threads, std::max<std::size_t>(1, points.count / 256));
  const std::size_t chunk = (points.count + workers - 1) / std::max<std::size_t>(1, workers);
  std::vector<std::pair<std::int64_t, std::int64_t>> counts(workers);
  std::vector<std::thread> pool;
  for (std::size_t w = 1; w < workers; ++w) {
    const std::size_t begin = std::min(points.count, w * chunk), end = std::min(points.count, begin + chunk);
    try {
      pool.emplace_back([&, w, begin, end] { counts[w] = impl_->answer(points, out, begin, end); });
    } catch (const std::system_error&) {  // no thread to be had: answer this chunk here
      counts[w] = impl_->answer(points, out, begin, end);
    }
  }
  counts[0] = impl_->answer(points, out, 0, std::min(points.count, chunk));
  for (auto& t : pool) t.join();
  // cumulative counters
  for (const auto& [hits, degenerate] : counts) {
    impl_->stats.hits += hits;
    impl_->stats.degenerate += degenerate;
  }
  impl_->stats.points += static_cast<std::int64_t>(points.count);
  ++impl_->stats.queries;
  impl_->stats.query_ms += sw.ms();
}

CollideStats EmbreeCollider::stats() const { return impl_->stats; }

std::unique_ptr<Collider> make_embree_collider(const ColliderOptions& options) {
  return std::make_unique<EmbreeCollider>(options);
}

}  // namespace clothbench
