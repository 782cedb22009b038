#include "clothbench/io/data_root.hpp"

#include <cstdlib>

#include "clothbench/config.h"

namespace clothbench {

std::string data_root() {
  const char* env = std::getenv("CLOTHBENCH_DATA");
  if (env && *env) return env;
  return std::string(CLOTHBENCH_SOURCE_DIR) + "/../shared/data";
}

std::string data_path(const std::string& relative) { return data_root() + "/" + relative; }

}  // namespace clothbench
