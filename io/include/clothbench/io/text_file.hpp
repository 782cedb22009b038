#pragma once
/// Writing text files whole: never a half-written file.
#include <string>

namespace clothbench {

/// Writes text to PATH.tmp then renames it (no half-written file); throws InputError naming the
/// path when the directory is not writable.
void write_text_file(const std::string& path, const std::string& text);

}  // namespace clothbench
