// Sew, attach and drape: the garment dressed on the body standing still.
#include "dressing.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "budget.hpp"
#include "clothbench/sim/timer.hpp"

namespace clothbench::runner_detail {

namespace {

// an attached vertex is bound only within this distance of the body [m]: a waistband rests on the body within a few
// millimetres, and one bound farther off would hold the garment in mid-air
constexpr Real kAttachReach = 0.01f;

// bind the attached vertices within reach (Durupinar 3.2); say how many stood farther off and were left free
void attach(const RunContext& run) {
  const std::size_t attached = run.sim.mesh().attached.size();
  if (!attached) return;
  const std::size_t bound = static_cast<std::size_t>(run.sim.attach(run.frame, kAttachReach));
  if (bound < attached)
    std::fprintf(stderr,
                 "clothbench: note: %s: %zu of %zu attached vertices stood more than %.0f mm off the body once "
                 "dressed and were left free (a waistband looser than the body there)\n",
                 run.scene.path.c_str(), attached - bound, attached, 1e3 * double(kAttachReach));
}

// stop.settle_window_s in iterations
long window(const Scene& scene, const Simulator& sim) {
  return std::max(1L, static_cast<long>(std::ceil(scene.stop.settle_window_s / sim.dt())));
}

// a sewing that has stopped closing: the widest seam pair gap has not narrowed by kNarrower for `window` iterations
// (a pair the limit holds a few millimetres apart, where a sleeve's corners meet the front's and the back's under
// the arm, stayed so to the end of the sew phase's time); with every pair within twice solver.merge_distance, they
// are then merged (Simulator::merge_stalled_seams)
struct Stall {
  static constexpr Real kNarrower = 1e-4f;  // [m]
  long window, since = 0;
  Real least = std::numeric_limits<Real>::infinity();
  bool stalled(Real widest) {
    if (widest < least - kNarrower) least = widest, since = 0;
    if (++since <= window) return false;
    since = 0;
    return true;
  }
};

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
  Stall stall{window(scene, sim)};
  for (long i = 0; i < cap && !p.reached; ++i) {
    Stopwatch iteration;
    const bool alive = sim.step();
    if (run.options.trace) r.sew_iteration_ms.push_back(float(iteration.ms()));
    if (!alive) break;
    Real widest = sim.seam_pair_gap_max();
    if (stall.stalled(widest) && sim.merge_stalled_seams() > 0) widest = sim.seam_pair_gap_max();
    p.reached = widest <= gap || sim.sewn_fraction() >= 1;
    run.progress.report("sew: iteration %ld, seam pairs within %.1f mm", i + 1, 1e3 * double(widest));
  }
  clock.finish(p);
}

void drape(const RunContext& run, RunResult& r) {
  const Scene& scene = run.scene;
  Simulator& sim = run.sim;
  PhaseResult& p = r.drape;
  sim.set_phase(Phase::kDrape);
  PhaseClock clock{sim};
  const long cap = iteration_cap(scene, scene.stop.drape_max_s, sim.dt());
  const long settle = window(scene, sim);
  // settled: `settle` iterations in a row below the speed
  long calm = 0;
  // the attachments bind after the first iteration: the seams' pull leaves springs stretched past the limit at the
  // end of sewing, which one step of the limit without it relaxes (bound before, a waistband's would stay so)
  bool bound = false;
  for (long i = 0; i < cap && !p.reached; ++i) {
    if (!sim.step()) break;
    if (!bound) attach(run), bound = true;
    calm = rms_speed(sim) < scene.stop.settle_speed ? calm + 1 : 0;
    p.reached = calm >= settle;
    run.progress.report("drape: iteration %ld, RMS speed %.3f m/s", i + 1, double(rms_speed(sim)));
  }
  if (!bound && !sim.divergence()) attach(run);
  clock.finish(p);
}

}  // namespace clothbench::runner_detail
