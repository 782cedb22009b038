// Sew, attach and drape: the garment dressed on the body standing still.
#include "dressing.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "budget.hpp"
#include "clothbench/sim/timer.hpp"

namespace clothbench::runner_detail {

namespace {

// an attached vertex bound far from the body holds the garment in mid-air (an attached edge that sewing did not
// bring to the body): warn
void warn_attached_far(const Scene& scene, const Simulator& sim) {
  constexpr Real kFar = 0.01f;  // [m]: a waistband rests on the body within a few millimetres
  const Points3& offsets = sim.attachment_offsets();
  long far = 0;
  Real farthest = 0;
  for (Eigen::Index i = 0; i < offsets.cols(); ++i) {
    const Real d = offsets.col(i).norm();
    farthest = std::max(farthest, d);
    far += d > kFar;
  }
  if (far)
    std::fprintf(stderr,
                 "clothbench: warning: %s: %ld of %ld attached vertices are bound more than %.0f mm from the body (the "
                 "farthest %.1f mm): they hold the garment in mid-air (check the pattern's attached edge and that "
                 "sewing brings it to the body)\n",
                 scene.path.c_str(), far, long(offsets.cols()), 1e3 * double(kFar), 1e3 * double(farthest));
}

// sqrt(2 E_kin / m): the cloth's RMS speed [m/s]
Real rms_speed(const Simulator& sim) {
  const double mass = sim.masses().sum();
  return mass > 0 ? Real(std::sqrt(2 * sim.kinetic_energy() / mass)) : 0;
}

}  // namespace

void sew(const RunContext& run, RunResult& r) {
  const Scene& scene = run.scene;
  Simulator& sim = run.sim;
  PhaseResult& p = r.sew;
  if (!scene.stop.sew || sim.mesh().seam_pairs.cols() == 0) return;
  sim.set_phase(Phase::kSew);
  PhaseClock clock{sim};
  const long cap = iteration_cap(scene, scene.stop.sew_max_s, sim.dt());
  const Real gap = scene.stop.sewn_gap_mm * 1e-3f;
  for (long i = 0; i < cap && !p.reached; ++i) {
    Stopwatch iteration;
    const bool alive = sim.step();
    if (run.options.trace) r.sew_iteration_ms.push_back(float(iteration.ms()));
    if (!alive) break;
    p.reached = sim.seam_pair_gap_max() <= gap || sim.sewn_fraction() >= 1;
    run.progress.report("sew: iteration %ld, seam pairs within %.1f mm", i + 1, 1e3 * double(sim.seam_pair_gap_max()));
  }
  clock.finish(p);
}

void attach(const RunContext& run) {
  if (run.sim.mesh().attached.empty()) return;
  run.sim.attach(run.frame);
  warn_attached_far(run.scene, run.sim);
}

void drape(const RunContext& run, RunResult& r) {
  const Scene& scene = run.scene;
  Simulator& sim = run.sim;
  PhaseResult& p = r.drape;
  sim.set_phase(Phase::kDrape);
  PhaseClock clock{sim};
  const long cap = iteration_cap(scene, scene.stop.drape_max_s, sim.dt());
  const long window = std::max(1L, static_cast<long>(std::ceil(scene.stop.settle_window_s / sim.dt())));
  // settled: `window` iterations in a row below the speed
  long calm = 0;
  for (long i = 0; i < cap && !p.reached; ++i) {
    if (!sim.step()) break;
    calm = rms_speed(sim) < scene.stop.settle_speed ? calm + 1 : 0;
    p.reached = calm >= window;
    run.progress.report("drape: iteration %ld, RMS speed %.3f m/s", i + 1, double(rms_speed(sim)));
  }
  clock.finish(p);
}

}  // namespace clothbench::runner_detail
