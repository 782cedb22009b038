#pragma once
// The names of the rows one experiment writes and another reads (claims, the report's answers): made in one place,
// so that writer and reader cannot drift apart and a renamed row is not silently "not measured".
#include <string>

#include "clothbench/experiments/experiment.hpp"

namespace clothbench::row_names {

// the paper tables' rows: TABLE/GARMENT/COLLIDER[/REGIME][/ours] (the regime left out when stable; "ours": our own
// detection in place of the papers')
inline std::string paper_table(const std::string& table, const std::string& garment, const std::string& collider,
                               const std::string& regime = "stable", bool ours = false) {
  return table + "/" + garment + "/" + collider + regime_suffix(regime, "/") + (ours ? "/ours" : "");
}

inline std::string dressing_t1(const std::string& garment, const std::string& collider,
                               const std::string& regime = "stable", bool ours = false) {
  return paper_table("dressing-t1", garment, collider, regime, ours);
}

// walking-t2's variants read elsewhere, by their row suffix
inline constexpr const char* kWithoutEq16 = "/noeq16";  // the stable regime without walking Eq. 16

// walking-t2/GARMENT/COLLIDER[VARIANT]
inline std::string walking_t2(const std::string& garment, const std::string& collider,
                              const std::string& variant = "") {
  return "walking-t2/" + garment + "/" + collider + variant;
}

// walking-f8/tablecloth/LIMIT: the tablecloth on the moving sphere under one strain limiter
inline std::string walking_f8(const std::string& limit) { return "walking-f8/tablecloth/" + limit; }

// dressing-f8/GARMENT-VERTICES/COLLIDER: one size of a garment's time-per-iteration series
inline std::string dressing_f8(const std::string& garment, int vertices, const std::string& collider) {
  return "dressing-f8/" + garment + "-" + std::to_string(vertices) + "/" + collider;
}

}  // namespace clothbench::row_names
