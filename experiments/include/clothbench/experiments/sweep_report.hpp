#pragma once
/// `clothbench report`: the page the built-in experiments write (a summary first, the table, charts of time against
/// each accuracy figure, the HTML page) for any Google Benchmark document of run rows: a user's `sweep` (merged),
/// `merge`'s file or `run --json`'s.
#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace clothbench {

/// One configuration of a document: its rows (every repetition), the run with the median time among them.
struct ReportConfiguration {
  std::string label;      ///< the rows' name, with its configuration hash when two configurations share it
  nlohmann::json median;  ///< the row of the median time (ms per iteration)
  int runs = 0;           ///< rows of this configuration
  double spread_pct = 0;  ///< (slowest - fastest) / median [%]
};

/// The configurations of `doc` ("benchmarks": rows of run_type "iteration"; aggregates are left out, recomputed
/// here), in the document's order. Rows of one name but different `config_hash` are different configurations.
/// Throws InputError when `doc` has no "benchmarks" array or no run row.
std::vector<ReportConfiguration> report_configurations(const nlohmann::json& doc);

/// Writes OUT/sweep.md (summary, table, failed points), OUT/sweep.json (the median rows), the charts
/// OUT/sweep-{inside,crossings,strain}.png and OUT/index.html; `source` names the input on the page. Returns the
/// number of configurations.
std::size_t write_sweep_report(const nlohmann::json& doc, const std::string& source, const std::string& out);

}  // namespace clothbench
