#pragma once
/// results/history.jsonl: one line per experiment run by `reproduce` (date, git SHA, quick or not, and
/// per configuration its time per iteration, CD&R, CS and accuracy), the trend of each table over those
/// runs, and what changed since the previous run.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace clothbench {

/// The key figures of an experiment's rows (one per configuration: a run's row, or with repetitions
/// their median aggregate) as a history entry.
nlohmann::json history_entry(const std::string& id, const nlohmann::json& rows, const nlohmann::json& context,
                             bool quick);

/// Appends the entry as one line to PATH (created when missing).
void append_history(const std::string& path, const nlohmann::json& entry);

/// Every entry of PATH in file order (none when it does not exist); a malformed line is an InputError
/// naming the line.
std::vector<nlohmann::json> read_history(const std::string& path);

/// Two entries of one experiment compared: the geometric mean of new/old time per iteration over the
/// configurations both have, its range, and the configurations whose verdict changed, added or removed.
struct HistoryChange {
  int common = 0, added = 0, removed = 0, verdict_changed = 0;
  double time_ratio = 1, ratio_min = 1, ratio_max = 1;
};
HistoryChange compare_entries(const nlohmann::json& before, const nlohmann::json& after);

/// The entries of experiment `id` that were quick runs or not, as `quick` says, oldest first.
std::vector<nlohmann::json> entries_of(const std::vector<nlohmann::json>& history, const std::string& id,
                                       bool quick = false);

/// The chart spec (experiments/plot/plot.py) of an experiment's trend over its entries: the time index (the
/// geometric mean of new/old time per iteration over common configurations, chained from the first
/// entry = 1) and the share of configurations meeting the accuracy limits.
nlohmann::json trend_chart(const std::vector<nlohmann::json>& entries, const std::string& id);

}  // namespace clothbench
