// The iteration budget of a run's phases and the up-front estimate of its simulation time.
#include "budget.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "clothbench/sim/timer.hpp"

namespace clothbench::runner_detail {

namespace {

// cloth simulation per iteration [ms]: a few iterations of a copy of the simulator without
// collisions (the run never sees them)
double cloth_ms_per_iteration(const Simulator& sim, Phase phase) {
  Simulator copy = sim;
  copy.set_collider(nullptr);
  copy.set_phase(phase);
  Stopwatch clock;
  long n = 0;
  bool alive = true;
  do {
    alive = copy.step();
    ++n;
  } while (alive && n < 3 && clock.ms() < 20);
  return clock.ms() / double(n);
}

// collision detection per query point [ms]: batches of the cloth's points (spread over it) until
// 50 ms or 256 points; colliders answer queries without keeping state (only their stats count them)
double query_ms_per_point(const Points3& cloth, Collider& collider) {
  const Eigen::Index count = std::min<Eigen::Index>(256, cloth.cols()),
                     stride = cloth.cols() / std::max<Eigen::Index>(1, count);
  Points3 sample(3, count);
  for (Eigen::Index i = 0; i < count; ++i) sample.col(i) = cloth.col(i * stride);
  std::vector<Contact> contacts(static_cast<std::size_t>(count));
  Stopwatch clock;
  Eigen::Index done = 0;
  while (done < count && (done == 0 || clock.ms() < 50)) {
    const Eigen::Index batch = std::min<Eigen::Index>(16, count - done);
    collider.query(PointsView(sample.data() + 3 * done, static_cast<std::size_t>(batch)),
                   {contacts.data() + done, static_cast<std::size_t>(batch)});
    done += batch;
  }
  return done > 0 ? clock.ms() / double(done) : 0;
}

}  // namespace

long iteration_cap(const Scene& scene, double seconds, double dt) {
  const long by_time = static_cast<long>(std::ceil(seconds / dt));
  return scene.stop.max_iterations > 0 ? std::min(by_time, scene.stop.max_iterations) : by_time;
}

AnimationPlan animation_plan(const Scene& scene, const BodySource& source, double dt) {
  if (!source.moves()) return {};
  const double frame_dt = 1.0 / scene.body.fps;
  AnimationPlan p;
  p.steps = std::max(1L, static_cast<long>(std::ceil(frame_dt / dt)));
  p.poses = std::min(poses_per_frame(scene.body), p.steps);
  p.pose_dt = frame_dt / double(p.poses);
  p.lead_in = static_cast<long>(std::floor((source.start() - source.dress_time()) / frame_dt + 1e-9));
  p.frames = static_cast<long>(std::floor((source.end() - source.start()) / frame_dt + 1e-9));
  return p;
}

Budget iteration_budget(const Scene& scene, const BodySource& source, const Simulator& sim) {
  Budget b;
  if (scene.stop.sew && sim.mesh().seam_pairs.cols() > 0) b.sew = iteration_cap(scene, scene.stop.sew_max_s, sim.dt());
  b.drape = iteration_cap(scene, scene.stop.drape_max_s, sim.dt());
  const AnimationPlan a = animation_plan(scene, source, sim.dt());
  b.frames = a.lead_in + a.frames;
  b.poses = b.frames * a.poses;
  b.animate = b.frames * a.steps;
  b.lead_in = a.lead_in * a.steps;
  return b;
}

Estimate estimate_seconds(const Simulator& sim, Collider& dresser, Collider& collider, int query_points,
                          const Budget& b, double update_ms) {
  // per iteration: the cloth, the dresser's queries and (when another collider measures) the measured queries
  const double cloth_ms = cloth_ms_per_iteration(sim, b.sew > 0 ? Phase::kSew : Phase::kDrape);
  const double dress_ms = query_ms_per_point(sim.positions(), dresser) * query_points;
  const double measure_ms = &collider == &dresser || b.total() == b.dressing()
                                ? dress_ms
                                : query_ms_per_point(sim.positions(), collider) * query_points;
  // times the budget's iterations, the animation's frames each one collider update
  Estimate e;
  e.dressing_s = (cloth_ms + dress_ms) * double(b.sew + b.drape) / 1e3;
  e.animation_s = (cloth_ms * double(b.animate) + dress_ms * double(b.lead_in) +
                   measure_ms * double(b.animate - b.lead_in) + update_ms * double(b.poses)) /
                  1e3;
  return e;
}

void print_estimate(const std::string& label, const Scene& scene, const RunResult& r, const Budget& b,
                    const Estimate& e) {
  std::string animation;
  if (b.animate > 0)
    animation = "the animation about " + format_duration(e.animation_s) + " (" + std::to_string(b.frames) +
                " frames, " + std::to_string(b.animate) + " steps); ";
  std::fprintf(stderr,
               "  [%s] estimate: %ssewing and draping at most about %s (%s, %d queries/iteration, up to %ld "
               "iterations; they end once sewn and settled, often far sooner)\n",
               label.c_str(), animation.c_str(), format_duration(e.dressing_s).c_str(), scene.collider.c_str(),
               r.query_points, b.sew + b.drape);
}

}  // namespace clothbench::runner_detail
