#pragma once
/// A RunResult as JSON and back, every measured field and, when asked, the cloth's end state (mesh positions
/// and quads, what the drape error needs; never final_body): what a run in another process hands back
/// (ExperimentContext::prefetch).
#include <nlohmann/json.hpp>

#include "clothbench/bench/runner.hpp"

namespace clothbench {

nlohmann::json to_json(const RunResult& r, bool end_state = false);
/// The result `to_json` wrote; final_body stays empty, and mesh too unless the end state was written.
RunResult run_result_from_json(const nlohmann::json& j);

}  // namespace clothbench
