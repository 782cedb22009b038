#pragma once
/// Where shared data lives: $CLOTHBENCH_DATA, else ../shared/data beside the source tree.
#include <string>

namespace clothbench {

/// The data root directory (no trailing slash). Not checked for existence.
std::string data_root();
/// data_root() + "/" + relative.
std::string data_path(const std::string& relative);
/// Debian's neutral MakeHuman body (package assimp-testmodels), the default static body.
inline constexpr const char* kDebianHumanBody = "/usr/share/assimp/models/Collada/human.zae";

}  // namespace clothbench
