#pragma once
/// `clothbench report`: the page the built-in experiments write (a summary first, the table, charts of time against
/// each accuracy figure, the HTML page) for any Google Benchmark document of run rows: a user's `sweep` (merged),
/// `merge`'s file or `run --json`'s.
#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "clothbench/sim/cloth.hpp"

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

/// A reference drape for the drape error (bench/drape_error.hpp): its cloth at the end, and what the page calls it.
struct ReportReference {
  ClothMesh cloth;
  std::string name;
};

/// The reference in a results document (run --json --end-state's): the first run row that carries its end state.
/// Throws InputError naming `path` when no row does.
ReportReference report_reference(const nlohmann::json& doc, const std::string& path);

/// Writes OUT/sweep.md (summary, table, failed points), OUT/sweep.json (the median rows, without end states), the
/// charts OUT/sweep-{inside,crossings,strain}.png and OUT/index.html; `source` names the input on the page. With a
/// `reference`, every configuration whose median row carries its end state (--end-state) gets its drape error
/// against it: a column, the median row's drape_error_rms_mm and drape_error_max_mm, and the chart
/// OUT/sweep-drape-error.png. Returns the number of configurations.
std::size_t write_sweep_report(const nlohmann::json& doc, const std::string& source, const std::string& out,
                               const ReportReference* reference = nullptr);

}  // namespace clothbench
