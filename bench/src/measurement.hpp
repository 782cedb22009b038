#pragma once
// The exact oracle's measurements of a run (bench/src only): the collision proxy's deviation, every animation
// frame, and the end state, with where the worst spring, seam pair and vertex are.
#include "clothbench/bench/runner.hpp"
#include "clothbench/bench/scene.hpp"
#include "clothbench/sim/simulator.hpp"

namespace clothbench::runner_detail {

// the largest distance of an exact body vertex from the collision proxy's surface [mm]
double proxy_deviation_mm(const BodyFrame& proxy, const BodyFrame& exact);

// the strain at one animation frame: r.animate_strain_max, and where and when (r.animate_strain_max_where) when
// this frame's is the largest yet
void note_frame_strain(const Simulator& sim, const StrainStats& strain, double t, RunResult& r);

// the oracle at one animation frame (its strain beside): a sample in r.frame_samples, and where the deepest vertex
// is (r.depth_max_where) when this frame is the deepest yet
void measure_frame(const BodyFrame& frame, const Simulator& sim, const StrainStats& strain, double t, RunResult& r);

// accuracy of the end state against the exact body r.final_body (vertices, and quad midpoints with face queries;
// crossings of the structural springs; penetrating faces), the seam gap, the strain and the kinetic energy
void measure(const Scene& scene, const Simulator& sim, RunResult& r);

}  // namespace clothbench::runner_detail
