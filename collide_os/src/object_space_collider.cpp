#include "clothbench/collide_os/object_space_collider.hpp"

#include <algorithm>
#include <system_error>
#include <thread>
#include <vector>

#include "clothbench/sim/timer.hpp"
#include "object_space.hpp"

namespace clothbench {

namespace {

// takes a checked frame's motion (positions, normals, velocities, time) into `current`; the
// triangles are the same by detail::check_update
void adopt_frame(BodyFrame& current, const BodyFrame& body) {
  current.positions = body.positions;
  current.normals = body.normals;
  current.velocities = body.velocities;
  current.time_s = body.time_s;
  current.moving = body.moving;
}

}  // namespace

ObjectSpaceCollider::ObjectSpaceCollider(const ColliderOptions& options, const Traits& traits)
    : options_(options),
      name_(traits.name),
      what_(name_ + " collider"),
      keeps_(traits.keeps),
      parallel_queries_(traits.parallel_queries),
      coherence_(std::make_unique<detail::Coherence>()) {
  stats_.threads = traits.threads;
}

ObjectSpaceCollider::~ObjectSpaceCollider() = default;

void ObjectSpaceCollider::check(const BodyFrame& body) const { (void)body; }

ClosestPoint ObjectSpaceCollider::nearest(const Vec3& p, Real radius) const {
  (void)p, (void)radius;
  return {};
}

Contact ObjectSpaceCollider::answer(const Vec3& p, detail::PointMemory* memory, std::int64_t& searches) const {
  const auto find = [this](const Vec3& q, Real radius) { return nearest(q, radius); };
  return detail::answer_point(body_, pseudo_, box_, p, options_, find, memory, coherence_->body_moved(), searches);
}

void ObjectSpaceCollider::fit_frame_state() {
  if (keeps_ == Keeps::kFrame) return;
  pseudo_ = PseudoNormals(body_);
  box_ = bounding_box(body_.positions);
}

void ObjectSpaceCollider::set_body(const BodyFrame& body) {
  Stopwatch sw;
  validate_body(body, what_);
  check(body);
  // no body until the backend's structure is built: a throw leaves queries degenerate
  has_body_ = false;
  body_ = body;
  fit_frame_state();
  coherence_->forget();
  build(body_);
  has_body_ = true;
  stats_.setup_ms += sw.ms();
}

void ObjectSpaceCollider::update_body(const BodyFrame& body) {
  Stopwatch sw;
  detail::check_update(body_, has_body_, body, what_);
  check(body);
  if (keeps_ == Keeps::kPointBounds) coherence_->body_moves(body_.positions, body.positions);
  adopt_frame(body_, body);
  fit_frame_state();
  refit(body_);
  stats_.update_ms += sw.ms();
  ++stats_.updates;
}

CollideStats ObjectSpaceCollider::answer_chunk(PointsView points, ContactsOut out, detail::PointMemory* memory) const {
  CollideStats n;
  for (std::size_t i = 0; i < points.count; ++i) {
    const Vec3 p = points[i];
    if (!has_body_ || !p.allFinite()) {
      out[i] = Contact{};
      ++n.degenerate;
      continue;
    }
    out[i] = answer(p, memory ? memory + i : nullptr, n.searches);
    n.hits += out[i].hit;
  }
  return n;
}

void ObjectSpaceCollider::query(PointsView points, ContactsOut out) {
  Stopwatch sw;
  detail::PointMemory* memory = keeps_ == Keeps::kPointBounds && options_.coherent && has_body_
                                    ? coherence_->memory(points.xyz, points.count)
                                    : nullptr;
  // contiguous chunks, one per worker; the calling thread takes the first
  const std::size_t workers =
      parallel_queries_ ? std::min<std::size_t>(stats_.threads, std::max<std::size_t>(1, points.count / 256)) : 1;
  const std::size_t chunk = (points.count + workers - 1) / workers;
  std::vector<CollideStats> counts(workers);
  const auto answer_worker = [&](std::size_t w) {
    const std::size_t begin = std::min(points.count, w * chunk), end = std::min(points.count, begin + chunk);
    counts[w] = answer_chunk(PointsView(points.xyz + 3 * begin, end - begin),
                             ContactsOut{out.data + begin, end - begin}, memory ? memory + begin : nullptr);
  };
  std::vector<std::thread> pool;
  for (std::size_t w = 1; w < workers; ++w) {
    try {
      pool.emplace_back(answer_worker, w);
    } catch (const std::system_error&) {  // no thread to be had: answer this chunk here
      answer_worker(w);
    }
  }
  answer_worker(0);
  for (std::thread& t : pool) t.join();
  // cumulative counters
  for (const CollideStats& n : counts) {
    stats_.hits += n.hits;
    stats_.degenerate += n.degenerate;
    stats_.searches += n.searches;
  }
  stats_.points += static_cast<std::int64_t>(points.count);
  ++stats_.queries;
  stats_.query_ms += sw.ms();
}

}  // namespace clothbench
