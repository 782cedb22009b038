// The collider registry (bench/src/registry.cpp): every name of DESIGN.md, what this build has, the
// errors for unknown or unbuilt colliders.
#include "clothbench/bench/registry.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <string>

#include "clothbench/io/errors.hpp"

namespace clothbench {
namespace {

TEST(Registry, KnowsEveryColliderOnceWithItsOption) {
  std::set<std::string> names;
  for (const ColliderInfo& c : all_colliders()) {
    EXPECT_TRUE(names.insert(c.name).second) << c.name << " listed twice";
    EXPECT_FALSE(c.description.empty()) << c.name;
    if (c.name != "brute" && c.name != "is-cpu") {
      EXPECT_FALSE(c.option.empty()) << c.name;
    }
  }
  for (const char* name : {"is-gl", "is-egl", "is-cpu", "fcl", "embree", "vdb", "bbtree", "brute"})
    EXPECT_EQ(names.count(name), 1u) << name;
}

TEST(Registry, AvailableAreTheBuiltOnes) {
  std::vector<std::string> built;
  for (const ColliderInfo& c : all_colliders())
    if (c.built) built.push_back(c.name);
  EXPECT_EQ(available_colliders(), built);
  EXPECT_NE(std::find(built.begin(), built.end(), "brute"), built.end());
  EXPECT_NE(std::find(built.begin(), built.end(), "is-cpu"), built.end());
}

TEST(Registry, MakesEveryBuiltColliderByItsName) {
  for (const std::string& name : available_colliders()) {
    if (name == "is-gl" || name == "is-egl") continue;  // need an OpenGL context (the conformance suite covers them)
    EXPECT_NE(make_collider(name), nullptr) << name;
  }
}

TEST(Registry, UnknownAndUnbuiltNamesAreInputErrors) {
  try {
    make_collider("no-such-collider");
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("no-such-collider"), std::string::npos) << what;
    EXPECT_NE(what.find("is-cpu"), std::string::npos) << "lists the valid names: " << what;
  }
  for (const ColliderInfo& c : all_colliders()) {
    if (c.built) continue;
    try {
      make_collider(c.name);
      FAIL() << c.name << ": no error";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(c.option), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace clothbench
