#include "clothbench/io/data_root.hpp"

#include <cstdlib>
#include <filesystem>

#include "clothbench/config.h"
#include "clothbench/io/errors.hpp"

namespace clothbench {

std::string data_root() {
  const char* env = std::getenv("CLOTHBENCH_DATA");
  if (env && *env) return env;
  return std::string(CLOTHBENCH_SOURCE_DIR) + "/scenes/data";
}

std::string data_path(const std::string& relative) { return data_root() + "/" + relative; }

std::string resolve_data_reference(const std::string& ref) {
  if (ref == "debian:human") return kDebianHumanBody;
  if (ref.rfind("data:", 0) != 0) return ref;
  const std::string path = data_path(ref.substr(5));
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) {
    const char* env = std::getenv("CLOTHBENCH_DATA");
    throw InputError(located(path, 0, "file not found: `" + ref + "` resolves under the data root " + data_root() +
                                          (env && *env ? " (set by CLOTHBENCH_DATA)"
                                                       : " (the repository's scenes/data; CLOTHBENCH_DATA overrides it)")));
  }
  return path;
}

}  // namespace clothbench
