#pragma once
/// A RunResult as JSON and back, every measured field and, when asked, the cloth's end state (mesh positions
/// and quads, what the drape error needs; never final_body): what a run in another process hands back
/// (ExperimentContext::prefetch).
#include <nlohmann/json.hpp>
#include <optional>

#include "clothbench/bench/runner.hpp"

namespace clothbench {

nlohmann::json to_json(const RunResult& r, bool end_state = false);
/// The cloth's end state (positions, quads) into `j` as "end_positions" and "end_quads", and back: a mesh with just
/// those two, or nothing when `j` carries none. Throws InputError on sizes that do not fit.
void put_end_state(nlohmann::json& j, const ClothMesh& mesh);
std::optional<ClothMesh> end_state_from_json(const nlohmann::json& j);
/// The result `to_json` wrote; final_body stays empty, and mesh too unless the end state was written.
RunResult run_result_from_json(const nlohmann::json& j);

}  // namespace clothbench
