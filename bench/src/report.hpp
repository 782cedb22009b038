#pragma once
/// Results as DESIGN.md's "Result fields": Google Benchmark's JSON layout (context + benchmarks[])
/// with speed and accuracy counters in every row; machine context; atomic file writes.
#include <nlohmann/json.hpp>
#include <string>

#include "runner.hpp"

namespace clothbench {

/// The machine and build: date, host, CPU model, cores, compiler, flags, build type, git SHA.
nlohmann::json machine_context();

/// One benchmarks[] row named `name`: iterations, real_time = ms per iteration, and the counters
/// of DESIGN.md. Fields that do not apply (accuracy of a diverged run, fps of a static body) are
/// omitted, never faked.
nlohmann::json result_row(const RunResult& r, const std::string& name);

/// {"context": machine_context(), "benchmarks": rows}.
nlohmann::json result_document(const nlohmann::json& rows);

/// Writes text to PATH.tmp then renames it (no half-written file); throws InputError naming the
/// path when the directory is not writable.
void write_text_file(const std::string& path, const std::string& text);

/// A number with `digits` decimals, or "-" for NaN.
std::string num(double v, int digits);

}  // namespace clothbench
