#pragma once
// Progress lines on stderr and the phases' clocks (bench/src only: the runner's phases share them).
#include <cstdio>
#include <string>

#include "clothbench/bench/runner.hpp"
#include "clothbench/sim/simulator.hpp"
#include "clothbench/sim/timer.hpp"

namespace clothbench::runner_detail {

// progress on stderr, at most once a second, only after the first second, with an ETA: the time
// per iteration so far times the iterations left of the plan (an upper bound: phases end early
// when sewn or settled)
class Progress {
 public:
  Progress(bool on, std::string label, const Simulator& sim);
  // from now on, at most `iterations` more; the ETA takes the rate from here (a phase's iterations can cost far
  // more than the last one's: an object-space collider after an image-space dresser)
  void plan(long iterations);
  // one line, printf-style, when a second has passed since the last
  template <class... A>
  void report(const char* format, A... args) {
    if (!on_ || clock_.ms() < next_ms_) return;
    next_ms_ = clock_.ms() + 1000;
    std::fprintf(stderr, "  [%s %.0f s, ETA <= %s] ", label_.c_str(), clock_.ms() / 1e3, eta().c_str());
    std::fprintf(stderr, format, args...);
    std::fputc('\n', stderr);
  }

 private:
  std::string eta() const;

  bool on_;
  std::string label_;
  const Simulator& sim_;
  long start_, end_ = 0;
  Stopwatch clock_, phase_;
  double next_ms_ = 1000;
};

// the simulator's cumulative timings as a phase's share
struct PhaseClock {
  const Simulator& sim;
  SimTimings start = sim.timings();
  Stopwatch wall;
  double cpu_start = thread_cpu_ms();
  void finish(PhaseResult& r) const;
};

}  // namespace clothbench::runner_detail
