// The clothbench command line: exit codes of bad input, run + JSON fields, compare, reproduce --quick.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "clothbench/config.h"
#include "clothbench/io/data_root.hpp"

namespace {

namespace fs = std::filesystem;

const std::string kScenes = std::string(CLOTHBENCH_SOURCE_DIR) + "/scenes/";

int clothbench(const std::string& args, const std::string& output = "/dev/null") {
  const char* bin = std::getenv("CLOTHBENCH_BIN");
  if (!bin) return -1;
  const int rc = std::system((std::string(bin) + " " + args + " > " + output + " 2>&1").c_str());
  return WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
}

std::string read(const std::string& path) {
  std::ifstream in(path);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

class Cli : public ::testing::Test {
 protected:
  void SetUp() override {
    const char* bin = std::getenv("CLOTHBENCH_BIN");
    if (!bin || !fs::exists(bin)) GTEST_SKIP() << "CLOTHBENCH_BIN not set";
    dir_ = fs::temp_directory_path() / ("clothbench_cli_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(Cli, BadInputExitsTwoWithAMessage) {
  const std::string log = (dir_ / "log").string();
  EXPECT_EQ(clothbench("run " + kScenes + "missing.toml", log), 2);
  EXPECT_NE(read(log).find("missing.toml"), std::string::npos);
  EXPECT_EQ(clothbench("run " + kScenes + "walking/tablecloth_sphere.toml --collider nope", log), 2);
  EXPECT_NE(read(log).find("unknown collider 'nope'"), std::string::npos);
  EXPECT_EQ(clothbench("run " + kScenes + "walking/tablecloth_sphere.toml --set solver.limit=fast", log), 2);
  EXPECT_NE(read(log).find("solver.limit"), std::string::npos);
  EXPECT_EQ(clothbench("run " + kScenes + "walking/tablecloth_sphere.toml --set bad", log), 2);
  EXPECT_EQ(clothbench("run " + kScenes +
                           "walking/tablecloth_sphere.toml --json /proc/nope/x.json --set body.move_s=0.01 --set "
                           "stop.drape_max_s=0.01",
                       log),
            2);
  EXPECT_EQ(clothbench("reproduce --only nope", log), 2);
  EXPECT_EQ(clothbench("compare " + (dir_ / "a.json").string() + " " + (dir_ / "b.json").string(), log), 2);
}

TEST_F(Cli, RunWritesTheResultFields) {
  const std::string json = (dir_ / "r.json").string(), log = (dir_ / "log").string();
  ASSERT_EQ(clothbench("run --quiet " + kScenes +
                           "walking/tablecloth_sphere.toml --set garment.vertices=225 "
                           "--set body.move_s=0.05 --set stop.drape_max_s=0.1 --json " +
                           json + " --png " + (dir_ / "r.png").string(),
                       log),
            0);
  // the summary names the renderer of the picture and counts the crossings
  EXPECT_NE(read(log).find(") drawn by "), std::string::npos) << read(log);
  EXPECT_NE(read(log).find(" % of structural springs); seam gap"), std::string::npos) << read(log);
  const auto doc = nlohmann::json::parse(read(json));
  ASSERT_EQ(doc["benchmarks"].size(), 1u);
  const auto& row = doc["benchmarks"][0];
  for (const char* key : {"name", "iterations", "real_time", "time_unit", "vertices", "query_points", "total_s",
                          "cdr_ms", "cs_ms", "frames", "fps", "inside_pct", "depth_max_mm", "depth_p95_mm",
                          "strain_max", "strain_p99", "converged", "diverged"})
    EXPECT_TRUE(row.contains(key)) << key;
  EXPECT_EQ(row["time_unit"], "ms");
  EXPECT_TRUE(doc["context"].contains("git_sha"));
  EXPECT_TRUE(fs::exists(dir_ / "r.png"));
  EXPECT_FALSE(fs::exists(json + ".tmp"));
}

// every build draws maps with the CPU rasteriser; --renderer gl without CLOTHBENCH_WITH_GL names the option
TEST_F(Cli, MapsWithoutOpenGlUseTheCpuRendererAndNameTheMissingOption) {
  if (!fs::exists(clothbench::kDebianHumanBody)) GTEST_SKIP() << clothbench::kDebianHumanBody << " missing";
  const std::string log = (dir_ / "log").string();
  const std::string maps = "maps " + std::string(clothbench::kDebianHumanBody) + " --size 32 --png " + dir_.string();
  EXPECT_EQ(clothbench(maps + " --renderer cpu", log), 0) << read(log);
  EXPECT_TRUE(fs::exists(dir_ / "human_rest_depth.png"));
#ifdef CLOTHBENCH_WITH_GL
  GTEST_SKIP() << "built with CLOTHBENCH_WITH_GL";
#else
  EXPECT_EQ(clothbench(maps, log), 0) << read(log);  // the default renderer is cpu here
  EXPECT_NE(read(log).find("cpu maps"), std::string::npos) << read(log);
  EXPECT_EQ(clothbench(maps + " --renderer gl", log), 2);
  EXPECT_NE(read(log).find("-DCLOTHBENCH_WITH_GL=ON"), std::string::npos) << read(log);
#endif
}

TEST_F(Cli, CompareFlagsARegression) {
  const auto write = [&](const std::string& name, double t) {
    std::ofstream((dir_ / name).string())
        << nlohmann::json{{"context", {}}, {"benchmarks", {{{"name", "a/b"}, {"real_time", t}}}}}.dump();
  };
  write("old.json", 1.0);
  write("same.json", 1.05);
  write("slow.json", 1.5);
  const std::string old = (dir_ / "old.json").string();
  EXPECT_EQ(clothbench("compare " + old + " " + (dir_ / "same.json").string()), 0);
  EXPECT_EQ(clothbench("compare " + old + " " + (dir_ / "slow.json").string()), 1);
  EXPECT_EQ(clothbench("compare " + old + " " + (dir_ / "slow.json").string() + " --threshold 60"), 0);
}

}  // namespace
