// Sweep grids and shards (sweep.hpp); the runs themselves: Cli.Sweep* and ctest cluster.sweep_on_slurm.
#include "clothbench/bench/sweep.hpp"

#include <gtest/gtest.h>

#include <set>

#include "clothbench/io/errors.hpp"

namespace clothbench {
namespace {

TEST(Sweep, AnAxisSplitsOnCommasOutsideBracketsAndQuotes) {
  const SweepAxis a = parse_axis("body.center=[0,0.5,0],[1,0,0]");
  EXPECT_EQ(a.key, "body.center");
  EXPECT_EQ(a.values, (std::vector<std::string>{"[0,0.5,0]", "[1,0,0]"}));
  EXPECT_EQ(parse_axis("scene.name=\"a,b\",c").values, (std::vector<std::string>{"\"a,b\"", "c"}));
  EXPECT_THROW(parse_axis("novalue"), InputError);
  EXPECT_THROW(parse_axis("a.b=1,,2"), InputError);
  EXPECT_THROW(parse_axis("a.b=1,"), InputError);
}

TEST(Sweep, TheGridNamesEveryPointByItsSettingsInOrder) {
  SweepGrid g;
  g.colliders = {"is-cpu", "fcl"};
  g.axes = {parse_axis("garment.vertices=100,200,300"), parse_axis("solver.limit=velocity,directional")};
  const auto points = expand_grid(g);
  ASSERT_EQ(points.size(), 12u);
  EXPECT_EQ(points[0].name, "is-cpu/garment.vertices=100/solver.limit=velocity");
  EXPECT_EQ(points[1].name, "is-cpu/garment.vertices=100/solver.limit=directional");  // the last axis turns fastest
  EXPECT_EQ(points[11].name, "fcl/garment.vertices=300/solver.limit=directional");
  std::set<std::string> names;
  for (std::size_t i = 0; i < points.size(); ++i) {
    EXPECT_EQ(points[i].index, static_cast<int>(i));
    names.insert(points[i].name);
  }
  EXPECT_EQ(names.size(), points.size());
  EXPECT_EQ(SweepGrid::from_json(g.to_json()).to_json(), g.to_json());
  SweepGrid none;  // no axes, the scene's collider: one point
  EXPECT_EQ(expand_grid(none).size(), 1u);
}

TEST(Sweep, ShardsCoverEveryPointExactlyOnce) {
  SweepGrid g;
  g.axes = {parse_axis("a.b=1,2,3,4,5,6,7"), parse_axis("c.d=x,y,z")};
  const auto points = expand_grid(g);
  for (int n : {1, 2, 3, 5, 8, 21, 40}) {
    std::multiset<int> seen;
    for (int i = 0; i < n; ++i)
      for (const auto& p : shard_points(points, i, n)) seen.insert(p.index);
    ASSERT_EQ(seen.size(), points.size()) << n << " shards";
    for (const auto& p : points) EXPECT_EQ(seen.count(p.index), 1u) << n << " shards";
  }
  EXPECT_EQ(parse_shard("3/8"), std::make_pair(3, 8));
  for (const char* bad : {"8/8", "-1/4", "1/0", "a/2", "1", "1/2x", ""}) EXPECT_THROW(parse_shard(bad), InputError) << bad;
}

}  // namespace
}  // namespace clothbench
