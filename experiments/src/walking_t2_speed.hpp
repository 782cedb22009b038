#pragma once
// walking-t2's speed: the rows' frame rates and what they miss, the page's summary and its Speed paragraph.
// experiments/src only.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "clothbench/bench/report.hpp"
#include "clothbench/experiments/paper_figures.hpp"

namespace clothbench {

// what a run misses of inside, depth and crossings at every frame, the seam gap, and strain `with_strain` ("a; b"),
// empty when it meets them
std::string accuracy_misses(const RunResult& r, bool with_strain = false);

// a run's animation per frame: wall time [s] and its parts [ms] (skinning, maps/refit, cloth = CD&R + CS)
struct FrameTimes {
  double s, skinning_ms, maps_ms, cloth_ms;
};
FrameTimes frame_times(const RunResult& r);

// the frame rates of a configuration's runs: a headline rests on kVerdictRuns of them
struct FrameRates {
  std::vector<double> fps;  // one per run
  // "median of 5 runs, 13.9-14.8" or "one run"
  std::string text() const;
};

// one of the dress's prepared-ahead runs at the papers' clock: how fast, and what it misses (empty: nothing)
struct SpeedRun {
  std::string variant, clip;
  double fps;
  std::string misses;
  FrameTimes times;
  double strain_pct;   // the largest strain at any frame [%]
  bool strain_misses;  // over threshold + 1 % at some frame
  FrameRates rates;    // fps is their median
};

// the page's opening lines: the paper's frame rates, our fastest row within every limit, the rows that meet them
std::vector<std::string> speed_summary(const std::vector<SpeedRun>& frontier,
                                       const std::vector<std::pair<std::string, std::pair<int, int>>>& meeting,
                                       const std::optional<SpeedRun>& fastest);

// the benchmark figure (the dress with sleeves, is-cpu, at the papers' clock, prepared ahead) and what bounds it
std::string speed_figure(const RunResult& r, const paper::WalkingT2Row& p, const std::vector<SpeedRun>& frontier);

}  // namespace clothbench
