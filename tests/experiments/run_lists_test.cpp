// The paper tables' run lists (Experiment::runs): the colliders they list come from the registry, so a collider
// registered at run time joins every table of its family, and one kept out of the tables joins none.
#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "clothbench/bench/registry.hpp"
#include "clothbench/experiments/experiment.hpp"
#include "clothbench/sim/brute_collider.hpp"
#include "test_support.hpp"

namespace clothbench {
namespace {

const Experiment& experiment(const std::string& id) {
  const auto& all = experiments();
  const auto it = std::find_if(all.begin(), all.end(), [&](const Experiment& e) { return e.id == id; });
  if (it == all.end() || !it->runs) throw std::logic_error(id + ": no such experiment, or it lists no runs");
  return *it;
}

// the colliders of an experiment's runs, in the order they first appear
std::vector<std::string> colliders_of(const std::vector<ExperimentContext::Request>& runs) {
  std::vector<std::string> names;
  for (const auto& q : runs)
    if (std::find(names.begin(), names.end(), q.collider) == names.end()) names.push_back(q.collider);
  return names;
}

// the built ones of `names`, in their order
std::vector<std::string> built(const std::vector<std::string>& names) {
  const std::vector<std::string> available = available_colliders();
  std::vector<std::string> out;
  for (const auto& n : names)
    if (std::find(available.begin(), available.end(), n) != available.end()) out.push_back(n);
  return out;
}

// a collider registered for one test and removed after it
class ScopedCollider {
 public:
  ScopedCollider(const std::string& name, Family family, bool in_tables) : name_(name) {
    ColliderInfo info;
    info.name = name;
    info.description = "brute under another name (a test's)";
    info.family = family;
    info.in_tables = in_tables;
    register_collider(info, [](const ColliderOptions& o) { return std::make_unique<BruteForceCollider>(o); });
  }
  ~ScopedCollider() { unregister_collider(name_); }
  ScopedCollider(const ScopedCollider&) = delete;
  ScopedCollider& operator=(const ScopedCollider&) = delete;

 private:
  std::string name_;
};

// the built-in colliders the tables listed as typed-in lists, in the same order: Table 1 every collider of the
// tables, then image space and embree again with our defaults; Table 2 image space, then again with ours
TEST(RunLists, PaperTablesListTheirCollidersInTheirOrder) {
  const ExperimentContext ctx(test::temp_path("run-lists"), false, 1);
  const auto t1 = experiment("dressing-t1").runs(ctx);
  EXPECT_EQ(colliders_of(t1), built({"is-gl", "is-cpu", "fcl", "embree", "vdb", "bbtree"}));
  // per garment and regime: every collider, then the "ours" entries
  const std::size_t entries =
      built({"is-gl", "is-cpu", "fcl", "embree", "vdb", "bbtree"}).size() + built({"is-gl", "is-cpu", "embree"}).size();
  EXPECT_EQ(t1.size(), 2 * 2 * entries);
  EXPECT_EQ(experiment("walking-t1").runs(ctx).size(), t1.size());
  const auto t2 = experiment("dressing-t2").runs(ctx);
  EXPECT_EQ(colliders_of(t2), built({"is-gl", "is-cpu"}));
  EXPECT_EQ(t2.size(), 4 * 2 * 2 * built({"is-gl", "is-cpu"}).size());
}

// a toy object-space collider registered for the tables is in dressing-t1's run list (with the papers' detection and
// without "ours" entries, as fcl); one kept out of the tables is not; Table 2 (image space only) lists neither
TEST(RunLists, AToyColliderJoinsTheDressingTablesOfItsFamily) {
  const ScopedCollider toy("toy", Family::kObjectSpace, true), hidden("toy-hidden", Family::kObjectSpace, false);
  const ExperimentContext ctx(test::temp_path("run-lists"), false, 1);
  const auto t1 = experiment("dressing-t1").runs(ctx);
  const auto names = colliders_of(t1);
  EXPECT_EQ(names.back(), "toy") << "listed after the built-in colliders, in registry order";
  EXPECT_EQ(std::count(names.begin(), names.end(), "toy-hidden"), 0);
  EXPECT_EQ(std::count_if(t1.begin(), t1.end(), [](const auto& q) { return q.collider == "toy"; }), 2 * 2)
      << "one run per garment and regime";
  EXPECT_EQ(colliders_of(experiment("walking-t1").runs(ctx)), names);
  const auto t2 = colliders_of(experiment("dressing-t2").runs(ctx));
  EXPECT_EQ(std::count(t2.begin(), t2.end(), "toy"), 0);
  // and it runs where the tables run it: through ExperimentContext::run, by name
  ExperimentContext small(test::temp_path("run-lists-toy"), false, 1);
  const RunResult& r =
      small.run("walking/tablecloth_sphere.toml", "toy", {"garment.vertices=64", "stop.drape_max_s=0.02"});
  EXPECT_EQ(r.collider, "toy");
  EXPECT_GT(r.mesh.positions.cols(), 0);
}

// an image-space toy joins Table 2, whose entries are the image-space colliders of the tables and ours beside them
TEST(RunLists, AnImageSpaceToyJoinsTable2WithOurDefaultsBeside) {
  const ScopedCollider toy("toy-is", Family::kImageSpace, true);
  const ExperimentContext ctx(test::temp_path("run-lists"), false, 1);
  const auto t2 = experiment("dressing-t2").runs(ctx);
  EXPECT_EQ(colliders_of(t2).back(), "toy-is");
  EXPECT_EQ(std::count_if(t2.begin(), t2.end(), [](const auto& q) { return q.collider == "toy-is"; }), 4 * 2 * 2)
      << "per garment and regime: the papers' test and ours";
}

}  // namespace
}  // namespace clothbench
