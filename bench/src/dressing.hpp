#pragma once
// The dressing phases of a run (bench/src only): sew (seam forces, no gravity), drape (gravity) until settled, the
// attachments bound once it has begun.
#include "clothbench/bench/runner.hpp"
#include "run_context.hpp"

namespace clothbench::runner_detail {

// sew until every seam pair is within stop.sewn_gap_mm or merged (r.sew), at most stop.sew_max_s of simulated
// time; nothing without seams or with stop.sew off. With options.trace every iteration's wall time is kept
void sew(const RunContext& run, RunResult& r);

// drape until the RMS cloth speed stays below stop.settle_speed for stop.settle_window_s (r.drape), at most
// stop.drape_max_s of simulated time; the attachments (Durupinar 3.2) bind after its first iteration, those that
// sewing brought to the body
void drape(const RunContext& run, RunResult& r);

}  // namespace clothbench::runner_detail
