#pragma once
// What the phases of one run share (bench/src only): runner.cpp wires it, dressing.cpp and animation.cpp step it.
#include "body_source.hpp"
#include "clothbench/bench/runner.hpp"
#include "clothbench/bench/scene.hpp"
#include "clothbench/sim/collider.hpp"
#include "clothbench/sim/simulator.hpp"
#include "progress.hpp"

namespace clothbench::runner_detail {

// one run's scene, options, body, colliders, simulator and progress lines, as the phases see them
struct RunContext {
  const Scene& scene;
  const RunOptions& options;
  const BodySource& source;
  BodyFrame& frame;    // the body as the colliders last saw it (the collision proxy's, with body.collision_triangles)
  Collider& collider;  // the collider under test: the measured animation's
  Collider& dresser;   // sews, drapes and runs the lead-in: collider.dress_with's, else `collider` itself
  Simulator& sim;
  Progress& progress;
};

}  // namespace clothbench::runner_detail
