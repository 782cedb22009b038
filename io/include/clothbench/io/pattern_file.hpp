#pragma once
/// The `.pattern` text format of garment patterns (documented in scenes/README.md), read into and
/// written from sim's Pattern; and what both pattern formats share (the outline limit, validation).
/// Reading a file of either format by its extension: pattern_loader.hpp.
#include <string>
#include <string_view>

#include "clothbench/sim/garment.hpp"

namespace clothbench {

/// Most points a panel outline may have once its curves are flattened, in either format: the mesher
/// measures the distance to the outline, every point of it, from every grid node (found by fuzz/).
inline constexpr int kMaxOutlinePoints = 2000;

/// Reads a `.pattern` text file. Throws InputError "FILE:LINE: what is wrong" on bad input or an unreadable file.
Pattern load_pattern_text(const std::string& path);

/// Parses `.pattern` text. `name` is the file named in error messages; the garment is called after
/// its `garment` line, else after `name` without folders and extension. Outlines are read in cm,
/// curves flattened into straight segments no longer than the file's `curve_step` (cm).
/// Throws InputError(located(name, line, message)) on the first error.
Pattern parse_pattern(std::string_view text, const std::string& name);

/// Runs sim's validate_pattern on a pattern read from `file` and returns it unchanged. Throws
/// InputError "FILE: what is wrong" (no line: the checks see the whole pattern) when it fails.
Pattern validated_pattern(Pattern pattern, const std::string& file);

/// Writes `pattern` as `.pattern` text: every outline as straight segments from its points, edges
/// named e0, e1, ... in outline order. parse_pattern reads it back to the same Pattern (numbers are
/// written with enough digits to round-trip exactly).
std::string write_pattern(const Pattern& pattern);

}  // namespace clothbench
