// results/history.jsonl: entries from result rows, reading them back, and the change between two runs.
#include "clothbench/experiments/history.hpp"

#include <gtest/gtest.h>

#include "test_support.hpp"

#include <filesystem>
#include <fstream>

#include "clothbench/bench/report.hpp"
#include "clothbench/io/errors.hpp"

namespace clothbench {
namespace {

nlohmann::json row(const std::string& name, double real_ms, int meets) {
  nlohmann::json r{{"name", name}, {"run_type", "iteration"}, {"meets_limits", meets}};
  set_times(r, real_ms, real_ms);
  return r;
}

TEST(History, AnEntryKeepsOneFigureSetPerConfigurationTheMedianOfRepetitions) {
  std::vector<nlohmann::json> reps{row("t/a", 3, 1), row("t/a", 1, 1), row("t/a", 2, 1)};
  nlohmann::json rows = repetition_rows(reps);
  rows.push_back(row("t/b", 0.5, 0));  // 500 us
  const nlohmann::json e = history_entry("t", rows, {{"date", "D"}, {"git_sha", "abc"}}, false);
  EXPECT_EQ(e["experiment"], "t");
  EXPECT_EQ(e["git_sha"], "abc");
  ASSERT_EQ(e["rows"].size(), 2u);
  EXPECT_DOUBLE_EQ(e["rows"]["t/a"]["real_ms"].get<double>(), 2.0);
  EXPECT_DOUBLE_EQ(e["rows"]["t/b"]["real_ms"].get<double>(), 0.5);  // read in its unit
  EXPECT_EQ(e["rows"]["t/b"]["meets_limits"], 0);
}

TEST(History, TwoRunsComparedByTheirCommonConfigurations) {
  const auto entry = [](std::vector<nlohmann::json> rows) { return history_entry("t", rows, {}, false); };
  const nlohmann::json before = entry({row("a", 1, 1), row("b", 2, 1), row("gone", 1, 1)});
  const nlohmann::json after = entry({row("a", 2, 1), row("b", 1, 0), row("new", 1, 1)});
  const HistoryChange c = compare_entries(before, after);
  EXPECT_EQ(c.common, 2);
  EXPECT_EQ(c.added, 1);
  EXPECT_EQ(c.removed, 1);
  EXPECT_EQ(c.verdict_changed, 1);
  EXPECT_NEAR(c.time_ratio, 1.0, 1e-12);  // sqrt(2 x 0.5)
  EXPECT_DOUBLE_EQ(c.ratio_min, 0.5);
  EXPECT_DOUBLE_EQ(c.ratio_max, 2.0);
  const nlohmann::json chart = trend_chart({before, after, after}, "t");
  EXPECT_EQ(chart["series"][0]["y"], nlohmann::json({1.0, 1.0, 1.0}));
  EXPECT_EQ(chart["xticklabels"].size(), 3u);
}

TEST(History, AppendedLinesReadBackAndAMalformedLineIsNamed) {
  const std::string path = test::temp_path("history_test.jsonl");
  std::filesystem::remove(path);
  EXPECT_TRUE(read_history(path).empty());
  append_history(path, history_entry("t", {row("a", 1, 1)}, {}, false));
  append_history(path, history_entry("u", {row("a", 1, 1)}, {}, true));
  const auto h = read_history(path);
  ASSERT_EQ(h.size(), 2u);
  EXPECT_EQ(entries_of(h, "t").size(), 1u);
  EXPECT_TRUE(entries_of(h, "u").empty());  // quick runs are a history of their own
  EXPECT_EQ(entries_of(h, "u", true).size(), 1u);
  std::ofstream(path, std::ios::app) << "{not json\n";
  try {
    read_history(path);
    FAIL() << "a malformed line must be an error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(":3: not a history entry"), std::string::npos) << e.what();
  }
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace clothbench
