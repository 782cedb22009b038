#pragma once
/// Garment pattern files of either format, chosen by extension in this one place: `.json` is a
/// GarmentCode specification (garmentcode.hpp), anything else `.pattern` text (pattern_file.hpp).
#include <string>

#include "clothbench/sim/garment.hpp"

namespace clothbench {

/// Reads a pattern file of either format. Throws InputError "FILE:LINE: what is wrong" on bad input
/// or an unreadable file.
Pattern load_pattern(const std::string& path);

}  // namespace clothbench
