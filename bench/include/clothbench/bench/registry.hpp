#pragma once
/// The collider registry: names of DESIGN.md to implementations. The only place that knows
/// every backend (besides the driver that wires them to the simulator).
#include <memory>
#include <string>
#include <vector>

#include "clothbench/sim/collider.hpp"

namespace clothbench {

/// One registry entry.
struct ColliderInfo {
  std::string name;         ///< "is-gl", "is-cpu", "fcl", "embree", "brute"
  std::string description;  ///< one line
  bool built = false;       ///< false when the CMake option that enables it was off
  std::string option;       ///< the CMake option that builds it
};

/// Every collider clothbench knows, built or not.
std::vector<ColliderInfo> all_colliders();
/// Names of the colliders built in (the conformance suite runs over these).
std::vector<std::string> available_colliders();
/// Creates a collider by name. Throws InputError for an unknown name (listing the valid ones)
/// or a backend that was not built (naming the CMake option that enables it).
std::unique_ptr<Collider> make_collider(const std::string& name, const ColliderOptions& options = {});

}  // namespace clothbench
