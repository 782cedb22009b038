// libFuzzer target: `.pattern` text through parse_pattern. InputError is the expected answer to
// bad input; any other exception, crash or sanitizer report is a finding. A pattern that parses
// must also survive write_pattern and read back with the same panels and seams.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string_view>

#include "clothbench/io/errors.hpp"
#include "clothbench/io/pattern_file.hpp"

namespace {

// abort (a libFuzzer finding) when the written pattern reads back differently
void check_round_trip(const clothbench::Pattern& pattern) {
  const std::string text = clothbench::write_pattern(pattern);
  try {
    const clothbench::Pattern back = clothbench::parse_pattern(text, "fuzz-written.pattern");
    if (back.panels.size() == pattern.panels.size() && back.seams.size() == pattern.seams.size()) return;
    std::fprintf(stderr, "round trip changed the counts: %zu panels, %zu seams -> %zu, %zu\n", pattern.panels.size(),
                 pattern.seams.size(), back.panels.size(), back.seams.size());
  } catch (const clothbench::InputError& e) {
    std::fprintf(stderr, "written pattern does not read back: %s\n--- written ---\n%s\n", e.what(), text.c_str());
  }
  std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // the input as pattern text
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  clothbench::Pattern pattern;
  try {
    pattern = clothbench::parse_pattern(text, "fuzz.pattern");
  } catch (const clothbench::InputError&) {
    return 0;
  }
  check_round_trip(pattern);
  return 0;
}
