// clothbench report INPUT [--reference FILE] --out DIR: a user's runs as the built-in experiments' page (summary
// first, table, charts of time against inside, crossings, strain and, given a reference drape, the drape error;
// index.html). INPUT is a sweep folder, merge's file or run --json's.
#include <cstdio>
#include <filesystem>
#include <optional>

#include "clothbench/bench/report.hpp"
#include "clothbench/bench/sweep.hpp"
#include "clothbench/experiments/sweep_report.hpp"
#include "commands.hpp"

namespace clothbench::cli {

namespace {

struct ReportArgs {
  std::string input, out, reference;
};

int report(const ReportArgs& a) {
  const bool folder = std::filesystem::is_directory(a.input);
  const nlohmann::json doc = folder ? merge_sweeps({a.input}, false) : read_json_file(a.input);
  std::optional<ReportReference> reference;
  if (!a.reference.empty()) reference = report_reference(read_json_file(a.reference), a.reference);
  const std::size_t configs = write_sweep_report(doc, a.input, a.out, reference ? &*reference : nullptr);
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
                                 "inside, crossings, strain and (--reference) the drape error, and index.html");
  cmd->add_option("input", a->input, "a sweep folder, merge's JSON or run --json's JSON")->required();
  cmd->add_option("--out", a->out, "the report's folder (sweep.md, sweep.json, charts, index.html)")->required();
  cmd->add_option("--reference", a->reference,
                  "a reference drape (run --json FILE --end-state, e.g. a finer mesh with an exact collider): the drape "
                  "error of every configuration run or swept with --end-state");
  cmd->callback([&action, a] { action = [a] { return report(*a); }; });
}

}  // namespace clothbench::cli
