#pragma once
// What the claims experiment's two files share: a claim's row and the rows of a page an experiment wrote before
// it. claims.cpp measures its claims and reads walking-t2's page; claims_speed.cpp judges image space's speed on
// dressing-t1's page and the placements; claims_pages.cpp judges the claims that rest on minimal's, pareto's,
// dressing-f8's and walking-f8's pages.
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "clothbench/experiments/experiment.hpp"

namespace clothbench::claim_rows {

// one row of the claims table
struct Claim {
  std::string source, claim, experiment, numbers, verdict;
};

// what a claim that reads another experiment's page says when that page has not been written
inline const std::string kNotRun = "not measured: run `clothbench reproduce` (all experiments) first";

// rows of OUT/ID.json by name; empty when the experiment has not been run into OUT
std::map<std::string, nlohmann::json> rows_of(ExperimentContext& ctx, const std::string& id);

// the garments the claims sew at jittered placements, and one garment, regime and collider sewn at them (claims.cpp)
std::vector<std::pair<std::string, int>> placement_garments(const ExperimentContext& ctx);
std::vector<const RunResult*> placements(ExperimentContext& ctx, const std::string& scene, int vertices,
                                         const std::string& regime, const std::string& collider);

// walking and dressing Table 1: image space's CD&R 2-3x faster than object space's (claims_speed.cpp)
Claim speed_claim(ExperimentContext& ctx);

// dressing Table 2, section 6: face-body queries lower the minimum vertex count (minimal's page)
Claim face_queries_claim(ExperimentContext& ctx);
// dressing section 7: image space with face queries needs fewer vertices than the box tree (minimal's page)
Claim box_tree_claim(ExperimentContext& ctx);
// beyond the papers: image space with six views against embree's crossings and cost (pareto's page)
Claim views_claim(ExperimentContext& ctx);
// dressing Fig. 8: time per iteration grows linearly with the cloth's vertices (dressing-f8's page)
Claim linear_claim(ExperimentContext& ctx);
// walking Fig. 8: the directional limit beats averaging on a moving sphere (walking-f8's page)
Claim directional_claim(ExperimentContext& ctx);

}  // namespace clothbench::claim_rows
