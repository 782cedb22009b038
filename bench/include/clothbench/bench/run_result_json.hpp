#pragma once
/// A RunResult as JSON and back, every measured field but the end state's geometry (final_body, mesh):
/// what a run in another process hands back (ExperimentContext::prefetch).
#include <nlohmann/json.hpp>

#include "clothbench/bench/runner.hpp"

namespace clothbench {

nlohmann::json to_json(const RunResult& r);
/// The result `to_json` wrote; final_body and mesh stay empty.
RunResult run_result_from_json(const nlohmann::json& j);

}  // namespace clothbench
