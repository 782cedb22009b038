// The report rows (bench/src/report.cpp): time units, repetition aggregates, the accuracy limits' verdict,
// the document around the rows, numbers in tables.
#include "clothbench/bench/report.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace clothbench {
namespace {

using nlohmann::json;

TEST(Report, SetTimesPicksTheUnitThatKeepsRealTimeAtOneOrMore) {
  json row;
  set_times(row, 2.5, 1.0);
  EXPECT_EQ(row["time_unit"], "ms");
  EXPECT_DOUBLE_EQ(row["real_time"].get<double>(), 2.5);
  EXPECT_DOUBLE_EQ(row["cpu_time"].get<double>(), 1.0);
  set_times(row, 0.0025, 0.001);
  EXPECT_EQ(row["time_unit"], "us");
  EXPECT_DOUBLE_EQ(row["real_time"].get<double>(), 2.5);
  set_times(row, 2.5e-6, 1e-6);
  EXPECT_EQ(row["time_unit"], "ns");
  EXPECT_NEAR(row["real_time"].get<double>(), 2.5, 1e-9);
  EXPECT_NEAR(row_time_ms(row, "real_time"), 2.5e-6, 1e-15);
  EXPECT_NEAR(row_time_ms(row, "cpu_time"), 1e-6, 1e-15);
  set_times(row, 0, 0);
  EXPECT_EQ(row["time_unit"], "ms");
  set_times(row, 2.5, 1.0, "us");  // a unit given is kept
  EXPECT_EQ(row["time_unit"], "us");
  EXPECT_DOUBLE_EQ(row["real_time"].get<double>(), 2500);
  EXPECT_DOUBLE_EQ(unit_per_ms("s"), 1e-3);
  EXPECT_TRUE(std::isnan(unit_per_ms("min")));
}

TEST(Report, RepetitionRowsFollowGoogleBenchmarksLayout) {
  std::vector<json> runs;
  for (double ms : {3.0, 1.0, 2.0}) {
    json row{{"name", "case"}, {"run_type", "iteration"}, {"iterations", 10}};
    set_times(row, ms, ms / 2);
    runs.push_back(row);
  }
  const json out = repetition_rows(runs);
  ASSERT_EQ(out.size(), 3u + 4u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(out[i]["run_name"], "case");
    EXPECT_EQ(out[i]["repetitions"], 3);
    EXPECT_EQ(out[i]["repetition_index"], i);
  }
  const std::vector<std::string> aggregates{"mean", "median", "stddev", "cv"};
  for (std::size_t k = 0; k < aggregates.size(); ++k) {
    const json& a = out[3 + k];
    EXPECT_EQ(a["name"], "case_" + aggregates[k]);
    EXPECT_EQ(a["run_type"], "aggregate");
    EXPECT_EQ(a["aggregate_name"], aggregates[k]);
    EXPECT_FALSE(a.contains("repetition_index"));
  }
  EXPECT_DOUBLE_EQ(row_time_ms(out[3], "real_time"), 2.0);  // mean
  EXPECT_DOUBLE_EQ(row_time_ms(out[4], "real_time"), 2.0);  // median
  EXPECT_DOUBLE_EQ(row_time_ms(out[4], "cpu_time"), 1.0);
  EXPECT_EQ(out[6]["aggregate_unit"], "percentage");
  // one run: its row as it is
  const json one = repetition_rows({runs[0]});
  ASSERT_EQ(one.size(), 1u);
  EXPECT_EQ(one[0], runs[0]);
}

TEST(Report, RepetitionRowsForAnyNumberOfRuns) {
  // the aggregates once copied their fields from a reference into the array they were appended to, which the
  // appending moved: a crash (or garbage) for most counts (run --repetitions 2 failed every time)
  for (std::size_t n = 1; n <= 12; ++n) {
    std::vector<json> runs;
    for (std::size_t i = 0; i < n; ++i) {
      json row{{"name", "case"}, {"run_type", "iteration"}, {"iterations", 10}, {"vertices", 100}};
      set_times(row, 1.0 + double((i * 7) % n), 0.5);
      runs.push_back(row);
    }
    const json out = repetition_rows(runs);
    ASSERT_EQ(out.size(), n == 1 ? 1u : n + 4u) << n;
    for (std::size_t k = n; k < out.size(); ++k) {
      EXPECT_EQ(out[k]["run_type"], "aggregate") << n;
      EXPECT_EQ(out[k]["vertices"], 100) << n;
      EXPECT_EQ(out[k]["name"].get<std::string>().rfind("case_", 0), 0u) << n;
    }
  }
}

TEST(Report, LimitMissesNameEachLimitMissed) {
  RunResult r;
  EXPECT_TRUE(limit_misses(r).empty());
  EXPECT_EQ(limits_cell(r), "yes");
  r.accuracy.inside_pct = 6.1;
  r.accuracy.crossings_pct = 1.9;
  const std::vector<std::string> misses = limit_misses(r);
  ASSERT_EQ(misses.size(), 2u);
  EXPECT_EQ(misses[0], "inside 6.1 % > 0.5 %");
  EXPECT_EQ(misses[1], "crossings 1.9 % > 1 %");
  EXPECT_EQ(limits_cell(r), "no: inside 6.1 % > 0.5 %; crossings 1.9 % > 1 %");
  // strain counts only for runs with a super-elasticity limit
  EXPECT_EQ(limits_text(r), "inside <= 0.5 %, depth <= 5 mm, crossings <= 1 %, seam gap <= 2 mm");
  r.strain_threshold = 0.1;
  r.strain_max = 0.2;
  EXPECT_EQ(limit_misses(r).size(), 3u);
  EXPECT_EQ(limit_misses(r, false).size(), 2u);
  r.divergence = Divergence{};
  EXPECT_EQ(limit_misses(r), std::vector<std::string>{"diverged"});
  // a value just past its limit shows as many decimals as it takes to read it past
  RunResult near;
  near.accuracy.inside_pct = 0.5031;
  near.accuracy.depth_max_mm = 5.0004;
  EXPECT_EQ(limit_misses(near), (std::vector<std::string>{"inside 0.503 % > 0.5 %", "depth 5.0004 mm > 5 mm"}));
}

TEST(Report, AWalkThatStartsWithItsSeamsOpenMissesTheSeamGap) {
  // the seams closed by the end of the walk, open when its measured window started: the garment was not dressed
  RunResult r;
  r.seam_gap_max_mm = 0.0;
  r.window_seam_gap_mm = 2.8;
  EXPECT_EQ(limit_misses(r), std::vector<std::string>{"seam gap 2.8 mm > 2 mm"});
  r.window_seam_gap_mm = 1.5;
  EXPECT_TRUE(limit_misses(r).empty());
}

TEST(Report, ResultDocumentCarriesTheMachineContext) {
  const json rows = json::array({json{{"name", "a"}}});
  const json doc = result_document(rows);
  EXPECT_EQ(doc["benchmarks"], rows);
  for (const char* key : {"date", "host_name"}) EXPECT_TRUE(doc["context"].contains(key)) << key;
}

TEST(Report, NumbersKeepTheirDecimalsAndNanIsADash) {
  EXPECT_EQ(num(1.23456, 2), "1.23");
  EXPECT_EQ(num(2, 0), "2");
  EXPECT_EQ(num(std::nan(""), 1), "-");
}

}  // namespace
}  // namespace clothbench
