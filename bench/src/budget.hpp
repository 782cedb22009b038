#pragma once
// How long a run may take, up front: the iteration budget of every phase and the estimated simulation time
// (bench/src only).
#include <string>

#include "body_source.hpp"
#include "clothbench/bench/runner.hpp"
#include "clothbench/bench/scene.hpp"
#include "clothbench/sim/collider.hpp"
#include "clothbench/sim/simulator.hpp"

namespace clothbench::runner_detail {

// the iterations of `seconds` of simulated time at step `dt`, at most stop.max_iterations (when > 0)
long iteration_cap(const Scene& scene, double seconds, double dt);

// the animate phase's frames: `steps` iterations each, spread over `poses` body poses (collider updates), `lead_in`
// frames before the measured `frames`
struct AnimationPlan {
  long poses = 1, steps = 0, lead_in = 0, frames = 0;
  double pose_dt = 0;  // [s]
  // the steps of pose j (from 0) of a frame: its share of the frame's, each pose at least one
  long pose_steps(long j) const { return (j + 1) * steps / poses - j * steps / poses; }
};

// the plan at body.fps: ceil((1/fps)/dt) steps per frame, the body posed body.pose_fps / fps times a frame (no
// more often than the cloth steps); none for a body that does not move
AnimationPlan animation_plan(const Scene& scene, const BodySource& source, double dt);

// the most iterations each phase may take; the animate phase's lead-in runs with the dressing collider
struct Budget {
  long sew = 0, drape = 0, animate = 0, lead_in = 0, frames = 0, poses = 0;
  long total() const { return sew + drape + animate; }
  long dressing() const { return sew + drape + lead_in; }
};

Budget iteration_budget(const Scene& scene, const BodySource& source, const Simulator& sim);

// the run's simulation time [s], extrapolated from a few measured iterations: cloth simulation and queries per
// iteration (with the dressing collider up to the measured animation), plus one collider update per animation
// frame as long as its set-up. Sewing and draping: their budget, a bound (they end once sewn and settled, the shipped
// scenes at a tenth of it or less); the animation runs all its steps: a prediction
struct Estimate {
  double dressing_s = 0, animation_s = 0;
};

// `dresser` may be `collider` itself; `update_ms`: one collider update, taken as long as its set-up
Estimate estimate_seconds(const Simulator& sim, Collider& dresser, Collider& collider, int query_points,
                          const Budget& b, double update_ms);

// "estimate: the animation about 1 min 05 s (60 frames, 6660 steps); sewing and draping at most about 2 min 25 s
// (brute, 1234 queries/iteration, up to 7000 iterations; ...)" on stderr
void print_estimate(const std::string& label, const Scene& scene, const RunResult& r, const Budget& b,
                    const Estimate& e);

}  // namespace clothbench::runner_detail
