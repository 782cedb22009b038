// clothbench compare OLD.json NEW.json [--threshold PCT]: per row, ratio of median times; a
// Mann-Whitney U test when both sides have >= 3 repetitions (as Google Benchmark's compare.py);
// exit 1 on a regression beyond the threshold. Rows whose config_hash differs ran different
// settings: they are shown, flagged and not judged.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>

#include "clothbench/io/errors.hpp"
#include "commands.hpp"

namespace clothbench::cli {

namespace {

using Samples = std::map<std::string, std::vector<double>>;
using Hashes = std::map<std::string, std::set<std::string>>;

// real_time of every iteration row by name (repetitions give several samples), and the rows'
// config_hash where they have one
Samples read_samples(const std::string& path, Hashes& hashes) {
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open");
  nlohmann::json doc;
  try {
    doc = nlohmann::json::parse(in);
  } catch (const nlohmann::json::parse_error& e) {
    throw InputError(path + ": not JSON: " + e.what());
  }
  if (!doc.contains("benchmarks") || !doc["benchmarks"].is_array())
    throw InputError(path + ": no \"benchmarks\" array (expected Google Benchmark's layout)");
  Samples s;
  for (const auto& row : doc["benchmarks"]) {
    if (row.value("run_type", "iteration") != "iteration") continue;
    if (!row.contains("name") || !row.contains("real_time") || !row["real_time"].is_number())
      throw InputError(path + ": a row lacks name or numeric real_time");
    const std::string name = row["name"].get<std::string>();
    s[name].push_back(row["real_time"].get<double>());
    if (row.contains("config_hash") && row["config_hash"].is_string())
      hashes[name].insert(row["config_hash"].get<std::string>());
  }
  return s;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// two-sided Mann-Whitney U test, normal approximation with tie-free variance
double mann_whitney_p(const std::vector<double>& a, const std::vector<double>& b) {
  double u = 0;
  for (double x : a)
    for (double y : b) u += x > y ? 1 : x == y ? 0.5 : 0;
  const double n1 = double(a.size()), n2 = double(b.size());
  const double mean = n1 * n2 / 2, sd = std::sqrt(n1 * n2 * (n1 + n2 + 1) / 12);
  const double z = (std::abs(u - mean) - 0.5) / sd;
  return std::erfc(std::max(0.0, z) / std::sqrt(2.0));
}

// both sides record the row's configuration and the hashes differ
bool config_differs(const Hashes& before, const Hashes& after, const std::string& name) {
  const auto a = before.find(name), b = after.find(name);
  return a != before.end() && b != after.end() && a->second != b->second;
}

int compare(const std::string& old_path, const std::string& new_path, double threshold_pct) {
  Hashes old_hashes, new_hashes;
  const Samples before = read_samples(old_path, old_hashes), after = read_samples(new_path, new_hashes);
  int regressions = 0, changed = 0;
  std::printf("%-44s %12s %12s %8s %8s  %s\n", "name", "old [ms]", "new [ms]", "ratio", "p", "verdict");
  for (const auto& [name, old_t] : before) {
    const auto it = after.find(name);
    if (it == after.end()) {
      std::printf("%-44s %12.4f %12s %8s %8s  missing in new\n", name.c_str(), median(old_t), "-", "-", "-");
      continue;
    }
    const double ratio = median(it->second) / median(old_t);
    if (config_differs(old_hashes, new_hashes, name)) {
      ++changed;
      std::printf("%-44s %12.4f %12.4f %8.3f %8s  CONFIG DIFFERS (not judged)\n", name.c_str(), median(old_t),
                  median(it->second), ratio, "-");
      continue;
    }
    const bool tested = old_t.size() >= 3 && it->second.size() >= 3;
    const double p = tested ? mann_whitney_p(old_t, it->second) : NAN;
    const bool slower = ratio > 1 + threshold_pct / 100 && (!tested || p < 0.05);
    regressions += slower;
    std::printf("%-44s %12.4f %12.4f %8.3f %8s  %s\n", name.c_str(), median(old_t), median(it->second), ratio,
                tested ? std::to_string(p).substr(0, 6).c_str() : "-", slower ? "REGRESSION" : "ok");
  }
  std::printf("%d regression(s) beyond %.1f %% (p < 0.05 where both sides have >= 3 repetitions)\n", regressions, threshold_pct);
  if (changed)
    std::fprintf(stderr,
                 "clothbench compare: warning: %d row(s) ran with a different configuration (config_hash differs: "
                 "other scene settings or --set overrides); their times are not comparable and were not judged\n",
                 changed);
  return regressions ? 1 : 0;
}

}  // namespace

void add_compare_command(CLI::App& app, Action& action) {
  auto paths = std::make_shared<std::vector<std::string>>();
  auto threshold = std::make_shared<double>(10.0);
  auto* cmd = app.add_subcommand("compare", "Compare two result JSON files; exit 1 on a regression");
  cmd->add_option("files", *paths, "OLD.json NEW.json")->required()->expected(2);
  cmd->add_option("--threshold", *threshold, "slow-down that counts as a regression [%]")->check(CLI::Range(0.0, 1e6));
  cmd->callback([&action, paths, threshold] {
    action = [paths, threshold] { return compare((*paths)[0], (*paths)[1], *threshold); };
  });
}

}  // namespace clothbench::cli
