// The animate phase: body frames one after another, each one or more poses (a collider update each) and a few
// cloth steps a pose.
#include "animation.hpp"

#include <algorithm>
#include <optional>
#include <stdexcept>
#include <utility>

#include "budget.hpp"
#include "clothbench/bench/body_between_frames.hpp"
#include "clothbench/sim/timer.hpp"
#include "frame_ahead.hpp"
#include "measurement.hpp"

namespace clothbench::runner_detail {

namespace {

// the animate phase as it steps: the run, its plan, and how every frame is stepped
struct Animation {
  const RunContext& run;
  AnimationPlan plan;
  bool between = false;     // body.move_between_frames: each step sees the body at its own time
  Real region_margin = 0;   // collider.query_margin_mm: how far the cloth may move in a frame [m]
  bool alive = true;        // not diverged
  BodyFrame exact_scratch;  // the exact body of a frame, with a collision proxy
};

// one pass of frames (the lead-in's or the measured window's): its collider, answering between frames; its worker
// preparing the next frame (body.prepare_ahead, else null); where its frames' skinning time adds up [ms]
struct FramePass {
  BodyBetweenFrames& collider;
  FrameAhead* ahead;
  double& skinning_ms;
};

// what a measured frame spends outside the animation (the strain, the oracle, the caller's callback) [ms]
struct Outside {
  double wall_ms = 0, cpu_ms = 0;
};

// the queries of a frame come from the cloth's box grown by what it can move in `frames` frames (image space then
// draws only the map rows that spans)
void set_region(Collider& collider, const Simulator& sim, Real region_margin, int frames) {
  if (!(region_margin > 0)) return;
  Box3 region = bounding_box(sim.positions());
  region.min.array() -= Real(frames) * region_margin, region.max.array() += Real(frames) * region_margin;
  collider.set_query_region(region);
}

// one body pose at `t`: evaluate (timed), update the collider, move attachments, then `steps` steps spread over
// the pose's interval; with body.move_between_frames each step sees the body where it was at the step's time
// (BodyBetweenFrames), else the pose throughout. With a worker, a pose at t prepared during the last one is taken
// from it, and the pose at `t_next` (> 0) is prepared while this one's steps run (its map rows from the cloth's
// box now, grown by two poses' margin). Returns whether the cloth is still alive
bool advance_pose(Animation& a, FramePass& pass, double t, double t_next, long steps) {
  Simulator& sim = a.run.sim;
  BodyFrame& frame = a.run.frame;
  FrameAhead* const ahead = pass.ahead;
  // a frame prepared ahead is always the next one asked for (else the collider would make stale maps current)
  if (ahead && ahead->t >= 0 && ahead->t != t)
    throw std::logic_error("advance_pose: the pose prepared ahead is not next");
  // the body at t, from the worker or evaluated here, and the collider updated to it
  if (ahead && ahead->t == t) {
    std::swap(frame, ahead->frame);
    ahead->t = -1;
    pass.skinning_ms += ahead->skinning_ms;
    if (!ahead->prepared) set_region(pass.collider, sim, a.region_margin, 1);
  } else {
    Stopwatch skin;
    a.run.source.frame_into(frame, t);
    pass.skinning_ms += skin.ms();
    set_region(pass.collider, sim, a.region_margin, 1);
  }
  pass.collider.update_body(frame);
  if (ahead && t_next > 0) {
    set_region(pass.collider, sim, a.region_margin, 2);
    ahead->start(pass.collider, t_next);
  }
  // the cloth's steps through the pose's interval, each `tau` before the pose
  const bool attached = !sim.mesh().attached.empty();
  if (attached && !a.between) sim.follow_attachments(frame);
  bool alive = true;
  sim.set_collider(&pass.collider);
  for (long s = 0; s < steps && alive; ++s) {
    const Real tau = a.between ? Real(a.plan.pose_dt * double(steps - 1 - s) / double(steps)) : Real(0);
    pass.collider.set_time_before_pose(tau);
    // attached vertices start the step where the body had them a step before tau, and the step's dt v brings
    // them to tau (held once per frame, they would run a frame ahead of the body and jump back)
    if (attached && a.between) sim.follow_attachments(frame, tau + sim.dt());
    alive = sim.step();
  }
  if (ahead) ahead->wait();
  return alive;
}

// frame `f` (from 1) of `frames` after `t0`: its poses, the last at the frame's time, which it returns
double advance_frame(Animation& a, FramePass& pass, double t0, long f, long frames) {
  const long n = a.plan.poses, last = frames * n;
  const auto time = [&](long k) { return t0 + double(k) * a.plan.pose_dt; };
  for (long j = 0; j < n && a.alive; ++j) {
    const long k = (f - 1) * n + j + 1;
    a.alive = advance_pose(a, pass, time(k), k < last ? time(k + 1) : 0, a.plan.pose_steps(j));
  }
  return time(f * n);
}

// the lead-in: dress_at_s -> start_s with the dressing collider, not measured
void lead_in(Animation& a, FramePass& pass) {
  const long frames = a.plan.lead_in;
  for (long f = 1; f <= frames && a.alive; ++f) {
    advance_frame(a, pass, a.run.source.dress_time(), f, frames);
    a.run.progress.report("animate (lead-in): frame %ld of %ld", f, frames);
  }
}

// after measured frame `f` at `t`: the strain, with options.measure_frames the oracle, and the caller's callback
void look_at_frame(Animation& a, long f, double t, RunResult& r) {
  const RunContext& run = a.run;
  const StrainStats strain = run.sim.strain();
  note_frame_strain(run.sim, strain, t, r);
  const bool measured = run.options.measure_frames && a.alive;
  if (measured || run.options.on_frame) {  // the exact body only when something looks at it
    const BodyFrame& exact = run.source.exact(run.frame, a.exact_scratch);
    if (measured) measure_frame(exact, run.sim, strain, t, r);
    if (run.options.on_frame) run.options.on_frame(f, t, exact, run.sim);
  }
}

// the measured window: start_s -> end_s with the collider under test; the time spent looking at its frames goes
// to `outside`
void measured_window(Animation& a, FramePass& pass, Outside& outside, RunResult& r) {
  const long frames = a.plan.frames;
  for (long f = 1; f <= frames && a.alive; ++f) {
    const double t = advance_frame(a, pass, a.run.source.start(), f, frames);
    r.prepared_frames += pass.ahead && f < frames && pass.ahead->prepared;
    ++r.frames;
    Stopwatch wall;
    const double cpu = thread_cpu_ms();
    look_at_frame(a, f, t, r);
    outside.wall_ms += wall.ms();
    outside.cpu_ms += thread_cpu_ms() - cpu;
    a.run.progress.report("animate: frame %ld of %ld (t = %.2f s)", f, frames, t);
  }
}

}  // namespace

void animate(const RunContext& run, RunResult& r) {
  if (!run.source.moves()) return;
  const Scene& scene = run.scene;
  run.sim.set_phase(Phase::kAnimate);
  Animation a{run, animation_plan(scene, run.source, run.sim.dt()), scene.body.move_between_frames,
              Real(scene.collider_options.query_margin_mm * 1e-3)};
  r.steps_per_frame = double(a.plan.steps);
  // both passes' colliders answer between frames, the body body.skin_mm thicker; with body.prepare_ahead each pass
  // has its worker
  const Real tol = scene.collider_options.tol, skin = Real(scene.body.skin_mm * 1e-3);
  BodyBetweenFrames dresser_between(run.dresser, tol, skin), collider_between(run.collider, tol, skin);
  std::optional<FrameAhead> lead_ahead, ahead;
  if (scene.body.prepare_ahead) lead_ahead.emplace(run.source), ahead.emplace(run.source);
  double unmeasured_ms = 0;  // the lead-in's skinning time: not the measured animation's
  FramePass lead{dresser_between, lead_ahead ? &*lead_ahead : nullptr, unmeasured_ms};
  lead_in(a, lead);
  // the collider under test takes the body where the lead-in left it; its window sets the pace from here
  run.collider.update_body(run.frame);
  r.window_seam_gap_mm = 1e3 * double(run.sim.seam_pair_gap_max());
  run.progress.plan(a.plan.frames * a.plan.steps);
  PhaseClock clock{run.sim};
  const CollideStats before = run.collider.stats();
  FramePass window{collider_between, ahead ? &*ahead : nullptr, r.skinning_ms};
  Outside outside;
  measured_window(a, window, outside, r);
  run.sim.set_collider(&run.collider);  // the wrappers end here
  // the window's phase result: the collider's share, less the time spent looking at frames
  r.animate.reached = a.alive && r.frames == a.plan.frames;
  const CollideStats after = run.collider.stats();
  r.collider_update_ms = after.update_ms - before.update_ms;
  r.collider_updates = long(after.updates - before.updates);
  r.collider_queries = after.queries - before.queries;
  r.collider_query_ms = after.query_ms - before.query_ms;
  clock.finish(r.animate);
  r.animate.wall_ms -= outside.wall_ms;
  r.animate.cpu_ms -= outside.cpu_ms;
}

}  // namespace clothbench::runner_detail
