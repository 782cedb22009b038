// clothbench compare OLD.json NEW.json [--threshold PCT]: per benchmark, the Hodges-Lehmann ratio of the
// new times to the old with its 95 % confidence interval and a one-sided Mann-Whitney U test
// (timing_stats.hpp). A regression needs at least kMinRepetitions repetitions on both sides (rows with
// fewer get no verdict, said so), p < 0.05 and a ratio beyond the threshold. Times are read in each row's
// time_unit. Rows whose config_hash differs ran different settings: shown, flagged and not judged; rows
// on one side only are listed. Accuracy is judged with any number of repetitions (the simulation is
// deterministic): a row that stops meeting the accuracy limits, diverges, or whose accuracy figure worsens by more
// than --accuracy-tolerance of that figure's limit is an accuracy regression. Exit 1 on a regression of either
// kind, 2 when no row's time could be judged. --pair-by FIELD,... pairs the rows by those fields' values instead
// of their names (collider A in one file against collider B in the other: --pair-by scene,vertices); each pair is
// listed, and config_hash, which differs across such pairs by design, is not checked.
#include <cmath>
#include <cstdio>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "clothbench/bench/report.hpp"
#include "clothbench/bench/timing_stats.hpp"
#include "clothbench/io/errors.hpp"
#include "clothbench/sim/simulator.hpp"
#include "commands.hpp"

namespace clothbench::cli {

namespace {

// what a row says about accuracy (its first iteration row's: every repetition simulates the same)
struct Accuracy {
  bool present = false;
  bool meets = true, diverged = false;
  std::string misses;                 // limit_misses, joined
  std::map<std::string, double> figures;  // the figures below that the row has
};

// the accuracy figures compare judges and their limits (kAccuracyLimits; strain, a fraction, at the default
// threshold's: the rows do not carry theirs)
struct Figure {
  const char* key;
  double limit;
};
const double kStrainLimit = double(SolverParams{}.threshold) + kAccuracyLimits.strain_excess;
const Figure kFigures[] = {{"inside_pct", kAccuracyLimits.inside_pct},
                           {"worst_frame_inside_pct", kAccuracyLimits.inside_pct},
                           {"depth_max_mm", kAccuracyLimits.depth_mm},
                           {"worst_frame_depth_max_mm", kAccuracyLimits.depth_mm},
                           {"crossings_pct", kAccuracyLimits.crossings_pct},
                           {"worst_frame_crossings_pct", kAccuracyLimits.crossings_pct},
                           {"seam_gap_max_mm", kAccuracyLimits.seam_gap_mm},
                           {"strain_max", kStrainLimit},
                           {"worst_frame_strain_max", kStrainLimit}};

Accuracy read_accuracy(const nlohmann::json& row) {
  Accuracy a;
  a.present = true;
  const auto flag = [&](const char* key) { return row.contains(key) && row[key].is_number() && row[key].get<double>() != 0; };
  a.diverged = flag("diverged");
  a.meets = !row.contains("meets_limits") || flag("meets_limits");
  a.misses = row_limit_misses(row, ", ");
  for (const Figure& f : kFigures)
    if (row.contains(f.key) && row[f.key].is_number()) a.figures[f.key] = row[f.key].get<double>();
  return a;
}

struct Benchmark {
  Accuracy accuracy;               // the first iteration row's
  std::vector<double> ns;          // real_time of every iteration row (one per repetition) [ns]
  std::set<std::string> hashes;    // config_hash where the rows have one
  std::string unit = "ms";         // the rows' time_unit, for printing
  nlohmann::json first;            // the first iteration row (the fields --pair-by reads)
};
using Benchmarks = std::map<std::string, Benchmark>;

// nanoseconds in one time_unit
double ns_per(const std::string& unit, const std::string& path) {
  const double per_ms = unit_per_ms(unit);
  if (!std::isfinite(per_ms)) throw InputError(path + ": unknown time_unit '" + unit + "' (ns, us, ms, s)");
  return 1e6 / per_ms;
}

// the iteration rows (aggregates are recomputed from them), by name
Benchmarks read_benchmarks(const std::string& path) {
  const nlohmann::json doc = read_json_file(path);
  if (!doc.contains("benchmarks") || !doc["benchmarks"].is_array())
    throw InputError(path + ": no \"benchmarks\" array (expected Google Benchmark's layout)");
  Benchmarks s;
  for (const auto& row : doc["benchmarks"]) {
    if (row.value("run_type", "iteration") != "iteration") continue;
    if (!row.contains("name") || !row["name"].is_string() || !row.contains("real_time") ||
        !row["real_time"].is_number())
      throw InputError(path + ": a row lacks name or numeric real_time");
    const std::string name = row.contains("run_name") && row["run_name"].is_string()
                                 ? row["run_name"].get<std::string>()
                                 : row["name"].get<std::string>();
    Benchmark& b = s[name];
    b.unit = row.value("time_unit", std::string("ms"));
    b.ns.push_back(row["real_time"].get<double>() * ns_per(b.unit, path));
    if (row.contains("config_hash") && row["config_hash"].is_string()) b.hashes.insert(row["config_hash"].get<std::string>());
    if (!b.accuracy.present) b.accuracy = read_accuracy(row), b.first = row;
  }
  return s;
}

// "field=value, ..." of a row for --pair-by
std::string pair_key(const nlohmann::json& row, const std::vector<std::string>& fields, const std::string& path,
                     const std::string& name) {
  std::string key;
  for (const std::string& f : fields) {
    if (!row.contains(f)) throw InputError(path + ": row '" + name + "' has no field '" + f + "' (--pair-by)");
    key += (key.empty() ? "" : ", ") + f + "=" + (row[f].is_string() ? row[f].get<std::string>() : row[f].dump());
  }
  return key;
}

// the rows of one file by their --pair-by key; two rows with one key cannot be paired
std::map<std::string, std::string> by_key(const Benchmarks& rows, const std::vector<std::string>& fields,
                                          const std::string& path) {
  std::map<std::string, std::string> out;
  for (const auto& [name, b] : rows) {
    const std::string key = pair_key(b.first, fields, path, name);
    const auto [it, added] = out.emplace(key, name);
    if (!added)
      throw InputError(path + ": rows '" + it->second + "' and '" + name + "' both have " + key +
                       ": --pair-by does not tell them apart (add a field)");
  }
  return out;
}

std::string fixed(double v, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", digits, v);
  return buf;
}

// "12.345 ms" in the old rows' unit
std::string time_in(double ns, const std::string& unit) { return fixed(ns / ns_per(unit, ""), 4) + " " + unit; }

void print_row(const std::string& name, const std::string& old_t, const std::string& new_t, const std::string& ratio,
               const std::string& p, const std::string& verdict) {
  std::printf("%-48s %14s %14s %24s %8s  %s\n", name.c_str(), old_t.c_str(), new_t.c_str(), ratio.c_str(), p.c_str(),
              verdict.c_str());
}

struct Tally {
  int regressions = 0, judged = 0, unjudged = 0, changed = 0, one_side = 0;
  int accuracy_regressions = 0, accuracy_judged = 0;
  std::vector<std::string> accuracy_lines;  // printed after the table
};

// how the new row's accuracy is worse than the old one's beyond the tolerance (a fraction of each figure's limit);
// empty when it is not
std::vector<std::string> accuracy_worse(const Accuracy& o, const Accuracy& n, double tolerance) {
  std::vector<std::string> worse;
  if (n.diverged && !o.diverged) return {"diverged"};
  if (o.meets && !n.meets) worse.push_back("stopped meeting the accuracy limits" + (n.misses.empty() ? "" : " (" + n.misses + ")"));
  for (const Figure& f : kFigures) {
    const auto a = o.figures.find(f.key), b = n.figures.find(f.key);
    if (a == o.figures.end() || b == n.figures.end()) continue;
    const double allowed = tolerance * f.limit;
    if (b->second - a->second > allowed)
      worse.push_back(std::string(f.key) + " " + fixed(a->second, 4) + " -> " + fixed(b->second, 4) + " (tolerance +" +
                      fixed(allowed, 4) + ")");
  }
  return worse;
}

void judge_accuracy(const std::string& name, const Benchmark& o, const Benchmark& n, double tolerance, Tally& tally) {
  if (!o.accuracy.present || !n.accuracy.present) return;
  ++tally.accuracy_judged;
  const auto worse = accuracy_worse(o.accuracy, n.accuracy, tolerance);
  if (worse.empty()) return;
  ++tally.accuracy_regressions;
  std::string line = "ACCURACY REGRESSION " + name + ":";
  for (const std::string& w : worse) line += " " + w + ";";
  line.pop_back();
  tally.accuracy_lines.push_back(line);
}

void compare_one(const std::string& name, const Benchmark& o, const Benchmark& n, double threshold,
                 double accuracy_tolerance, Tally& tally) {
  const std::string before = time_in(median(o.ns), o.unit), after = time_in(median(n.ns), o.unit);
  const TimingComparison c = compare_timings(o.ns, n.ns, threshold);
  const std::string ratio = fixed(c.ratio, 3) + " [" + fixed(c.ratio_lo, 3) + ", " + fixed(c.ratio_hi, 3) + "]";
  if (!o.hashes.empty() && !n.hashes.empty() && o.hashes != n.hashes) {
    ++tally.changed;
    print_row(name, before, after, ratio, "-", "CONFIG DIFFERS (not judged)");
    return;
  }
  judge_accuracy(name, o, n, accuracy_tolerance, tally);
  if (!c.judged) {
    ++tally.unjudged;
    print_row(name, before, after, ratio, "-",
              "no verdict: " + std::to_string(c.n_old) + " vs " + std::to_string(c.n_new) + " repetitions (need >= " +
                  std::to_string(kMinRepetitions) + " on both sides)");
    return;
  }
  ++tally.judged;
  tally.regressions += c.regression;
  print_row(name, before, after, ratio, fixed(c.p_slower, 4), c.regression ? "REGRESSION" : "ok");
}

// the rows under their --pair-by keys (by_key), the hash then not compared
Benchmarks keyed(const Benchmarks& rows, const std::map<std::string, std::string>& names) {
  Benchmarks out;
  for (const auto& [key, name] : names) {
    out[key] = rows.at(name);
    out[key].hashes.clear();
  }
  return out;
}

int compare(const std::string& old_path, const std::string& new_path, double threshold_pct, double accuracy_pct,
            const std::vector<std::string>& pair_by) {
  Benchmarks before = read_benchmarks(old_path), after = read_benchmarks(new_path);
  if (!pair_by.empty()) {
    const auto old_names = by_key(before, pair_by, old_path), new_names = by_key(after, pair_by, new_path);
    for (const auto& [key, name] : old_names)
      if (new_names.count(key)) std::printf("paired by %s: old '%s' with new '%s'\n", key.c_str(), name.c_str(),
                                            new_names.at(key).c_str());
    before = keyed(before, old_names), after = keyed(after, new_names);
  }
  Tally tally;
  print_row(pair_by.empty() ? "name" : "pair", "old (median)", "new (median)", "new/old [95 % CI]", "p", "verdict");
  for (const auto& [name, o] : before) {
    const auto it = after.find(name);
    if (it == after.end()) {
      ++tally.one_side;
      print_row(name, time_in(median(o.ns), o.unit), "-", "-", "-", "only in old");
    } else {
      compare_one(name, o, it->second, threshold_pct / 100, accuracy_pct / 100, tally);
    }
  }
  for (const auto& [name, n] : after)
    if (!before.count(name)) ++tally.one_side, print_row(name, "-", time_in(median(n.ns), n.unit), "-", "-", "only in new");
  std::printf("%d regression(s) among %d judged row(s): slower by more than %.1f %% with p < 0.05 (one-sided "
              "Mann-Whitney U); %d row(s) without a verdict, %d with another configuration, %d on one side only\n",
              tally.regressions, tally.judged, threshold_pct, tally.unjudged, tally.changed, tally.one_side);
  for (const std::string& line : tally.accuracy_lines) std::printf("%s\n", line.c_str());
  std::printf("%d accuracy regression(s) among %d row(s) compared: stopped meeting the limits, diverged, or an accuracy "
              "figure worse by more than %.1f %% of its limit\n",
              tally.accuracy_regressions, tally.accuracy_judged, accuracy_pct);
  if (tally.changed)
    std::fprintf(stderr,
                 "clothbench compare: warning: %d row(s) ran with a different configuration (config_hash differs: "
                 "other scene settings or --set overrides); their times are not comparable and were not judged\n",
                 tally.changed);
  if (tally.regressions || tally.accuracy_regressions) return 1;
  if (tally.judged == 0) {
    const std::string why = tally.unjudged ? "run both sides with --repetitions " + std::to_string(kMinRepetitions) +
                                                 " or more"
                            : tally.changed ? "the rows that pair ran other configurations"
                                            : "no row pairs (by name, or by --pair-by's fields)";
    std::fprintf(stderr, "clothbench compare: no row's time could be judged: %s\n", why.c_str());
    return 2;
  }
  return 0;
}

}  // namespace

void add_compare_command(CLI::App& app, Action& action) {
  auto paths = std::make_shared<std::vector<std::string>>();
  auto threshold = std::make_shared<double>(10.0);
  auto accuracy = std::make_shared<double>(10.0);
  auto pair_by = std::make_shared<std::vector<std::string>>();
  auto* cmd = app.add_subcommand(
      "compare", "Compare two result JSON files (>= " + std::to_string(kMinRepetitions) +
                     " repetitions per row for a time verdict; accuracy is judged at any count); exit 1 on a regression "
                     "of time or accuracy, 2 when no row's time could be judged");
  cmd->add_option("files", *paths, "OLD.json NEW.json")->required()->expected(2);
  cmd->add_option("--threshold", *threshold, "slow-down that counts as a regression [%]")
      ->check(CLI::Range(0.0, 1e6))
      ->capture_default_str();
  cmd->add_option("--accuracy-tolerance", *accuracy,
                  "an accuracy figure (inside, depth, crossings, seam gap, strain; worst frame too) worse by more "
                  "than this share of its limit is an accuracy regression [%]")
      ->check(CLI::Range(0.0, 1e6))
      ->capture_default_str();
  cmd->add_option("--pair-by", *pair_by,
                  "pair rows by these JSON fields' values instead of their names, e.g. scene,vertices to set one "
                  "collider against another (config_hash, which differs then, is not checked)")
      ->delimiter(',');
  cmd->callback([&action, paths, threshold, accuracy, pair_by] {
    action = [paths, threshold, accuracy, pair_by] {
      return compare((*paths)[0], (*paths)[1], *threshold, *accuracy, *pair_by);
    };
  });
}

}  // namespace clothbench::cli
