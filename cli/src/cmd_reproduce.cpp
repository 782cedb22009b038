// clothbench reproduce [--only ID,...] [--out DIR] [--quick] [--repetitions N]
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <sstream>

#include "clothbench/bench/registry.hpp"
#include "clothbench/bench/report.hpp"
#include "clothbench/collide_is/map_set.hpp"
#include "clothbench/experiments/experiment.hpp"
#include "clothbench/experiments/history.hpp"
#include "clothbench/experiments/html_report.hpp"
#include "clothbench/io/errors.hpp"
#include "clothbench/sim/timer.hpp"
#include "commands.hpp"

namespace clothbench::cli {

namespace {

struct ReproduceArgs {
  std::vector<std::string> only;
  std::string out = "results";
  bool quick = false;
  int repetitions = 1;
  int jobs = 1;
};

// results/README.md's last section: each experiment's run against its previous one in history.jsonl, and
// its trend chart history-ID.png
std::string since_previous(ExperimentContext& ctx, const std::vector<std::pair<std::string, double>>& done) {
  const std::vector<nlohmann::json> history = read_history(ctx.path("history.jsonl"));
  MarkdownTable t({"ID", "previous run", "time per iteration, this / previous (geometric mean; range)",
                   "configurations compared", "verdicts changed", "added / removed", "trend"});
  for (const auto& [id, seconds] : done) {
    const std::vector<nlohmann::json> entries = entries_of(history, id, ctx.quick());
    if (entries.empty()) continue;
    const std::string chart = "history-" + id;
    const std::string trend = ctx.chart(chart, trend_chart(entries, id)) ? "[" + chart + ".png](" + chart + ".png)" : "-";
    if (entries.size() < 2) {
      t.row({id, "none (first run in the history)", "-", "-", "-", "-", trend});
      continue;
    }
    const nlohmann::json& before = entries[entries.size() - 2];
    const HistoryChange c = compare_entries(before, entries.back());
    t.row({id, before.value("git_sha", "?") + ", " + before.value("date", "?"),
           c.common ? num(c.time_ratio, 3) + " (" + num(c.ratio_min, 2) + "-" + num(c.ratio_max, 2) + ")" : "-",
           std::to_string(c.common), std::to_string(c.verdict_changed),
           std::to_string(c.added) + " / " + std::to_string(c.removed), trend});
  }
  return "## Since the previous run\n\nEvery `reproduce` appends each experiment's key figures (per configuration: time "
         "per iteration, CD&R, CS, accuracy, verdict) with the git SHA and date to `history.jsonl`. Below, this run "
         "against the previous run of the same experiment (quick runs only against quick runs); wall times on this shared machine "
         "drift by about ±20 % between runs, so only changes well beyond that, or changed verdicts, mean something "
         "(`clothbench compare` with repetitions is the statistical gate).\n\n" +
         t.str();
}

// what the OpenGL colliders draw on (GL_VENDOR, GL_RENDERER), and whether any of it is a GPU
std::string opengl_devices() {
  std::string list;
  bool gpu = false;
  for (const std::string& name : colliders([](const ColliderInfo& c) { return c.needs != Needs::kNothing; })) {
    try {
      const std::string device = make_collider(name)->device();
      gpu = gpu || !cpu_device(device);
      list += "- `" + name + "`: " + device + "\n";
    } catch (const std::exception& e) {
      list += "- `" + name + "`: no context: " + std::string(e.what()) + "\n";
    }
  }
  if (list.empty()) return {};
  return std::string("OpenGL devices (image space; every JSON row that used one names it as `device`)") +
         (gpu ? ":" : ", **no GPU**: the OpenGL timings are Mesa's CPU rasteriser (llvmpipe):") + "\n\n" + list + "\n";
}

// the wall times [s] the index `readme` lists, by experiment ID (its rows: ID, what, [ID.md](ID.md), ..., time)
std::map<std::string, std::string> listed_wall_times(const std::string& readme) {
  std::map<std::string, std::string> times;
  std::ifstream in(readme);
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> cells;
    std::stringstream s(line);
    for (std::string cell; std::getline(s, cell, '|');) cells.push_back(cell);
    // "| id | what | table | ... | time |" splits into an empty first cell and the table's
    if (cells.size() < 6 || line.rfind("| ", 0) != 0) continue;
    const auto trim = [](std::string v) {
      v.erase(0, v.find_first_not_of(' '));
      return v.erase(v.find_last_not_of(' ') + 1);
    };
    const std::string id = trim(cells[1]);
    if (trim(cells[3]) == "[" + id + ".md](" + id + ".md)") times[id] = trim(cells.back());
  }
  return times;
}

// the git SHA a page's data was written at (its JSON's context), "?" when unreadable
std::string page_git_sha(const std::string& json_path) {
  try {
    std::ifstream in(json_path);
    return nlohmann::json::parse(in).at("context").at("git_sha").get<std::string>();
  } catch (const std::exception&) {
    return "?";
  }
}

// results/README.md: the index of every experiment page in `out` (those not run now keep the wall time the index
// listed them with), the git SHA each was written at, and the machine
void write_index(ExperimentContext& ctx, const std::string& out,
                 const std::vector<std::pair<std::string, double>>& done, bool quick) {
  std::map<std::string, std::string> seconds = listed_wall_times(out + "/README.md");
  for (const auto& [id, s] : done) seconds[id] = num(s, 1);
  const nlohmann::json c = machine_context();
  std::ostringstream md;
  md << "# clothbench results\n\nWritten by `clothbench reproduce" << (quick ? " --quick" : "")
     << "` (`make reproduce`); never edited by hand. Regenerate with `make reproduce`, or one experiment with "
        "`build/bin/clothbench reproduce --only ID`.\n\n"
     << "Machine: " << c["cpu_model"].get<std::string>() << ", " << c["num_cpus"] << " cores, host "
     << c["host_name"].get<std::string>() << "; compiler " << c["compiler"].get<std::string>() << ", "
     << c["build_type"].get<std::string>() << ", flags `" << c["cxx_flags"].get<std::string>() << "`; git "
     << c["git_sha"].get<std::string>() << "; " << c["date"].get<std::string>() << " (the last `reproduce`: "
     << (done.size() == experiments().size() ? "every page" : std::to_string(done.size()) + " of the pages")
     << "; each page says its own).\n\n"
     << opengl_devices();
  MarkdownTable t({"ID", "what", "table", "data", "git", "wall time [s]"});
  for (const auto& e : experiments()) {
    if (!std::filesystem::exists(out + "/" + e.id + ".md")) continue;
    const auto listed = seconds.find(e.id);
    t.row({e.id, e.title, "[" + e.id + ".md](" + e.id + ".md)", "[" + e.id + ".json](" + e.id + ".json)",
           page_git_sha(out + "/" + e.id + ".json"), listed == seconds.end() ? "-" : listed->second});
  }
  md << t.str() << "\nCharts are `ID.png`; pictures of dressed bodies are under `pictures/`; maps under `maps/`; "
     << "garment meshes under `garments/`.\n\n"
     << since_previous(ctx, done);
  write_text_file(out + "/README.md", md.str());
}

// the experiment IDs of `reproduce --help`, from the registry, with their titles
std::string experiment_list() {
  std::size_t width = 0;
  for (const auto& e : experiments()) width = std::max(width, e.id.size());
  std::ostringstream s;
  s << "Experiments (--only ID,...; in the order they run):\n";
  for (const auto& e : experiments()) s << "  " << e.id << std::string(width + 2 - e.id.size(), ' ') << e.title << "\n";
  return s.str();
}

int reproduce(const ReproduceArgs& a) {
  std::set<std::string> wanted;
  for (const auto& list : a.only) {
    std::stringstream s(list);
    for (std::string id; std::getline(s, id, ',');) wanted.insert(id);
  }
  std::string known;
  for (const auto& e : experiments()) known += (known.empty() ? "" : ", ") + e.id;
  for (const auto& id : wanted) {
    bool found = false;
    for (const auto& e : experiments()) found = found || e.id == id;
    if (!found) throw InputError("--only: unknown experiment '" + id + "' (known: " + known + ")");
  }
  ExperimentContext ctx(a.out, a.quick, a.repetitions, a.jobs);
  // fail early on an unwritable output folder
  write_text_file(ctx.path(".write-test"), "");
  std::remove(ctx.path(".write-test").c_str());
  std::vector<std::pair<std::string, double>> done;
  for (const auto& e : experiments()) {
    if (!wanted.empty() && !wanted.count(e.id)) continue;
    std::cerr << "[" << e.id << "] " << e.title << "\n";
    Stopwatch clock;
    e.run(ctx);
    done.emplace_back(e.id, clock.ms() / 1e3);
    std::cerr << "[" << e.id << "] done in " << num(clock.ms() / 1e3, 1) << " s\n";
  }
  write_index(ctx, a.out, done, a.quick);
  // results/index.html from whatever the folder now holds (screenshots of it on full runs)
  write_html_report(a.out, wanted.empty());
  return 0;
}

}  // namespace

void add_reproduce_command(CLI::App& app, Action& action) {
  auto args = std::make_shared<ReproduceArgs>();
  auto* cmd = app.add_subcommand("reproduce", "Regenerate the papers' tables and charts with our figures beside theirs");
  cmd->add_option("--only", args->only, "comma-separated experiment IDs (default: all; listed below)");
  cmd->footer(experiment_list);
  cmd->add_option("--out", args->out, "output folder")->capture_default_str();
  cmd->add_flag("--quick", args->quick, "fewer iterations and sizes, same code paths (smoke test)");
  cmd->add_option("--repetitions", args->repetitions, "runs per configuration: tables show the median run; the JSON has every run's row and the aggregates (mean, median, stddev, cv)")
      ->check(CLI::Range(1, 100))
      ->capture_default_str();
  cmd->add_option("--jobs", args->jobs,
                  "worker processes for the grids of pareto, minimal and stability (default 1: every run in this "
                  "process; make reproduce passes the cores, the grids' timings then measured under shared cores)")
      ->check(CLI::Range(1, 256));
  cmd->callback([&action, args] { action = [args] { return reproduce(*args); }; });
}

}  // namespace clothbench::cli
