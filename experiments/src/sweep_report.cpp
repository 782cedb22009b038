// clothbench report: a user's rows (sweep, merge, run --json) as the built-in experiments' page: a summary first, the
// table with each configuration's spread, time against each accuracy figure, the HTML page
#include "clothbench/experiments/sweep_report.hpp"

#include <algorithm>
#include <map>
#include <optional>
#include <set>

#include "clothbench/bench/drape_error.hpp"
#include "clothbench/bench/report.hpp"
#include "clothbench/bench/run_result_json.hpp"
#include "clothbench/experiments/experiment.hpp"
#include "clothbench/experiments/html_report.hpp"
#include "clothbench/experiments/markdown_table.hpp"
#include "clothbench/io/errors.hpp"

namespace clothbench {

namespace {

double field(const nlohmann::json& row, const char* key) {
  const auto it = row.find(key);
  return it != row.end() && it->is_number() ? it->get<double>() : 0.0;
}

// the worse of the end state's figure and the worst measured frame's (a moving body), times `scale`
double worst(const nlohmann::json& row, const char* end, const char* frames, double scale = 1) {
  return scale * std::max(field(row, end), field(row, frames));
}

bool meets(const nlohmann::json& row) { return field(row, "meets_limits") == 1; }
bool diverged(const nlohmann::json& row) { return field(row, "diverged") == 1; }
double ms(const nlohmann::json& row) { return row_time_ms(row, "real_time"); }
std::string text(const nlohmann::json& row, const char* key) {
  const auto it = row.find(key);
  return it != row.end() && it->is_string() ? it->get<std::string>() : "-";
}

// "yes", "no: what it misses" (as the run wrote it), or where it diverged
std::string verdict(const nlohmann::json& row) {
  if (diverged(row))
    return "diverged at iteration " + num(field(row, "diverged_iteration"), 0) + " (" + text(row, "diverged_reason") +
           ")";
  if (meets(row)) return "yes";
  const std::string misses = row_limit_misses(row, "; ");
  return misses.empty() ? "no" : "no: " + misses;
}

std::string describe(const ReportConfiguration& c) {
  return c.label + ", " + num(ms(c.median), 3) + " ms/iteration (" +
         (c.runs == 1 ? std::string("1 run")
                      : std::to_string(c.runs) + " runs, spread " + num(c.spread_pct, 1) + " %") +
         ")";
}

// the charts: time per iteration against one accuracy figure, a series per collider
struct Chart {
  const char* name;
  const char* ylabel;
  double (*value)(const nlohmann::json&);
  std::map<std::string, std::pair<std::vector<double>, std::vector<double>>> points;
};

std::vector<std::string> summary(const std::vector<ReportConfiguration>& configs, const std::string& source,
                                 std::size_t failed) {
  const ReportConfiguration* fastest = nullptr;
  const ReportConfiguration* within = nullptr;
  int meeting = 0, diverging = 0, runs = 0, fewest = 0;
  for (const auto& c : configs) {
    runs += c.runs;
    fewest = fewest == 0 ? c.runs : std::min(fewest, c.runs);
    if (diverged(c.median)) {
      ++diverging;
      continue;
    }
    meeting += meets(c.median);
    if (!fastest || ms(c.median) < ms(fastest->median)) fastest = &c;
    if (meets(c.median) && (!within || ms(c.median) < ms(within->median))) within = &c;
  }
  std::vector<std::string> lines{
      std::to_string(configs.size()) + (configs.size() == 1 ? " configuration from " : " configurations from ") +
      source + ", " + std::to_string(runs) + (runs == 1 ? " run: " : " runs in all: ") + std::to_string(meeting) +
      (meeting == 1 ? " meets" : " meet") + " every limit, strain included" +
      (diverging ? ", " + std::to_string(diverging) + " diverged" : "") +
      (failed ? ", " + std::to_string(failed) + " points failed or are missing (listed below)" : "") + "."};
  lines.push_back(within ? "The fastest meeting every limit: " + describe(*within) + "."
                         : std::string("No configuration meets every limit."));
  if (fastest)
    lines.push_back("The fastest of all: " + describe(*fastest) + ", meets the limits: " + verdict(fastest->median) +
                    ".");
  std::string v = !within ? "no configuration here is fastest within the limits"
                  : within == fastest
                      ? "the fastest configuration meets every limit"
                      : "meeting every limit costs " + num(ms(within->median) / ms(fastest->median), 2) +
                            " times the fastest configuration's time per iteration";
  if (fewest < 5)
    v += "; timings from fewer than five runs per configuration (`--repetitions 5` or more to judge speed)";
  lines.push_back("Verdict: " + v + ".");
  return lines;
}

}  // namespace

std::vector<ReportConfiguration> report_configurations(const nlohmann::json& doc) {
  if (!doc.is_object() || !doc.contains("benchmarks") || !doc["benchmarks"].is_array())
    throw InputError(
        "not a results document: no \"benchmarks\" array (give a sweep folder, merge's file or run "
        "--json's)");
  std::vector<std::string> order;  // keys in the document's order
  std::map<std::string, std::vector<nlohmann::json>> rows;
  std::map<std::string, std::set<std::string>> hashes;  // per name: the configurations that carry it
  for (const auto& row : doc["benchmarks"]) {
    if (!row.is_object() || text(row, "run_type") == "aggregate") continue;
    if (!row.contains("name") || !row["name"].is_string() || !row.contains("real_time") ||
        !row["real_time"].is_number())
      throw InputError("a row without a name or a numeric real_time: " + row.dump().substr(0, 200));
    const std::string name = row["name"].get<std::string>(), hash = text(row, "config_hash");
    const std::string key = name + "\n" + hash;
    if (!rows.count(key)) order.push_back(key);
    rows[key].push_back(row);
    hashes[name].insert(hash);
  }
  if (order.empty()) throw InputError("the document has no run rows (only aggregates, or none)");
  std::vector<ReportConfiguration> out;
  for (const auto& key : order) {
    auto& group = rows[key];
    std::stable_sort(group.begin(), group.end(), [](const auto& a, const auto& b) { return ms(a) < ms(b); });
    const std::string name = key.substr(0, key.find('\n')), hash = key.substr(key.find('\n') + 1);
    ReportConfiguration c;
    c.label = hashes[name].size() > 1 ? name + " [config " + hash + "]" : name;
    c.median = group[(group.size() - 1) / 2];
    c.runs = static_cast<int>(group.size());
    c.spread_pct = ms(c.median) > 0 ? 100 * (ms(group.back()) - ms(group.front())) / ms(c.median) : 0;
    out.push_back(std::move(c));
  }
  return out;
}

ReportReference report_reference(const nlohmann::json& doc, const std::string& path) {
  if (doc.is_object() && doc.contains("benchmarks") && doc["benchmarks"].is_array())
    for (const auto& row : doc["benchmarks"])
      if (auto cloth = end_state_from_json(row)) return {std::move(*cloth), text(row, "name") + " (" + path + ")"};
  throw InputError(path + ": no row carries its cloth's end state (write the reference with run --json FILE "
                   "--end-state)");
}

namespace {

// the median row's drape error against the reference [mm], when it carries its end state (false otherwise)
bool add_drape_error(nlohmann::json& row, const ReportReference& reference) {
  const std::optional<ClothMesh> cloth = end_state_from_json(row);
  if (!cloth) return false;
  const DrapeError e = drape_error(*cloth, reference.cloth);
  row["drape_error_rms_mm"] = 1e3 * e.rms;
  row["drape_error_max_mm"] = 1e3 * e.max;
  return true;
}

std::vector<Chart> accuracy_charts(bool drape) {
  std::vector<Chart> charts{
      {"sweep-inside", "inside the body [%] (worst frame)",
       [](const nlohmann::json& r) { return worst(r, "inside_pct", "worst_frame_inside_pct"); }, {}},
      {"sweep-crossings", "structural springs crossing the body [%] (worst frame)",
       [](const nlohmann::json& r) { return worst(r, "crossings_pct", "worst_frame_crossings_pct"); }, {}},
      {"sweep-strain", "largest structural strain [%] (worst frame)",
       [](const nlohmann::json& r) { return worst(r, "strain_max", "worst_frame_strain_max", 100); }, {}}};
  if (drape)
    charts.push_back({"sweep-drape-error", "drape error against the reference, RMS [mm]",
                      [](const nlohmann::json& r) { return field(r, "drape_error_rms_mm"); }, {}});
  return charts;
}

// the charts as pictures, time on a log axis only where the times span a decade (over a narrower range its labels
// run together); the page's links to them
std::string draw_charts(const std::vector<Chart>& charts, const std::vector<ReportConfiguration>& configs,
                        ExperimentContext& ctx) {
  double lo = 0, hi = 0;
  for (const auto& c : configs)
    if (!diverged(c.median)) lo = lo > 0 ? std::min(lo, ms(c.median)) : ms(c.median), hi = std::max(hi, ms(c.median));
  const bool logx = lo > 0 && hi > 10 * lo;
  std::string pictures;
  for (const Chart& ch : charts) {
    nlohmann::json series = nlohmann::json::array();
    for (const auto& [collider, xy] : ch.points)
      series.push_back({{"label", collider}, {"x", xy.first}, {"y", xy.second}, {"style", "o"}});
    if (!series.empty() && ctx.chart(ch.name, {{"title", std::string(ch.ylabel) + " against time"},
                                               {"xlabel", "ms per iteration (median)"},
                                               {"ylabel", ch.ylabel},
                                               {"logx", logx},
                                               {"series", series}}))
      pictures += "![" + std::string(ch.name) + "](" + ch.name + ".png) ";
  }
  return pictures;
}

// the summary's line on the drape error: the reference, the closest configuration, those without an end state
std::string drape_line(const std::vector<ReportConfiguration>& configs, const ReportReference& reference,
                       std::size_t without) {
  const ReportConfiguration* closest = nullptr;
  for (const auto& c : configs)
    if (c.median.contains("drape_error_rms_mm") && !diverged(c.median) &&
        (!closest || field(c.median, "drape_error_rms_mm") < field(closest->median, "drape_error_rms_mm")))
      closest = &c;
  std::string line = "Drape error against the reference " + reference.name +
                     " (the symmetric vertex-to-surface distance of the two end states): ";
  line += closest ? "the closest is " + closest->label + ", RMS " + num(field(closest->median, "drape_error_rms_mm"), 2) +
                        " mm, max " + num(field(closest->median, "drape_error_max_mm"), 1) + " mm"
                  : "no configuration carries its end state";
  if (closest && without)
    line += "; " + std::to_string(without) + (without == 1 ? " configuration carries" : " configurations carry") +
            " no end state (run or sweep with --end-state)";
  return line + ".";
}

}  // namespace

std::size_t write_sweep_report(const nlohmann::json& doc, const std::string& source, const std::string& out,
                               const ReportReference* reference) {
  std::vector<ReportConfiguration> configs = report_configurations(doc);
  std::vector<std::string> header{"configuration", "collider", "vertices", "runs", "ms/iteration (median)",
                                  "spread [%]", "total [s]", "frames/s", "inside [%]", "depth max [mm]",
                                  "crossings [%]", "seam gap [mm]", "strain max [%]"};
  if (reference) header.push_back("drape error RMS / max [mm]");
  header.push_back("meets the limits");
  MarkdownTable t(header);
  std::vector<Chart> charts = accuracy_charts(reference != nullptr);
  nlohmann::json medians = nlohmann::json::array();
  std::size_t without_end_state = 0;
  for (auto& c : configs) {
    nlohmann::json& r = c.median;
    const bool div = diverged(r), drape = reference && add_drape_error(r, *reference);
    without_end_state += reference && !drape;
    const auto figure = [&](double v, int digits) { return div ? std::string("-") : num(v, digits); };
    std::vector<std::string> cells{c.label, text(r, "collider"), num(field(r, "vertices"), 0), std::to_string(c.runs),
                                   num(ms(r), 3), c.runs > 1 ? num(c.spread_pct, 1) : "-", num(field(r, "total_s"), 3),
                                   r.contains("fps") ? num(field(r, "fps"), 1) : "-", figure(charts[0].value(r), 2),
                                   figure(worst(r, "depth_max_mm", "worst_frame_depth_max_mm"), 1),
                                   figure(charts[1].value(r), 2), figure(field(r, "seam_gap_max_mm"), 1),
                                   figure(charts[2].value(r), 1)};
    if (reference)
      cells.push_back(drape && !div ? num(field(r, "drape_error_rms_mm"), 2) + " / " +
                                          num(field(r, "drape_error_max_mm"), 1)
                                    : "-");
    cells.push_back(verdict(r));
    t.row(cells);
    medians.push_back(r);
    medians.back().erase("end_positions");
    medians.back().erase("end_quads");
    if (div) continue;
    for (Chart& ch : charts) {
      if (ch.name == std::string("sweep-drape-error") && !drape) continue;
      auto& [x, y] = ch.points[text(r, "collider")];
      x.push_back(ms(r));
      y.push_back(ch.value(r));
    }
  }
  const std::size_t failed = doc.contains("failed") && doc["failed"].is_array() ? doc["failed"].size() : 0;
  ExperimentContext ctx(out, false, 1);  // for its charts
  const std::string pictures = draw_charts(charts, configs, ctx);
  std::vector<std::string> lines = summary(configs, source, failed);
  if (reference) lines.insert(lines.end() - 1, drape_line(configs, *reference, without_end_state));
  const AccuracyLimits& l = kAccuracyLimits;
  const nlohmann::json context = doc.value("context", nlohmann::json::object());
  std::string md = "# sweep: Report of " + source + "\n\n" + markdown_summary(lines) + "Written by `clothbench report " +
                   source + "`; the runs' machine and build, from the document: " + text(context, "cpu_model") + ", " +
                   num(field(context, "num_cpus"), 0) + " cores; git " + text(context, "git_sha") + "; " +
                   text(context, "date") +
                   ".\n\nOne row per configuration: the run with the median time per iteration among its runs, spread "
                   "= (slowest - fastest) / median. Accuracy from the exact oracle at the end state or, on a moving "
                   "body, its worst measured frame; a run meets the limits when it keeps inside at most " +
                   num(l.inside_pct, 1) + " %, depth " + num(l.depth_mm, 0) + " mm, crossings " +
                   num(l.crossings_pct, 0) + " %, seam gap " + num(l.seam_gap_mm, 0) +
                   " mm and strain at most its threshold + " + num(100 * l.strain_excess, 0) +
                   " % (every frame when walking), as the run itself judged.\n\n" + pictures + "\n\n" + t.str();
  if (failed) {
    md += "\nFailed or missing points:\n\n";
    for (const auto& f : doc["failed"])
      md +=
          "- " + text(f, "name") + ": " + text(f, "error") + " (exit status " + num(field(f, "exit_status"), 0) + ")\n";
  }
  write_text_file(ctx.path("sweep.md"), md);
  write_text_file(ctx.path("sweep.json"), nlohmann::json{{"context", context}, {"benchmarks", medians}}.dump(2) + "\n");
  write_html_report(out, false);
  return configs.size();
}

}  // namespace clothbench
