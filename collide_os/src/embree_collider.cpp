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
  detail::Coherence coherence;  // per-point bounds between queries (options.coherent)
  bool has_body = false;
  CollideStats stats;

  explicit Impl(const ColliderOptions& o) : options(o), scene(std::max(1, o.threads)) {
    stats.threads = std::max(1, o.threads);
  }

  // answers points [begin, end) with their memory (nullptr: from scratch); one worker's counts
  CollideStats answer(PointsView points, ContactsOut out, detail::PointMemory* memory, std::size_t begin,
                      std::size_t end) const {
    CollideStats n;
    const auto find = [this](const Vec3& p, Real radius) { return scene.closest(p, radius); };
    detail::answer_points(PointsView(points.xyz + 3 * begin, end - begin), ContactsOut{out.data + begin, end - begin},
                          has_body, n, [&](std::size_t i, const Vec3& p) {
                            return detail::answer_point(body, pseudo, box, p, options, find,
                                                        memory ? memory + begin + i : nullptr, coherence.body_moved(),
                                                        n.searches);
                          });
    return n;
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
  impl_->coherence.forget();
  impl_->scene.build(impl_->body, impl_->body.moving);
  impl_->has_body = true;
  impl_->stats.setup_ms += sw.ms();
}

void EmbreeCollider::update_body(const BodyFrame& body) {
  Stopwatch sw;
  detail::check_update(impl_->body, impl_->has_body, body, "embree collider");
  impl_->coherence.body_moves(impl_->body.positions, body.positions);
  detail::adopt_frame(impl_->body, body);
  impl_->pseudo = PseudoNormals(impl_->body);
  impl_->box = bounding_box(impl_->body.positions);
  impl_->scene.refit(impl_->body);
  impl_->stats.update_ms += sw.ms();
  ++impl_->stats.updates;
}

void EmbreeCollider::query(PointsView points, ContactsOut out) {
  Stopwatch sw;
  // contiguous chunks, one per worker; the calling thread takes the first
  const std::size_t workers = std::min<std::size_t>(impl_->stats.threads, std::max<std::size_t>(1, points.count / 256));
  const std::size_t chunk = (points.count + workers - 1) / std::max<std::size_t>(1, workers);
  detail::PointMemory* memory =
      impl_->options.coherent && impl_->has_body ? impl_->coherence.memory(points.xyz, points.count) : nullptr;
  std::vector<CollideStats> counts(workers);
  std::vector<std::thread> pool;
  for (std::size_t w = 1; w < workers; ++w) {
    const std::size_t begin = std::min(points.count, w * chunk), end = std::min(points.count, begin + chunk);
    try {
      pool.emplace_back([&, w, begin, end] { counts[w] = impl_->answer(points, out, memory, begin, end); });
    } catch (const std::system_error&) {  // no thread to be had: answer this chunk here
      counts[w] = impl_->answer(points, out, memory, begin, end);
    }
  }
  counts[0] = impl_->answer(points, out, memory, 0, std::min(points.count, chunk));
  for (auto& t : pool) t.join();
  // cumulative counters
  for (const CollideStats& n : counts) {
    impl_->stats.hits += n.hits;
    impl_->stats.degenerate += n.degenerate;
    impl_->stats.searches += n.searches;
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
