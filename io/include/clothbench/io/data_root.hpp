#pragma once
/// Where data lives: $CLOTHBENCH_DATA, else the repository's own scenes/data (README.md: Data).
#include <string>

namespace clothbench {

/// The data root directory (no trailing slash). Not checked for existence.
std::string data_root();
/// data_root() + "/" + relative.
std::string data_path(const std::string& relative);
/// A body or file reference as scenes and the CLI write it: "debian:human" (Debian's body),
/// "data:REL" (under the data root; throws InputError naming the data root and CLOTHBENCH_DATA
/// when absent), anything else is returned unchanged.
std::string resolve_data_reference(const std::string& ref);
/// Debian's neutral MakeHuman body (package assimp-testmodels), the default static body.
inline constexpr const char* kDebianHumanBody = "/usr/share/assimp/models/Collada/human.zae";

}  // namespace clothbench
