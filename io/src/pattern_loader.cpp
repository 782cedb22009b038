// load_pattern: the one extension dispatch of the pattern formats.
#include "clothbench/io/pattern_loader.hpp"

#include "clothbench/io/garmentcode.hpp"
#include "clothbench/io/pattern_file.hpp"

namespace clothbench {

Pattern load_pattern(const std::string& path) {
  const std::string json = ".json";
  const bool garmentcode = path.size() >= json.size() && path.compare(path.size() - json.size(), json.size(), json) == 0;
  return garmentcode ? load_garmentcode(path) : load_pattern_text(path);
}

}  // namespace clothbench
