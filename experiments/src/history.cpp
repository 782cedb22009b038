// results/history.jsonl (history.hpp).
#include "clothbench/experiments/history.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>

#include "clothbench/bench/report.hpp"
#include "clothbench/io/errors.hpp"

namespace clothbench {

namespace {

// the figures kept per configuration
nlohmann::json key_figures(const nlohmann::json& row) {
  nlohmann::json k{{"real_ms", row_time_ms(row, "real_time")}};
  for (const char* f : {"cdr_ms", "cs_ms", "inside_pct", "depth_max_mm", "crossings_pct", "meets_limits"})
    if (row.contains(f)) k[f] = row[f];
  return k;
}

}  // namespace

nlohmann::json history_entry(const std::string& id, const nlohmann::json& rows, const nlohmann::json& context,
                             bool quick) {
  nlohmann::json figures = nlohmann::json::object();
  for (const auto& row : rows) {
    if (!row.contains("real_time") || !row.contains("name")) continue;
    const bool aggregate = row.value("run_type", "iteration") == "aggregate";
    if (aggregate && row.value("aggregate_name", "") == "median")
      figures[row.value("run_name", "")] = key_figures(row);  // with repetitions: their median
    else if (!aggregate && !figures.contains(row.value("name", "")))
      figures[row.value("name", "")] = key_figures(row);
  }
  const auto field = [&](const char* key) { return context.is_object() ? context.value(key, "") : std::string(); };
  return {{"date", field("date")}, {"git_sha", field("git_sha")}, {"experiment", id},
          {"quick", quick},                    {"rows", figures}};
}

void append_history(const std::string& path, const nlohmann::json& entry) {
  std::ofstream out(path, std::ios::app);
  if (!out || !(out << entry.dump() << "\n")) throw InputError(path + ": cannot append the history line");
}

std::vector<nlohmann::json> read_history(const std::string& path) {
  std::vector<nlohmann::json> entries;
  std::ifstream in(path);
  std::string line;
  for (int n = 1; std::getline(in, line); ++n) {
    if (line.empty()) continue;
    const auto e = nlohmann::json::parse(line, nullptr, false);
    if (e.is_discarded() || !e.contains("experiment") || !e.contains("rows"))
      throw InputError(path + ":" + std::to_string(n) + ": not a history entry");
    entries.push_back(e);
  }
  return entries;
}

std::vector<nlohmann::json> entries_of(const std::vector<nlohmann::json>& history, const std::string& id,
                                       bool quick) {
  std::vector<nlohmann::json> out;
  for (const auto& e : history)
    if (e["experiment"] == id && e.value("quick", false) == quick) out.push_back(e);
  return out;
}

HistoryChange compare_entries(const nlohmann::json& before, const nlohmann::json& after) {
  HistoryChange c;
  const auto& a = before["rows"];
  const auto& b = after["rows"];
  double log_sum = 0;
  for (const auto& [name, old_row] : a.items()) {
    if (!b.contains(name)) {
      ++c.removed;
      continue;
    }
    const auto& new_row = b[name];
    const double o = old_row.value("real_ms", 0.0), n = new_row.value("real_ms", 0.0);
    if (o > 0 && n > 0) {
      const double r = n / o;
      c.ratio_min = c.common ? std::min(c.ratio_min, r) : r;
      c.ratio_max = c.common ? std::max(c.ratio_max, r) : r;
      log_sum += std::log(r);
      ++c.common;
    }
    c.verdict_changed += old_row.value("meets_limits", -1) != new_row.value("meets_limits", -1);
  }
  for (const auto& [name, row] : b.items()) c.added += !a.contains(name);
  c.time_ratio = c.common ? std::exp(log_sum / c.common) : 1;
  return c;
}

nlohmann::json trend_chart(const std::vector<nlohmann::json>& entries, const std::string& id) {
  std::vector<double> x, index, meets;
  std::vector<std::string> labels;
  double level = 1;
  for (std::size_t i = 0; i < entries.size(); ++i) {
    if (i) level *= compare_entries(entries[i - 1], entries[i]).time_ratio;
    int n = 0, ok = 0;
    for (const auto& [name, row] : entries[i]["rows"].items())
      if (row.contains("meets_limits")) ++n, ok += row["meets_limits"].get<int>() == 1;
    x.push_back(double(i));
    index.push_back(level);
    meets.push_back(n ? double(ok) / n : NAN);
    labels.push_back(entries[i].value("git_sha", "?") + " " + entries[i].value("date", "").substr(0, 10));
  }
  nlohmann::json series = nlohmann::json::array(
      {{{"label", "time per iteration (geometric mean, first run = 1)"}, {"x", x}, {"y", index}, {"style", "o-"}}});
  if (std::any_of(meets.begin(), meets.end(), [](double v) { return !std::isnan(v); }))
    series.push_back({{"label", "share of configurations meeting the limits"}, {"x", x}, {"y", meets}, {"style", "s--"}});
  return {{"title", id + ": trend over reproduce runs (results/history.jsonl)"},
          {"xlabel", "run (git SHA, date)"},
          {"ylabel", "relative"},
          {"xticklabels", labels},
          {"series", series}};
}

}  // namespace clothbench
