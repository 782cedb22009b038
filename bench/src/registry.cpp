#include "registry.hpp"

#include <functional>

#include "clothbench/config.h"
#include "clothbench/sim/brute_collider.hpp"
#include "clothbench/io/errors.hpp"

namespace clothbench {

namespace {

using Factory = std::function<std::unique_ptr<Collider>(const ColliderOptions&)>;

struct Entry {
  ColliderInfo info;
  Factory make;  // empty when not built
};

std::vector<Entry> entries() {
  std::vector<Entry> e;
  e.push_back({{"brute", "exact, every triangle per point (tests and oracle reference)", true, ""},
               [](const ColliderOptions& o) { return std::make_unique<BruteForceCollider>(o); }});
  return e;
}

}  // namespace

std::vector<ColliderInfo> all_colliders() {
  std::vector<ColliderInfo> out;
  for (auto& e : entries()) out.push_back(e.info);
  return out;
}

std::vector<std::string> available_colliders() {
  std::vector<std::string> out;
  for (auto& e : entries())
    if (e.info.built) out.push_back(e.info.name);
  return out;
}

std::unique_ptr<Collider> make_collider(const std::string& name, const ColliderOptions& options) {
  std::string known;
  for (auto& e : entries()) {
    if (e.info.name == name) {
      if (!e.info.built)
        throw InputError("collider '" + name + "' was not built: configure with -D" + e.info.option + "=ON");
      return e.make(options);
    }
    known += (known.empty() ? "" : ", ") + e.info.name;
  }
  throw InputError("unknown collider '" + name + "' (known: " + known + ")");
}

}  // namespace clothbench
