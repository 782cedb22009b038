// The rows other pages read (claims, the report's answers) by the names row_names makes: present in the committed
// results/, which come from the committed code, so a row renamed on one side only fails here.
#include <gtest/gtest.h>

#include <fstream>
#include <set>
#include <string>

#include <nlohmann/json.hpp>

#include "clothbench/experiments/row_names.hpp"

namespace clothbench {
namespace {

std::set<std::string> row_names_in(const std::string& id) {
  std::ifstream in(std::string(CLOTHBENCH_SOURCE_DIR) + "/results/" + id + ".json");
  std::set<std::string> names;
  if (!in) return names;
  const auto doc = nlohmann::json::parse(in, nullptr, false);
  if (doc.is_discarded() || !doc.contains("benchmarks")) return names;
  for (const auto& r : doc["benchmarks"]) names.insert(r.value("name", ""));
  return names;
}

TEST(RowNames, ClaimsFindTheRowsTheTablesWrote) {
  const auto t1 = row_names_in("dressing-t1");
  ASSERT_FALSE(t1.empty()) << "results/dressing-t1.json";
  for (const char* garment : {"shirt", "dress"})
    for (const char* collider : {"is-cpu", "bbtree", "embree"})
      EXPECT_TRUE(t1.count(row_names::dressing_t1(garment, collider))) << row_names::dressing_t1(garment, collider);
  EXPECT_TRUE(t1.count(row_names::dressing_t1("shirt", "is-cpu", "papers")));
  const auto t2 = row_names_in("walking-t2");
  ASSERT_FALSE(t2.empty()) << "results/walking-t2.json";
  for (const char* garment : {"skirt", "dress_sleeves"}) {
    EXPECT_TRUE(t2.count(row_names::walking_t2(garment, "is-cpu"))) << garment;
    EXPECT_TRUE(t2.count(row_names::walking_t2(garment, "is-cpu", row_names::kWithoutEq16))) << garment;
  }
}

}  // namespace
}  // namespace clothbench
