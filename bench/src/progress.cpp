// Progress lines with an ETA, the phases' clocks, and durations for people.
#include "progress.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace clothbench {

std::string format_duration(double seconds) {
  if (!std::isfinite(seconds)) return "?";
  if (seconds < 0.95) return "under 1 s";
  const long s = std::lround(seconds);
  char buf[48];
  if (s < 60) {
    std::snprintf(buf, sizeof buf, "%ld s", s);
  } else if (s < 3600) {
    std::snprintf(buf, sizeof buf, "%ld min %ld s", s / 60, s % 60);
  } else {
    std::snprintf(buf, sizeof buf, "%ld h %02ld min", s / 3600, s / 60 % 60);
  }
  return buf;
}

namespace runner_detail {

Progress::Progress(bool on, std::string label, const Simulator& sim)
    : on_(on), label_(std::move(label)), sim_(sim), start_(sim.timings().iterations) {}

void Progress::plan(long iterations) {
  start_ = sim_.timings().iterations;
  end_ = start_ + iterations;
  phase_.restart();
}

std::string Progress::eta() const {
  const long now = sim_.timings().iterations, done = now - start_;
  if (done <= 0) return "?";
  return format_duration(phase_.ms() / 1e3 / double(done) * double(std::max(0L, end_ - now)));
}

void PhaseClock::finish(PhaseResult& r) const {
  r.iterations = sim.timings().iterations - start.iterations;
  r.cdr_ms = sim.timings().cdr_ms - start.cdr_ms;
  r.cs_ms = sim.timings().cs_ms - start.cs_ms;
  r.limit_ms = sim.timings().limit_ms - start.limit_ms;
  r.cloth_ms = sim.timings().cloth_ms - start.cloth_ms;
  r.wall_ms = wall.ms();
  r.cpu_ms = thread_cpu_ms() - cpu_start;
}

}  // namespace runner_detail

}  // namespace clothbench
