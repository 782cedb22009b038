// Result rows, machine context and atomic writes.
#include "clothbench/bench/report.hpp"
#include "clothbench/bench/timing_stats.hpp"

#include <unistd.h>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include "clothbench/bench/run_result_json.hpp"
#include "clothbench/config.h"
#include "clothbench/io/errors.hpp"

namespace clothbench {

int run_python_script(const std::string& script, const std::string& args) {
  const std::string python = std::filesystem::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
  return std::system((python + " '" + std::string(CLOTHBENCH_SOURCE_DIR) + "/" + script + "' " + args).c_str());
}

std::string command_output(const std::string& command, int* status) {
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) {
    if (status) *status = -1;
    return "";
  }
  std::string out;
  std::array<char, 256> buf{};
  while (std::fgets(buf.data(), buf.size(), pipe)) out += buf.data();
  const int rc = pclose(pipe);
  if (status) *status = rc;
  while (!out.empty() && (out.back() == '\n' || out.back() == '\r')) out.pop_back();
  return out;
}

namespace {

std::string cpu_model() {
  std::ifstream in("/proc/cpuinfo");
  for (std::string line; std::getline(in, line);)
    if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
  return "unknown";
}

// "6.10" -> 6.1, "5.00" -> 5: no trailing zeros
std::string trimmed(std::string s) {
  if (s.find('.') == std::string::npos) return s;
  while (s.back() == '0') s.pop_back();
  if (s.back() == '.') s.pop_back();
  return s;
}

// 6.1, 0.5, 5: two decimals at most, no trailing zeros
std::string short_num(double v) { return trimmed(num(v, 2)); }

// a value past its limit, with as many decimals as show it past (0.503 against 0.5, where two would print 0.5)
std::string past_limit(double v, double limit) {
  if (!std::isfinite(v)) return num(v, 2);
  for (int decimals = 2; decimals < 6; ++decimals)
    if (std::stod(num(v, decimals)) > limit) return trimmed(num(v, decimals));
  return num(v, 6);
}

// one limit: its name, the run's value and the limit, in the unit shown
struct LimitCheck {
  const char* name;
  double value, limit;
  const char* unit;
};

std::vector<LimitCheck> limit_checks(const RunResult& r, bool with_strain) {
  const AccuracyLimits& l = kAccuracyLimits;
  // an animated run is judged by its worst frame (those measured: RunOptions::measure_frames; strain at every
  // frame) as well as its end state, its seams also where the measured window starts (a walk that starts with
  // them open was not dressed)
  const auto worst = [&](double end, double frames) { return std::max(end, frames); };
  std::vector<LimitCheck> checks{
      {"inside", worst(r.accuracy.inside_pct, r.frame_max(&FrameSample::inside_pct)), l.inside_pct, "%"},
      {"depth", worst(r.accuracy.depth_max_mm, r.frame_max(&FrameSample::depth_max_mm)), l.depth_mm, "mm"},
      {"crossings", worst(r.accuracy.crossings_pct, r.frame_max(&FrameSample::crossings_pct)), l.crossings_pct, "%"},
      {"seam gap", worst(r.seam_gap_max_mm, r.window_seam_gap_mm), l.seam_gap_mm, "mm"}};
  if (with_strain && r.strain_threshold > 0)
    checks.push_back(
        {"strain", 100 * worst(r.strain_max, r.animate_strain_max), 100 * (r.strain_threshold + l.strain_excess), "%"});
  return checks;
}

}  // namespace

std::string git_sha() {
  const std::string sha =
      command_output("git -C '" + std::string(CLOTHBENCH_SOURCE_DIR) + "' rev-parse --short HEAD 2>/dev/null");
  if (sha.empty()) return "unknown";
  // the source tree's state; results/ is what a reproduce run is rewriting, so it does not count
  const std::string dirty =
      command_output("git -C '" + std::string(CLOTHBENCH_SOURCE_DIR) +
                     "' status --porcelain --untracked-files=no -- . ':(exclude)results' 2>/dev/null");
  return sha + (dirty.empty() ? "" : "-dirty");
}

std::vector<std::string> limit_misses(const RunResult& r, bool with_strain) {
  if (r.divergence) return {"diverged"};
  std::vector<std::string> misses;
  for (const LimitCheck& c : limit_checks(r, with_strain))
    if (!(c.value <= c.limit))  // NaN misses too
      misses.push_back(std::string(c.name) + " " + past_limit(c.value, c.limit) + " " + c.unit + " > " +
                       short_num(c.limit) + " " + c.unit);
  return misses;
}

std::string limits_cell(const RunResult& r, bool with_strain) {
  const std::vector<std::string> misses = limit_misses(r, with_strain);
  if (misses.empty()) return "yes";
  std::string cell = "no:";
  for (const std::string& m : misses) cell += " " + m + ";";
  cell.pop_back();
  return cell;
}

std::string limits_text(const RunResult& r, bool with_strain) {
  std::string text;
  for (const LimitCheck& c : limit_checks(r, with_strain))
    text += (text.empty() ? "" : ", ") + std::string(c.name) + " <= " + short_num(c.limit) + " " + c.unit;
  return text;
}

nlohmann::json machine_context() {
  char host[256] = {};
  gethostname(host, sizeof host - 1);
  const std::time_t now = std::time(nullptr);
  char date[64];
  std::strftime(date, sizeof date, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
  return {{"date", date},
          {"host_name", host},
          {"executable", "clothbench"},
          {"num_cpus", std::thread::hardware_concurrency()},
          {"cpu_model", cpu_model()},
          {"compiler", CLOTHBENCH_CXX_COMPILER},
          {"build_type", CLOTHBENCH_BUILD_TYPE},
          {"cxx_flags", CLOTHBENCH_CXX_FLAGS},
          {"library_build_type", CLOTHBENCH_BUILD_TYPE},
          {"git_sha", git_sha()},
          {"threads", 1}};
}

double unit_per_ms(const std::string& unit) {
  if (unit == "ns") return 1e6;
  if (unit == "us") return 1e3;
  if (unit == "ms") return 1;
  if (unit == "s") return 1e-3;
  return NAN;
}

void set_times(nlohmann::json& row, double real_ms, double cpu_ms, std::string unit) {
  // the unit that keeps the real time at 1 or more (Google Benchmark: one unit per benchmark)
  const double a = std::abs(real_ms);
  if (unit.empty()) unit = a >= 1 || a == 0 ? "ms" : a >= 1e-3 ? "us" : "ns";
  const double per_ms = unit_per_ms(unit);
  row["real_time"] = real_ms * per_ms;
  row["cpu_time"] = cpu_ms * per_ms;
  row["time_unit"] = unit;
}

namespace {

// the fields every run has: sizes, times per iteration, the configuration, the phases and the verdicts
nlohmann::json run_fields(const RunResult& r, const std::string& name) {
  return {{"name", name},
          {"run_type", "iteration"},
          {"iterations", r.iterations()},
          {"vertices", r.vertices},
          {"query_points", r.query_points},
          {"body_triangles", r.body_triangles},
          {"collision_triangles", r.collision_triangles},
          {"proxy_deviation_mm", r.proxy_deviation_mm},
          {"total_s", r.total_s()},
          {"setup_ms", r.setup_ms},
          {"cdr_ms", r.cdr_ms_per_iteration()},
          {"cs_ms", r.cs_ms_per_iteration()},
          {"limit_ms", r.limit_ms_per_iteration()},
          {"cloth_ms", r.cloth_ms_per_iteration()},
          {"scene", r.scene},
          {"collider", r.collider},
          {"integrator", r.integrator},
          {"regime", r.regime},
          {"dt_ms", 1e3 * r.dt_s},
          {"dt_bound_ms", 1e3 * r.dt_bound_s},
          {"dt_spectral_ms", 1e3 * r.dt_spectral_s},
          {"sew_iterations", r.sew.iterations},
          {"sewn", r.sew.reached ? 1 : 0},
          {"drape_iterations", r.drape.iterations},
          {"threads", r.threads},
          {"converged", r.converged ? 1 : 0},
          {"diverged", r.divergence ? 1 : 0},
          {"meets_limits", limit_misses(r).empty() ? 1 : 0}};
}

// an animated run: its frames, their rate and what each cost
void add_animation_fields(const RunResult& r, nlohmann::json& row) {
  row["frames"] = r.frames;
  row["fps"] = r.animate.wall_ms > 0 ? 1e3 * double(r.frames) / r.animate.wall_ms : 0.0;
  row["steps_per_frame"] = r.steps_per_frame;
  row["skinning_ms_per_frame"] = r.skinning_ms / double(r.frames);
  row["collider_update_ms_per_frame"] = r.collider_update_ms / double(r.frames);
  row["poses_per_frame"] = double(r.collider_updates) / double(r.frames);
  row["animate_iterations"] = r.animate.iterations;
  row["prepared_frames"] = r.prepared_frames;
}

// the end state against the exact body, and with every animation frame measured (RunOptions::measure_frames) the
// worst and the mean frame
void add_accuracy_fields(const RunResult& r, nlohmann::json& row) {
  row["inside_pct"] = r.accuracy.inside_pct;
  row["depth_max_mm"] = r.accuracy.depth_max_mm;
  row["depth_p95_mm"] = r.accuracy.depth_p95_mm;
  row["crossings"] = r.accuracy.crossings;
  row["crossings_pct"] = r.accuracy.crossings_pct;
  row["structural_springs"] = r.accuracy.segments;
  row["faces_inside_pct"] = r.accuracy.faces_inside_pct;
  row["cloth_crossings_pct"] = r.accuracy.cloth_crossings_pct;
  row["oracle_depth_ms"] = r.accuracy.depth_ms;
  row["oracle_crossings_ms"] = r.accuracy.crossings_ms;
  row["seam_gap_max_mm"] = r.seam_gap_max_mm;
  row["strain_max"] = r.strain_max;
  row["strain_p99"] = r.strain_p99;
  row["strain_over"] = r.strain_over;
  row["strain_max_where"] = r.strain_max_where;
  row["cloth_crossings_where"] = r.cloth_crossings_where;
  row["kinetic_energy_j"] = r.kinetic_energy;
  if (r.frame_samples.empty()) return;
  row["frames_measured"] = r.frame_samples.size();
  row["worst_frame_inside_pct"] = r.frame_max(&FrameSample::inside_pct);
  row["mean_frame_inside_pct"] = r.frame_mean(&FrameSample::inside_pct);
  row["worst_frame_depth_max_mm"] = r.frame_max(&FrameSample::depth_max_mm);
  row["worst_frame_crossings_pct"] = r.frame_max(&FrameSample::crossings_pct);
  row["mean_frame_crossings_pct"] = r.frame_mean(&FrameSample::crossings_pct);
  row["worst_frame_cloth_crossings_pct"] = r.frame_max(&FrameSample::cloth_crossings_pct);
  row["worst_frame_strain_max"] = r.frame_max(&FrameSample::strain_max);
  row["worst_frame_strain_where"] = r.animate_strain_max_where;
  row["depth_max_where"] = r.depth_max_where;
}

}  // namespace

nlohmann::json result_row(const RunResult& r, const std::string& name) {
  nlohmann::json row = run_fields(r, name);
  set_times(row, r.ms_per_iteration(), r.cpu_ms_per_iteration());
  if (!r.config_hash.empty()) row["config_hash"] = r.config_hash;
  if (!r.device.empty()) row["device"] = r.device;
  if (r.search_share > 0) row["search_share"] = r.search_share;
  if (r.frames > 0) add_animation_fields(r, row);
  if (r.divergence) {
    row["diverged_iteration"] = r.divergence->iteration;
    row["diverged_phase"] = to_string(r.divergence->phase);
    row["diverged_vertex"] = r.divergence->vertex;
    row["diverged_reason"] = r.divergence->reason;
    return row;  // no accuracy for a diverged run
  }
  add_accuracy_fields(r, row);
  return row;
}

double row_time_ms(const nlohmann::json& row, const char* key) {
  return row.at(key).get<double>() / unit_per_ms(row.value("time_unit", std::string("ms")));
}

std::string row_limit_misses(const nlohmann::json& row, const std::string& separator) {
  std::string out;
  const auto it = row.find("limit_misses");
  if (it != row.end() && it->is_array())
    for (const auto& m : *it)
      if (m.is_string()) out += (out.empty() ? "" : separator) + m.get<std::string>();
  return out;
}

namespace {

// an aggregate row of Google Benchmark's repetitions: name_AGG, run_type aggregate
nlohmann::json aggregate_row(const nlohmann::json& first, const std::string& aggregate, double real_ms, double cpu_ms,
                             std::size_t n) {
  nlohmann::json row = first;
  row.erase("repetition_index");
  row["name"] = first["run_name"].get<std::string>() + "_" + aggregate;
  row["run_type"] = "aggregate";
  row["aggregate_name"] = aggregate;
  row["iterations"] = n;
  if (aggregate == "cv") {
    // Google Benchmark writes the coefficient of variation as a fraction, aggregate_unit "percentage"
    row["aggregate_unit"] = "percentage";
    row["real_time"] = real_ms;
    row["cpu_time"] = cpu_ms;
    return row;
  }
  row["aggregate_unit"] = "time";
  set_times(row, real_ms, cpu_ms, first["time_unit"].get<std::string>());
  return row;
}

}  // namespace

nlohmann::json repetition_rows(const std::vector<nlohmann::json>& runs) {
  nlohmann::json out = nlohmann::json::array();
  if (runs.size() < 2) {
    for (const auto& r : runs) out.push_back(r);
    return out;
  }
  std::vector<double> real, cpu;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    nlohmann::json row = runs[i];
    row["run_name"] = runs[0]["name"];
    row["name"] = runs[0]["name"];
    row["repetitions"] = runs.size();
    row["repetition_index"] = i;
    real.push_back(row_time_ms(row, "real_time"));
    cpu.push_back(row_time_ms(row, "cpu_time"));
    out.push_back(std::move(row));
  }
  // the aggregates carry the other fields of the median run (the one median_run picks: the upper middle)
  std::vector<std::size_t> order(real.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return real[a] < real[b]; });
  // a copy: the aggregates pushed below may move `out`'s rows
  const nlohmann::json first = out[order[order.size() / 2]];
  const std::string unit = first["time_unit"];  // one unit for the benchmark, the median run's
  for (std::size_t i = 0; i < out.size(); ++i) set_times(out[i], real[i], cpu[i], unit);
  const std::size_t n = runs.size();
  out.push_back(aggregate_row(first, "mean", mean(real), mean(cpu), n));
  out.push_back(aggregate_row(first, "median", median(real), median(cpu), n));
  out.push_back(aggregate_row(first, "stddev", stddev(real), stddev(cpu), n));
  out.push_back(aggregate_row(first, "cv", stddev(real) / mean(real), stddev(cpu) / mean(cpu), n));
  return out;
}

nlohmann::json result_document(const nlohmann::json& rows) {
  return {{"context", machine_context()}, {"benchmarks", rows}};
}

nlohmann::json runs_document(const std::vector<RunResult>& runs, const std::string& name, const std::string& scene_path,
                             bool end_state) {
  std::vector<nlohmann::json> rows;
  for (const RunResult& r : runs) {
    rows.push_back(result_row(r, name));
    rows.back()["limit_misses"] = limit_misses(r);
    if (end_state) put_end_state(rows.back(), r.mesh);
  }
  nlohmann::json doc = result_document(repetition_rows(rows));
  doc["context"]["scene"] = scene_path;
  if (!runs.empty()) doc["context"]["config_hash"] = runs.front().config_hash;
  return doc;
}

nlohmann::json read_json_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open");
  try {
    return nlohmann::json::parse(in);
  } catch (const nlohmann::json::parse_error& e) {
    throw InputError(path + ": not JSON: " + e.what());
  }
}

std::string num(double v, int digits) {
  if (!std::isfinite(v)) return "-";
  std::ostringstream s;
  s.setf(std::ios::fixed);
  s.precision(digits);
  s << v;
  return s.str();
}

}  // namespace clothbench
