#pragma once
/// Results as DESIGN.md's "Result fields": Google Benchmark's JSON layout (context + benchmarks[])
/// with speed and accuracy counters in every row; machine context; atomic file writes.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "clothbench/bench/runner.hpp"
#include "clothbench/io/text_file.hpp"  // write_text_file, for every report

namespace clothbench {

/// The source tree's short git SHA, with "-dirty" for uncommitted source changes; "unknown"
/// outside a git checkout.
std::string git_sha();

/// The machine and build: date, host, CPU model, cores, compiler, flags, build type, git SHA.
nlohmann::json machine_context();

/// The accuracy limits a drape must meet: `minimal` searches the smallest model meeting them, `run`
/// prints its verdict against them. Crossings are the holes of dressing section 7 ("a smaller
/// number [of vertices] produces holes on the garments").
struct AccuracyLimits {
  double inside_pct = 0.5;      ///< cloth points inside the body [%]
  double depth_mm = 5;          ///< deepest point inside the body [mm]
  double crossings_pct = 1;     ///< structural springs crossing the body [%]
  double seam_gap_mm = 2;       ///< widest opening along the seams (Simulator::widest_seam_gap) [mm]
  double strain_excess = 0.01;  ///< strain above the super-elasticity threshold (runs with a limit)
};
inline constexpr AccuracyLimits kAccuracyLimits{};

/// What a run misses of kAccuracyLimits, e.g. "inside 6.1 % > 0.5 %"; {"diverged"} for a diverged
/// run; empty when it meets them. An animated run counts its worst measured frame too (inside, depth and
/// crossings under RunOptions::measure_frames, strain at every frame). Strain counts when `with_strain` and the run had a limit
/// (RunResult::strain_threshold > 0).
std::vector<std::string> limit_misses(const RunResult& r, bool with_strain = true);
/// The limits that apply to the run, e.g. "inside <= 0.5 %, depth <= 5 mm, ...".
std::string limits_text(const RunResult& r, bool with_strain = true);
/// A table cell: "yes" when the run meets the limits, else "no: " and what it misses.
std::string limits_cell(const RunResult& r, bool with_strain = true);

/// One benchmarks[] row named `name`: iterations, real_time = collision (CD&R) plus cloth (CS) time per
/// iteration, cpu_time = the running thread's CPU time per iteration over the phases (their stop checks,
/// and for animations the body updates, included), both in time_unit (set_times), and the counters
/// of DESIGN.md. Fields that do not apply (accuracy of a diverged run, fps of a static body) are
/// omitted, never faked.
nlohmann::json result_row(const RunResult& r, const std::string& name);

/// real_time and cpu_time of a row given in ms, in `unit` (ns, us, ms, s; empty: the one that keeps
/// real_time at 1 or more), written to time_unit.
void set_times(nlohmann::json& row, double real_ms, double cpu_ms, std::string unit = "");

/// A row's real_time or cpu_time (`key`) in ms, read in its time_unit.
double row_time_ms(const nlohmann::json& row, const char* key);
/// A row's limit_misses as the run wrote them, joined by `separator`; "" when it has none.
std::string row_limit_misses(const nlohmann::json& row, const std::string& separator);

/// Google Benchmark's layout for repetitions: every run's row (run_name, repetitions, repetition_index)
/// followed by the aggregates mean, median, stddev (aggregate_unit "time") and cv (a fraction,
/// aggregate_unit "percentage") of real_time and cpu_time; other fields as the run with the median real time's. One run:
/// its row as it is.
nlohmann::json repetition_rows(const std::vector<nlohmann::json>& runs);

/// {"context": machine_context(), "benchmarks": rows}.
nlohmann::json result_document(const nlohmann::json& rows);

/// The document of one configuration's runs named `name`: every run's row with its limit_misses (and the
/// aggregates of repetition_rows when there are several), the context naming the scene file and the
/// configuration's hash; with `end_state`, each run's row carries the cloth's end state too (put_end_state), for
/// `report --reference`.
nlohmann::json runs_document(const std::vector<RunResult>& runs, const std::string& name,
                             const std::string& scene_path, bool end_state = false);

/// The JSON of a file; InputError naming the path when it cannot be opened or is not JSON.
nlohmann::json read_json_file(const std::string& path);

/// The output of a shell command, trailing newlines removed; `status` (when given) receives pclose's
/// status (-1 when the command could not be started).
std::string command_output(const std::string& command, int* status = nullptr);

/// Runs the source tree's Python script SCRIPT (relative to the repository) with `args` (already quoted) under
/// Debian's interpreter where it exists (where python3-matplotlib and the libjs packages' users live, not a
/// user's pyenv or venv); returns the command's exit status (0 = success).
int run_python_script(const std::string& script, const std::string& args);

/// Values of time_unit in 1 ms: ns 1e6, us 1e3, ms 1, s 1e-3; NaN for any other.
double unit_per_ms(const std::string& unit);


/// A number with `digits` decimals, or "-" for NaN.
std::string num(double v, int digits);

}  // namespace clothbench
