#pragma once
/// Garment pattern files: the `.pattern` text format (documented in scenes/README.md) and, by
/// extension, GarmentCode JSON specifications (garmentcode.hpp), both read into sim's Pattern.
#include <string>
#include <string_view>

#include "clothbench/sim/garment.hpp"

namespace clothbench {

/// Most points a panel outline may have once its curves are flattened, in either format: the mesher
/// measures the distance to the outline, every point of it, from every grid node (found by fuzz/).
inline constexpr int kMaxOutlinePoints = 2000;

/// Reads a pattern file: `.json` is read as a GarmentCode specification, anything else as
/// `.pattern` text. Throws InputError "FILE:LINE: what is wrong" on bad input or an unreadable file.
Pattern load_pattern(const std::string& path);

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
