// The collider registry (bench/src/registry.cpp): every name of DESIGN.md, what this build has, the traits the
// experiments choose by, colliders registered at run time, the errors for unknown or unbuilt colliders.
#include "clothbench/bench/registry.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <string>

#include "clothbench/io/errors.hpp"
#include "clothbench/sim/brute_collider.hpp"

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
    // an OpenGL context is not there on every machine (the conformance suite and tests/collide_is cover them)
    if (collider_info(name)->needs != Needs::kNothing) continue;
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

// what the tables and tests choose by: image space, object space and the reference; which are exact, listed, need
// OpenGL
TEST(Registry, TraitsOfTheBuiltInColliders) {
  std::vector<std::string> image, object, reference, exact, listed, opengl;
  for (const ColliderInfo& c : all_colliders()) {
    (c.family == Family::kImageSpace ? image : c.family == Family::kObjectSpace ? object : reference).push_back(c.name);
    if (c.exact) exact.push_back(c.name);
    if (c.in_tables) listed.push_back(c.name);
    if (c.needs != Needs::kNothing) opengl.push_back(c.name);
  }
  using V = std::vector<std::string>;
  EXPECT_EQ(image, (V{"is-gl", "is-egl", "is-cpu"}));
  EXPECT_EQ(object, (V{"fcl", "embree", "vdb", "bbtree"}));
  EXPECT_EQ(reference, (V{"brute"}));
  EXPECT_EQ(exact, (V{"fcl", "embree", "brute"}));
  EXPECT_EQ(listed, (V{"is-gl", "is-cpu", "fcl", "embree", "vdb", "bbtree"}));
  EXPECT_EQ(opengl, (V{"is-gl", "is-egl"}));
  EXPECT_EQ(collider_info("is-egl")->needs, Needs::kGpu);
  EXPECT_TRUE(collider_info("vdb")->slow_update);
  EXPECT_TRUE(collider_info("embree")->coherent && collider_info("fcl")->face_normals);
  EXPECT_FALSE(collider_info("sphere")) << "the runner's analytic body is no registry entry";
}

TEST(Registry, CollidersAreTheBuiltOnesAFilterKeepsInRegistryOrder) {
  std::vector<std::string> object;
  for (const std::string& name : available_colliders())
    if (collider_info(name)->family == Family::kObjectSpace) object.push_back(name);
  EXPECT_EQ(colliders([](const ColliderInfo& c) { return c.family == Family::kObjectSpace; }), object);
  EXPECT_EQ(colliders([](const ColliderInfo&) { return true; }), available_colliders());
  EXPECT_TRUE(colliders([](const ColliderInfo& c) { return !c.built; }).empty());
}

// a collider added at run time, as a test or a plug-in adds one: listed, made by name, removed again
TEST(Registry, RegistersAColliderAtRunTime) {
  ColliderInfo toy;
  toy.name = "toy-brute";
  toy.description = "brute under another name";
  toy.family = Family::kObjectSpace;
  register_collider(toy, [](const ColliderOptions& o) { return std::make_unique<BruteForceCollider>(o); });
  EXPECT_EQ(available_colliders().back(), "toy-brute");
  EXPECT_TRUE(collider_info("toy-brute")->built);
  EXPECT_NE(make_collider("toy-brute"), nullptr);
  const auto object = colliders([](const ColliderInfo& c) { return c.family == Family::kObjectSpace; });
  EXPECT_EQ(object.back(), "toy-brute");
  EXPECT_THROW(register_collider(toy, [](const ColliderOptions& o) { return std::make_unique<BruteForceCollider>(o); }),
               std::invalid_argument);
  EXPECT_THROW(register_collider(ColliderInfo{}, {}), std::invalid_argument);
  EXPECT_TRUE(unregister_collider("toy-brute"));
  EXPECT_FALSE(unregister_collider("toy-brute"));
  EXPECT_FALSE(collider_info("toy-brute"));
  EXPECT_THROW(make_collider("toy-brute"), InputError);
}

}  // namespace
}  // namespace clothbench
