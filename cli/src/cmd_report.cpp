// clothbench report INPUT --out DIR: a user's runs as the built-in experiments' page (summary first, table, charts of
// time against inside, crossings and strain, index.html). INPUT is a sweep folder, merge's file or run --json's.
#include <cstdio>
#include <filesystem>

#include "clothbench/bench/report.hpp"
#include "clothbench/bench/sweep.hpp"
#include "clothbench/experiments/sweep_report.hpp"
#include "commands.hpp"

namespace clothbench::cli {

namespace {

struct ReportArgs {
  std::string input, out;
};

int report(const ReportArgs& a) {
  const bool folder = std::filesystem::is_directory(a.input);
  const nlohmann::json doc = folder ? merge_sweeps({a.input}, false) : read_json_file(a.input);
  const std::size_t configs = write_sweep_report(doc, a.input, a.out);
  std::printf("report of %zu configuration(s) from %s: %s/sweep.md, %s/index.html\n", configs, a.input.c_str(),
              a.out.c_str(), a.out.c_str());
  return 0;
}

}  // namespace

void add_report_command(CLI::App& app, Action& action) {
  auto a = std::make_shared<ReportArgs>();
  auto* cmd = app.add_subcommand("report",
                                 "Write the page of the built-in experiments for your own runs: a summary (the fastest "
                                 "configuration within every limit), the table with spreads, charts of time against "
                                 "inside, crossings and strain, and index.html");
  cmd->add_option("input", a->input, "a sweep folder, merge's JSON or run --json's JSON")->required();
  cmd->add_option("--out", a->out, "the report's folder (sweep.md, sweep.json, charts, index.html)")->required();
  cmd->callback([&action, a] { action = [a] { return report(*a); }; });
}

}  // namespace clothbench::cli
