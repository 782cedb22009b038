#pragma once
// The animate phase of a run (bench/src only).
#include "clothbench/bench/runner.hpp"
#include "run_context.hpp"

namespace clothbench::runner_detail {

// the animate phase of a moving body, at body.fps with ceil((1/fps)/dt) cloth steps per frame: the lead-in
// (dress_at_s -> start_s, with the dressing collider, not measured), then the measured window (start_s -> end_s,
// with the collider under test: r.animate, the frames, the collider's updates and queries; with
// options.measure_frames the oracle at every frame). Nothing for a body that does not move
void animate(const RunContext& run, RunResult& r);

}  // namespace clothbench::runner_detail
