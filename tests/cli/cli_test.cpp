// The clothbench command line: exit codes of bad input, run + JSON fields, compare, reproduce --quick,
// --version, help and listings, the accuracy verdict, the configuration hash, the time estimate.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>

#include <Eigen/Core>

#include "clothbench/bench/registry.hpp"
#include "clothbench/bench/report.hpp"
#include "clothbench/bench/runner.hpp"
#include "clothbench/config.h"
#include "clothbench/experiments/experiment.hpp"
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

// the first line of `text` that starts with `prefix`, "" when none does
std::string line_starting(const std::string& text, const std::string& prefix) {
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);)
    if (line.rfind(prefix, 0) == 0) return line;
  return "";
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
  for (const char* key : {"name", "scene", "collider", "regime", "iterations", "real_time", "time_unit", "vertices", "query_points", "total_s",
                          "cdr_ms", "cs_ms", "frames", "fps", "inside_pct", "depth_max_mm", "depth_p95_mm",
                          "strain_max", "strain_p99", "converged", "diverged"})
    EXPECT_TRUE(row.contains(key)) << key;
  // one unit per row, the one that keeps real_time at 1 or more; cpu_time measured (the thread's CPU time)
  const std::string unit = row["time_unit"];
  EXPECT_TRUE(unit == "ms" || unit == "us" || unit == "ns") << unit;
  EXPECT_GE(row["real_time"].get<double>(), 1.0);
  EXPECT_GT(row["cpu_time"].get<double>(), 0.0);
  EXPECT_EQ(row["threads"], 1);  // github-action-benchmark's googlecpp reads name, real_time, cpu_time,
  EXPECT_TRUE(row.contains("iterations"));  // time_unit, iterations and threads
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

// maps --renderer egl names the device it drew on and draws is-gl's pictures; a run with is-egl names it too
TEST_F(Cli, MapsAndRunsThroughEglNameTheirDevice) {
#ifndef CLOTHBENCH_WITH_EGL
  GTEST_SKIP() << "built without CLOTHBENCH_WITH_EGL";
#else
  if (!fs::exists(clothbench::kDebianHumanBody)) GTEST_SKIP() << clothbench::kDebianHumanBody << " missing";
  const std::string log = (dir_ / "log").string();
  const int rc = clothbench("maps " + std::string(clothbench::kDebianHumanBody) + " --size 64 --renderer egl --png " +
                                (dir_ / "egl").string(),
                            log);
  if (rc == 1 && read(log).find("no OpenGL context through EGL") != std::string::npos)
    GTEST_SKIP() << "no EGL context here: " << read(log);
  ASSERT_EQ(rc, 0) << read(log);
  EXPECT_NE(read(log).find("egl: EGL "), std::string::npos) << read(log);
  EXPECT_TRUE(fs::exists(dir_ / "egl" / "human_rest_depth.png"));
  const std::string json = (dir_ / "r.json").string();
  ASSERT_EQ(clothbench("run " + std::string(CLOTHBENCH_SOURCE_DIR) +
                           "/scenes/walking/tablecloth_sphere.toml --collider is-egl --quiet --set garment.vertices=64 "
                           "--set stop.drape_max_s=0.02 --set body.move_s=0.02 --json " +
                           json,
                       log),
            0)
      << read(log);
  EXPECT_NE(read(log).find("device: EGL "), std::string::npos) << read(log);
  std::ifstream in(json);
  const auto doc = nlohmann::json::parse(in);
  EXPECT_EQ(doc["benchmarks"][0]["device"].get<std::string>().rfind("EGL ", 0), 0u) << doc["benchmarks"][0];
#endif
}

// a result file of `reps` repetitions of row NAME around time t (ms; +-1 % apart, as repetitions are)
void write_runs(const std::string& path, const std::string& name, double t, int reps, const std::string& hash = "") {
  nlohmann::json rows = nlohmann::json::array();
  for (int i = 0; i < reps; ++i) {
    nlohmann::json row{{"name", name}, {"run_type", "iteration"}, {"real_time", t * (1 + 0.01 * (i - reps / 2))},
                       {"time_unit", "ms"}};
    if (!hash.empty()) row["config_hash"] = hash;
    rows.push_back(row);
  }
  std::ofstream(path) << nlohmann::json{{"context", {}}, {"benchmarks", rows}}.dump();
}

TEST_F(Cli, CompareFlagsARegressionOnlyWithEnoughRepetitions) {
  const auto file = [&](const std::string& name) { return (dir_ / name).string(); };
  write_runs(file("old.json"), "a/b", 1.0, 5);
  write_runs(file("same.json"), "a/b", 1.05, 5);
  write_runs(file("slow.json"), "a/b", 1.5, 5);
  write_runs(file("once.json"), "a/b", 1.5, 1);
  const std::string old = file("old.json"), log = file("log");
  EXPECT_EQ(clothbench("compare " + old + " " + file("same.json")), 0);
  EXPECT_EQ(clothbench("compare " + old + " " + file("slow.json"), log), 1);
  EXPECT_NE(read(log).find("REGRESSION"), std::string::npos) << read(log);
  EXPECT_EQ(clothbench("compare " + old + " " + file("slow.json") + " --threshold 60"), 0);
  // one run against five: no verdict, and nothing judged is exit 2, not a pass
  EXPECT_EQ(clothbench("compare " + old + " " + file("once.json"), log), 2);
  EXPECT_NE(read(log).find("no verdict: 5 vs 1 repetitions (need >= 5 on both sides)"), std::string::npos) << read(log);
}

// accuracy is judged at any number of repetitions: a row that stops meeting the limits, or whose figure worsens by
// more than the tolerance (a share of that figure's limit), is an accuracy regression even when its time is the same
TEST_F(Cli, CompareFlagsAnAccuracyRegression) {
  const auto file = [&](const std::string& name) { return (dir_ / name).string(); };
  const auto write = [&](const std::string& path, double crossings_pct, bool meets, int reps) {
    nlohmann::json rows = nlohmann::json::array();
    for (int i = 0; i < reps; ++i)
      rows.push_back({{"name", "a/b"}, {"run_type", "iteration"}, {"real_time", 1.0 + 0.01 * (i - reps / 2)},
                      {"time_unit", "ms"}, {"crossings_pct", crossings_pct}, {"meets_limits", meets ? 1 : 0},
                      {"limit_misses", meets ? nlohmann::json::array() : nlohmann::json::array({"crossings 9 % > 1 %"})}});
    std::ofstream(path) << nlohmann::json{{"context", {}}, {"benchmarks", rows}}.dump();
  };
  write(file("old.json"), 0.41, true, 5);
  write(file("close.json"), 0.45, true, 5);   // worse by 0.04: within 10 % of the 1 % limit
  write(file("worse.json"), 0.80, true, 5);   // worse by 0.39: beyond it, still meeting the limits
  write(file("fails.json"), 9.0, false, 5);
  write(file("fails_once.json"), 9.0, false, 1);
  const std::string old = file("old.json"), log = file("log");
  EXPECT_EQ(clothbench("compare " + old + " " + file("close.json"), log), 0) << read(log);
  EXPECT_NE(read(log).find("0 accuracy regression(s) among 1 row(s)"), std::string::npos) << read(log);
  EXPECT_EQ(clothbench("compare " + old + " " + file("worse.json"), log), 1) << read(log);
  EXPECT_NE(read(log).find("ACCURACY REGRESSION a/b: crossings_pct 0.4100 -> 0.8000"), std::string::npos) << read(log);
  EXPECT_EQ(clothbench("compare " + old + " " + file("worse.json") + " --accuracy-tolerance 50", log), 0) << read(log);
  EXPECT_EQ(clothbench("compare " + old + " " + file("fails.json"), log), 1) << read(log);
  EXPECT_NE(read(log).find("stopped meeting the accuracy limits (crossings 9 % > 1 %)"), std::string::npos) << read(log);
  // one repetition: no time verdict, but the accuracy regression is still found
  EXPECT_EQ(clothbench("compare " + old + " " + file("fails_once.json"), log), 1) << read(log);
  EXPECT_NE(read(log).find("ACCURACY REGRESSION"), std::string::npos) << read(log);
}

TEST_F(Cli, CompareListsRowsOnOneSideOnlyAndReadsEachRowsTimeUnit) {
  const auto file = [&](const std::string& name) { return (dir_ / name).string(); };
  write_runs(file("old.json"), "a/b", 1.0, 5);
  nlohmann::json rows = nlohmann::json::array();
  for (int i = 0; i < 5; ++i)  // the same times in us, and a row the old file lacks
    rows.push_back({{"name", "a/b"}, {"real_time", 1000.0 * (1 + 0.01 * (i - 2))}, {"time_unit", "us"}}),
        rows.push_back({{"name", "a/new"}, {"real_time", 1.0}, {"time_unit", "ms"}});
  std::ofstream(file("new.json")) << nlohmann::json{{"context", {}}, {"benchmarks", rows}}.dump();
  const std::string log = file("log");
  EXPECT_EQ(clothbench("compare " + file("old.json") + " " + file("new.json"), log), 0) << read(log);
  EXPECT_NE(read(log).find("only in new"), std::string::npos) << read(log);
  EXPECT_NE(read(log).find("1.000 ["), std::string::npos) << read(log);  // 1 ms = 1000 us
  EXPECT_EQ(clothbench("compare " + file("new.json") + " " + file("old.json"), log), 0) << read(log);
  EXPECT_NE(read(log).find("only in old"), std::string::npos) << read(log);
}

// one collider against another: rows named after their colliders pair by the fields the user names, each pair is
// listed, and the hash (another collider, another configuration) is not held against them
TEST_F(Cli, ComparePairsRowsAcrossCollidersByTheFieldsNamed) {
  const auto file = [&](const std::string& name) { return (dir_ / name).string(); };
  const auto write = [&](const std::string& path, const std::vector<std::string>& colliders, double t) {
    nlohmann::json rows = nlohmann::json::array();
    for (const std::string& c : colliders)
      for (int i = 0; i < 5; ++i)
        rows.push_back({{"name", "walking-skirt/" + c}, {"run_type", "iteration"}, {"real_time", t * (1 + 0.01 * (i - 2))},
                        {"time_unit", "ms"}, {"scene", "walking-skirt"}, {"vertices", 680}, {"collider", c},
                        {"config_hash", "hash-" + c}});
    std::ofstream(path) << nlohmann::json{{"context", {}}, {"benchmarks", rows}}.dump();
  };
  write(file("cpu.json"), {"is-cpu"}, 1.0);
  write(file("embree.json"), {"embree"}, 2.0);
  write(file("both.json"), {"is-cpu", "embree"}, 2.0);
  const std::string cpu = file("cpu.json"), embree = file("embree.json"), log = file("log");
  EXPECT_EQ(clothbench("compare " + cpu + " " + embree, log), 2) << read(log);  // by name nothing pairs
  EXPECT_NE(read(log).find("no row pairs"), std::string::npos) << read(log);
  EXPECT_EQ(clothbench("compare " + cpu + " " + embree + " --pair-by scene,vertices", log), 1) << read(log);
  EXPECT_NE(read(log).find("paired by scene=walking-skirt, vertices=680: old 'walking-skirt/is-cpu' with new "
                           "'walking-skirt/embree'"),
            std::string::npos)
      << read(log);
  EXPECT_NE(read(log).find("REGRESSION"), std::string::npos) << read(log);  // twice as slow
  EXPECT_EQ(clothbench("compare " + cpu + " " + embree + " --pair-by collider", log), 2) << read(log);
  EXPECT_EQ(clothbench("compare " + cpu + " " + embree + " --pair-by colour", log), 2) << read(log);
  EXPECT_NE(read(log).find("has no field 'colour' (--pair-by)"), std::string::npos) << read(log);
  EXPECT_EQ(clothbench("compare " + cpu + " " + file("both.json") + " --pair-by scene", log), 2) << read(log);
  EXPECT_NE(read(log).find("--pair-by does not tell them apart"), std::string::npos) << read(log);
}

TEST_F(Cli, VersionPrintsTheVersionAndTheGitSha) {
  const std::string log = (dir_ / "log").string();
  ASSERT_EQ(clothbench("--version", log), 0);
  const std::string sha = clothbench::git_sha();
  EXPECT_EQ(read(log).rfind("clothbench " CLOTHBENCH_VERSION " (git " + sha.substr(0, sha.find('-')), 0), 0u)
      << read(log);
}

TEST_F(Cli, ReproduceHelpListsEveryExperimentOfTheRegistry) {
  const std::string log = (dir_ / "log").string();
  ASSERT_EQ(clothbench("reproduce --help", log), 0);
  const std::string help = read(log);
  ASSERT_FALSE(clothbench::experiments().empty());
  for (const auto& e : clothbench::experiments()) {
    const std::string line = line_starting(help, "  " + e.id + " ");
    EXPECT_FALSE(line.empty()) << e.id << " missing in\n" << help;
    EXPECT_EQ(line.substr(line.find_first_not_of(' ', e.id.size() + 2)), e.title) << line;
  }
}

// reproduce --only rewrites the index from the pages the folder holds: the page it ran with its wall time and git SHA,
// another page with the wall time the index listed it with (its SHA unknown without its JSON)
TEST_F(Cli, ReproduceOnlyKeepsTheIndexOfEveryPageInTheFolder) {
  const std::string log = (dir_ / "log").string(), out = (dir_ / "results").string();
  fs::create_directories(out);
  std::ofstream(out + "/dressing-t1.md") << "# dressing-t1\n";
  std::ofstream(out + "/README.md")
      << "| dressing-t1 | x | [dressing-t1.md](dressing-t1.md) | [dressing-t1.json](dressing-t1.json) | 12.5 |\n";
  ASSERT_EQ(clothbench("reproduce --quick --only pictures --out " + out, log), 0) << read(log);
  const std::string index = read(out + "/README.md");
  const std::string ran = line_starting(index, "| pictures |"), kept = line_starting(index, "| dressing-t1 |");
  EXPECT_NE(ran.find("| " + clothbench::git_sha() + " |"), std::string::npos) << index;
  EXPECT_NE(kept.find("| ? | 12.5 |"), std::string::npos) << index;
  EXPECT_LT(index.find("| dressing-t1 |"), index.find("| pictures |"));  // in the registry's order
}

// the placement preview: the garment placed on a body as a run places it, measured against the exact body and drawn
TEST_F(Cli, GarmentOnABodyReportsHowItStartsAndDrawsIt) {
  const std::string log = (dir_ / "log").string(), png = (dir_ / "placed.png").string();
  const std::string skirt = kScenes + "garments/skirt.pattern";
  ASSERT_EQ(clothbench("garment " + skirt + " --vertices 300 --on debian:human --json", log), 0) << read(log);
  const auto doc = nlohmann::json::parse(read(log).substr(read(log).find('{')));
  const auto& p = doc.at("placement");
  EXPECT_EQ(p.at("body"), "debian:human");
  EXPECT_LE(p.at("inside_pct").get<double>(), 1.0);  // the shipped skirt is placed around the body
  EXPECT_LE(p.at("touching").get<long>(), doc.at("vertices").get<long>());
  EXPECT_EQ(p.at("attached").get<long>(), doc.at("attached").get<long>());
  EXPECT_GE(p.at("attached_far").get<long>(), 0);
  ASSERT_EQ(clothbench("garment " + skirt + " --vertices 300 --on debian:human --png " + png, log), 0) << read(log);
  EXPECT_NE(read(log).find("inside "), std::string::npos) << read(log);
  EXPECT_NE(read(log).find("picture " + png), std::string::npos) << read(log);
  EXPECT_GT(fs::file_size(png), 1000u);
  // a body that is not there is bad input, named
  EXPECT_EQ(clothbench("garment " + skirt + " --on " + (dir_ / "nobody.obj").string(), log), 2);
  EXPECT_NE(read(log).find("nobody.obj"), std::string::npos) << read(log);
}

TEST_F(Cli, CollidersPrintsAnAlignedTableOrJson) {
  const std::string log = (dir_ / "log").string();
  const auto colliders = clothbench::all_colliders();
  ASSERT_EQ(clothbench("colliders", log), 0);
  std::istringstream table(read(log));
  std::string header;
  std::getline(table, header);
  EXPECT_EQ(header.rfind("name ", 0), 0u) << header;
  const std::size_t built = header.find("built"), family = header.find("family"),
                    description = header.find("description");
  ASSERT_NE(family, std::string::npos) << header;
  ASSERT_NE(description, std::string::npos) << header;
  for (const auto& c : colliders) {
    std::string line;
    ASSERT_TRUE(std::getline(table, line)) << c.name;
    EXPECT_EQ(line.rfind(c.name + " ", 0), 0u) << line;
    EXPECT_EQ(line.find_first_not_of(' ', c.name.size()), built) << line;
    EXPECT_EQ(line.find(c.built ? "yes" : "no (-D" + c.option + "=ON)"), built) << line;
    EXPECT_EQ(line.find(c.description), description) << line;
  }
  ASSERT_EQ(clothbench("colliders --json", log), 0);
  const auto doc = nlohmann::json::parse(read(log));
  ASSERT_EQ(doc.size(), colliders.size());
  for (std::size_t i = 0; i < colliders.size(); ++i) {
    EXPECT_EQ(doc[i]["name"], colliders[i].name);
    EXPECT_EQ(doc[i]["built"], colliders[i].built);
    EXPECT_EQ(doc[i]["option"], colliders[i].option);
    EXPECT_EQ(doc[i]["description"], colliders[i].description);
    // the registry's traits, as experiments and tests choose colliders by them
    EXPECT_EQ(doc[i]["exact"], colliders[i].exact);
    EXPECT_EQ(doc[i]["in_tables"], colliders[i].in_tables);
    EXPECT_EQ(doc[i]["coherent"], colliders[i].coherent);
    EXPECT_EQ(doc[i]["face_normals"], colliders[i].face_normals);
    EXPECT_EQ(doc[i]["slow_update"], colliders[i].slow_update);
    EXPECT_EQ(doc[i]["family"] == "image space", colliders[i].family == clothbench::Family::kImageSpace);
    EXPECT_EQ(doc[i]["needs"] == "nothing", colliders[i].needs == clothbench::Needs::kNothing);
  }
}

TEST_F(Cli, UnknownSceneKeySuggestsTheNearestKnownKey) {
  const std::string log = (dir_ / "log").string();
  EXPECT_EQ(clothbench("run " + kScenes + "walking/tablecloth_sphere.toml --set garment.vertice=225", log), 2);
  EXPECT_NE(read(log).find("garment.vertice (from --set): unknown key `vertice` (did you mean `vertices`?)"),
            std::string::npos)
      << read(log);
  const std::string scene = (dir_ / "typo.toml").string();
  std::ofstream(scene) << "[solver]\nthreshhold = 0.1\n";
  EXPECT_EQ(clothbench("run " + scene, log), 2);
  EXPECT_NE(read(log).find("typo.toml:2: solver.threshhold: unknown key `threshhold` (did you mean `threshold`?)"),
            std::string::npos)
      << read(log);
}

// a small run of the tablecloth on the analytic sphere: well under a second
const std::string kSmallRun =
    "walking/tablecloth_sphere.toml --set garment.vertices=225 --set body.move_s=0.05 "
    "--set stop.drape_max_s=0.1";

TEST_F(Cli, RunRecordsTheOverridesAndTheConfigHashAndCompareFlagsADifferentConfig) {
  const std::string a = (dir_ / "a.json").string(), b = (dir_ / "b.json").string(), log = (dir_ / "log").string();
  ASSERT_EQ(clothbench("run --quiet " + kScenes + kSmallRun + " --json " + a, log), 0) << read(log);
  const auto doc = nlohmann::json::parse(read(a));
  const auto& context = doc["context"];
  EXPECT_EQ(context["scene"], kScenes + "walking/tablecloth_sphere.toml");
  EXPECT_EQ(context["overrides"], nlohmann::json({"garment.vertices=225", "body.move_s=0.05", "stop.drape_max_s=0.1"}));
  const std::string hash = context["config_hash"];
  EXPECT_EQ(hash.size(), 16u);
  EXPECT_EQ(doc["benchmarks"][0]["config_hash"], hash);
  // the summary names them too
  EXPECT_NE(read(log).find("--set garment.vertices=225 body.move_s=0.05 stop.drape_max_s=0.1; config " + hash),
            std::string::npos)
      << read(log);
  // the same row with another setting: another hash, and compare does not judge it
  ASSERT_EQ(clothbench("run --quiet " + kScenes + kSmallRun + " --set material.damping=0.003 --json " + b, log), 0);
  const auto other = nlohmann::json::parse(read(b));
  EXPECT_NE(other["context"]["config_hash"], hash);
  ASSERT_EQ(other["benchmarks"][0]["name"], doc["benchmarks"][0]["name"]);
  EXPECT_EQ(clothbench("compare " + a + " " + b + " --threshold 0", log), 2) << read(log);  // nothing judged
  EXPECT_NE(read(log).find("CONFIG DIFFERS (not judged)"), std::string::npos) << read(log);
  EXPECT_NE(read(log).find("warning: 1 row(s) ran with a different configuration"), std::string::npos) << read(log);
  clothbench("compare " + a + " " + a, log);
  EXPECT_EQ(read(log).find("CONFIG DIFFERS"), std::string::npos) << read(log);
}

TEST_F(Cli, CompareDoesNotJudgeRowsOfDifferentConfigurations) {
  const auto file = [&](const std::string& name) { return (dir_ / name).string(); };
  write_runs(file("old.json"), "a/b", 1.0, 5, "0000000000000001");
  write_runs(file("slow.json"), "a/b", 1.5, 5, "0000000000000001");
  write_runs(file("other.json"), "a/b", 1.5, 5, "0000000000000002");
  const std::string old = file("old.json"), log = file("log");
  EXPECT_EQ(clothbench("compare " + old + " " + file("slow.json")), 1);
  EXPECT_EQ(clothbench("compare " + old + " " + file("other.json"), log), 2);  // the only row is not judged
  EXPECT_NE(read(log).find("CONFIG DIFFERS"), std::string::npos) << read(log);
}

// --repetitions: a row per run (run_name, repetition_index) and Google Benchmark's aggregates, which compare
// reads back as samples of one benchmark
TEST_F(Cli, RunWithRepetitionsWritesEveryRunAndTheAggregates) {
  const std::string a = (dir_ / "a.json").string(), log = (dir_ / "log").string();
  ASSERT_EQ(clothbench("run --quiet --repetitions 5 " + kScenes + kSmallRun + " --json " + a, log), 0) << read(log);
  EXPECT_NE(read(log).find("5 repetitions: per iteration median"), std::string::npos) << read(log);
  const auto rows = nlohmann::json::parse(read(a))["benchmarks"];
  ASSERT_EQ(rows.size(), 9u);
  for (int i = 0; i < 5; ++i) {
    EXPECT_EQ(rows[i]["run_type"], "iteration");
    EXPECT_EQ(rows[i]["repetition_index"], i);
    EXPECT_EQ(rows[i]["run_name"], rows[0]["name"]);
  }
  const char* aggregates[] = {"mean", "median", "stddev", "cv"};
  for (int i = 0; i < 4; ++i) {
    const auto& g = rows[5 + i];
    EXPECT_EQ(g["run_type"], "aggregate");
    EXPECT_EQ(g["aggregate_name"], aggregates[i]);
    EXPECT_EQ(g["name"], rows[0]["name"].get<std::string>() + "_" + aggregates[i]);
    EXPECT_EQ(g["aggregate_unit"], i == 3 ? "percentage" : "time");
  }
  std::vector<double> t;
  for (int i = 0; i < 5; ++i) t.push_back(rows[i]["real_time"].get<double>());
  std::sort(t.begin(), t.end());
  EXPECT_DOUBLE_EQ(rows[6]["real_time"].get<double>(), t[2]);  // the median of the five
  // the same file on both sides: five samples each, judged, no regression
  EXPECT_EQ(clothbench("compare " + a + " " + a, log), 0) << read(log);
  EXPECT_NE(read(log).find("among 1 judged row(s)"), std::string::npos) << read(log);
}

// a sweep in shards: every point exactly once over the shards, a failing point reported with its error and
// exit status and the others kept, a re-run skipping what is done, merge joining the shards' folder (and refusing
// rows it could not tell apart)
TEST_F(Cli, SweepShardsKeepTheGoodPointsAndReportTheFailedOne) {
  if (!fs::exists(clothbench::kDebianHumanBody)) GTEST_SKIP() << clothbench::kDebianHumanBody << " missing";
  const std::string out = (dir_ / "sweep").string(), log = (dir_ / "log").string();
  const std::string grid = "sweep " + kScenes + "dressing/skirt.toml --collider is-cpu --set garment.vertices=100,-5,120 "
                           "--set stop.max_iterations=5 --out " + out;
  EXPECT_EQ(clothbench(grid + " --shard 0/2 --jobs 1", log), 0) << read(log);  // points 0 and 2: fine
  EXPECT_EQ(clothbench(grid + " --shard 1/2 --jobs 1", log), 5) << read(log);  // point 1: vertices = -5
  EXPECT_TRUE(fs::exists(dir_ / "sweep/points/0.json"));
  EXPECT_TRUE(fs::exists(dir_ / "sweep/points/1.error.json"));
  EXPECT_TRUE(fs::exists(dir_ / "sweep/points/2.json"));
  const std::string merged = (dir_ / "merged.json").string();
  EXPECT_EQ(clothbench("merge " + out + " --out " + merged, log), 5) << read(log);
  EXPECT_NE(read(log).find("FAILED is-cpu/garment.vertices=-5/stop.max_iterations=5 (point 1"), std::string::npos)
      << read(log);
  EXPECT_NE(read(log).find("exit status 2)"), std::string::npos) << read(log);
  const auto doc = nlohmann::json::parse(read(merged));
  EXPECT_EQ(doc["benchmarks"].size(), 2u);
  ASSERT_EQ(doc["failed"].size(), 1u);
  EXPECT_EQ(doc["failed"][0]["index"], 1);
  // one folder named twice, or two folders holding points of one name, would give rows nobody can tell apart
  EXPECT_EQ(clothbench("merge " + out + " " + out + " --out " + merged, log), 2) << read(log);
  EXPECT_NE(read(log).find("is named twice"), std::string::npos) << read(log);
  fs::copy(out, dir_ / "sweep-copy", fs::copy_options::recursive);
  EXPECT_EQ(clothbench("merge " + out + " " + (dir_ / "sweep-copy").string() + " --out " + merged, log), 2) << read(log);
  EXPECT_NE(read(log).find("both hold the point 'skirt/is-cpu/garment.vertices=100"), std::string::npos) << read(log);
  // done points are not run again; a folder of another grid is refused
  EXPECT_EQ(clothbench(grid + " --shard 0/2", log), 0) << read(log);
  EXPECT_NE(read(log).find("shard 0/2: 0 to run"), std::string::npos) << read(log);
  EXPECT_EQ(clothbench(grid + " --shard 1/2", log), 5) << read(log);  // a failed point is tried again
  EXPECT_NE(read(log).find("shard 1/2: 1 to run"), std::string::npos) << read(log);
  EXPECT_EQ(clothbench("sweep " + kScenes + "dressing/skirt.toml --out " + out, log), 2) << read(log);
  EXPECT_NE(read(log).find("holds another sweep"), std::string::npos) << read(log);
}

// a user's own sweep as the built-in experiments' page: one row per configuration (the median of its repetitions and
// their spread), the summary first, the JSON of the rows; a file of run --json too; a document of no runs is bad input
TEST_F(Cli, ReportOfAUsersSweepOpensWithItsSummaryAndKeepsEachConfiguration) {
  if (!fs::exists(clothbench::kDebianHumanBody)) GTEST_SKIP() << clothbench::kDebianHumanBody << " missing";
  const std::string sweep = (dir_ / "sweep").string(), report = (dir_ / "report").string();
  const std::string log = (dir_ / "log").string();
  ASSERT_EQ(clothbench("sweep " + kScenes +
                           "dressing/skirt.toml --collider is-cpu,embree --set "
                           "garment.vertices=100,120 --set stop.max_iterations=5 --repetitions 2 --jobs 2 --out " +
                           sweep,
                       log),
            0)
      << read(log);
  ASSERT_EQ(clothbench("report " + sweep + " --out " + report, log), 0) << read(log);
  const std::string md = read(report + "/sweep.md");
  EXPECT_EQ(line_starting(md, "**Summary"), "**Summary.**") << md;
  EXPECT_NE(md.find("- 4 configurations from " + sweep + ", 8 runs in all: "), std::string::npos) << md;
  EXPECT_NE(md.find("fewer than five runs per configuration"), std::string::npos) << md;
  for (const char* name : {"skirt/is-cpu/garment.vertices=100", "skirt/embree/garment.vertices=120"})
    EXPECT_NE(md.find(std::string("| ") + name), std::string::npos) << name << "\n" << md;
  const auto doc = nlohmann::json::parse(read(report + "/sweep.json"));
  EXPECT_EQ(doc["benchmarks"].size(), 4u);
  // run --json's file: one configuration of three runs
  const std::string json = (dir_ / "r.json").string();
  ASSERT_EQ(clothbench("run --quiet " + kScenes +
                           "dressing/skirt.toml --set garment.vertices=100 "
                           "stop.max_iterations=5 --repetitions 3 --json " +
                           json,
                       log),
            0)
      << read(log);
  ASSERT_EQ(clothbench("report " + json + " --out " + report, log), 0) << read(log);
  EXPECT_NE(read(report + "/sweep.md").find("- 1 configuration from " + json + ", 3 runs in all"), std::string::npos)
      << read(report + "/sweep.md");
  std::ofstream(dir_ / "empty.json") << "{\"benchmarks\": []}";
  EXPECT_EQ(clothbench("report " + (dir_ / "empty.json").string() + " --out " + report, log), 2);
  EXPECT_NE(read(log).find("no run rows"), std::string::npos) << read(log);
}

// given a reference drape (run --json --end-state), report measures every configuration swept with --end-state
// against it: the reference's own configuration is 0 away, the others are not; a reference file without an end state
// is bad input, and a sweep without end states says so in place of the figures
TEST_F(Cli, ReportMeasuresTheDrapeErrorAgainstAReferenceDrape) {
  if (!fs::exists(clothbench::kDebianHumanBody)) GTEST_SKIP() << clothbench::kDebianHumanBody << " missing";
  const auto file = [&](const std::string& name) { return (dir_ / name).string(); };
  const std::string sweep = file("sweep"), report = file("report"), ref = file("ref.json"), log = file("log");
  const std::string scene = kScenes + "dressing/skirt.toml", short_run = " --set stop.max_iterations=40";
  ASSERT_EQ(clothbench("run --quiet " + scene + " --collider embree --set garment.vertices=160" + short_run +
                           " --end-state --json " + ref,
                       log),
            0)
      << read(log);
  ASSERT_EQ(clothbench("sweep " + scene + " --collider is-cpu,embree --set garment.vertices=100,160" + short_run +
                           " --end-state --jobs 2 --out " + sweep,
                       log),
            0)
      << read(log);
  ASSERT_EQ(clothbench("report " + sweep + " --reference " + ref + " --out " + report, log), 0) << read(log);
  const std::string md = read(report + "/sweep.md");
  EXPECT_NE(md.find("drape error RMS / max [mm]"), std::string::npos) << md;
  EXPECT_NE(md.find("Drape error against the reference"), std::string::npos) << md;
  EXPECT_TRUE(fs::exists(report + "/sweep-drape-error.png"));
  const auto doc = nlohmann::json::parse(read(report + "/sweep.json"));
  ASSERT_EQ(doc["benchmarks"].size(), 4u);
  for (const auto& row : doc["benchmarks"]) {
    const std::string name = row["name"];
    ASSERT_TRUE(row.contains("drape_error_rms_mm")) << name;
    EXPECT_FALSE(row.contains("end_positions")) << name;
    if (name.find("embree/garment.vertices=160") != std::string::npos)
      EXPECT_EQ(row["drape_error_max_mm"].get<double>(), 0.0) << name;
    else
      EXPECT_GT(row["drape_error_rms_mm"].get<double>(), 0.0) << name;
  }
  // a reference that carries no end state; a sweep without end states
  const std::string plain = file("plain.json"), plain_sweep = file("plain-sweep");
  ASSERT_EQ(clothbench("run --quiet " + scene + " --set garment.vertices=100" + short_run + " --json " + plain, log), 0);
  EXPECT_EQ(clothbench("report " + sweep + " --reference " + plain + " --out " + report, log), 2);
  EXPECT_NE(read(log).find("no row carries its cloth's end state"), std::string::npos) << read(log);
  ASSERT_EQ(clothbench("report " + plain + " --reference " + ref + " --out " + report, log), 0) << read(log);
  EXPECT_NE(read(report + "/sweep.md").find("no configuration carries its end state"), std::string::npos)
      << read(report + "/sweep.md");
}

// the shipped rest body written again as a user's scan might come: vertex x, y, z mapped by `f`
void rewrite_body(const std::string& out, Eigen::Matrix3d f) {
  std::ifstream in(clothbench::data_path("body/mh_female_walk_rest.obj"));
  std::ofstream o(out);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("v ", 0) != 0) {
      o << line << "\n";
      continue;
    }
    std::istringstream v(line.substr(2));
    Eigen::Vector3d p;
    v >> p.x() >> p.y() >> p.z();
    const Eigen::Vector3d q = f * p;
    o << "v " << q.x() << " " << q.y() << " " << q.z() << "\n";
  }
}

// A user's journey from the README alone: their own body (a scan in centimetres, Z up; one turned to face +X is
// warned about), their own pattern, its placement checked before a run, a sweep over two colliders, the report of it,
// and a change that loses accuracy caught by compare
TEST_F(Cli, AUsersOwnBodyAndPatternRunSweepReportAndCompare) {
  if (!fs::exists(clothbench::data_path("body/mh_female_walk_rest.obj"))) GTEST_SKIP() << "no rest body";
  const auto file = [&](const std::string& name) { return (dir_ / name).string(); };
  const std::string log = file("log");
  Eigen::Matrix3d z_up_cm, facing_x;
  z_up_cm << 100, 0, 0, 0, 0, -100, 0, 100, 0;  // (x, y, z) -> (x, -z, y) in cm
  facing_x << 0, 0, 1, 0, 1, 0, -1, 0, 0;       // turned a quarter round Y
  rewrite_body(file("scan.obj"), z_up_cm);
  rewrite_body(file("turned.obj"), facing_x);
  ASSERT_EQ(clothbench("body " + file("scan.obj"), log), 0) << read(log);
  EXPECT_NE(read(log).find("turned +Y up"), std::string::npos) << read(log);
  EXPECT_NE(read(log).find("scaled by"), std::string::npos) << read(log);
  ASSERT_EQ(clothbench("body " + file("turned.obj"), log), 0) << read(log);
  EXPECT_NE(read(log).find("may face +-X"), std::string::npos) << read(log);
  // their pattern: a straight-sided skirt, its waist attached
  std::ofstream(file("aline.pattern")) << "garment aline\n"
                                          "panel front\n  place anchor 0.5 0.309 0.36 offset 0 0 20 wrap 20\n"
                                          "  start -28 0\n  edge hem line 28 0\n  edge right line 21 54\n"
                                          "  edge waist line -21 54\n  edge left close\n  attach waist\nend\n"
                                          "panel back\n  place anchor 0.5 0.309 0.36 offset 0 0 -20 yaw 180 wrap 20\n"
                                          "  start -28 0\n  edge hem line 28 0\n  edge right line 21 54\n"
                                          "  edge waist line -21 54\n  edge left close\n  attach waist\nend\n"
                                          "seam front.right back.left\nseam front.left back.right\n";
  ASSERT_EQ(
      clothbench("garment " + file("aline.pattern") + " --vertices 200 --on " + file("scan.obj") + " --json", log), 0)
      << read(log);
  const auto placed = nlohmann::json::parse(read(log).substr(read(log).find('{')))["placement"];
  EXPECT_LE(placed["inside_pct"].get<double>(), 1.0) << placed;
  EXPECT_GT(placed["attached"].get<long>(), 0) << placed;
  const auto scene = [&](const std::string& name, int vertices) {
    std::ofstream(file(name)) << "[scene]\nname = \"aline\"\n[body]\nfile = \"scan.obj\"\n[[garment]]\nfile = "
                                 "\"aline.pattern\"\nvertices = "
                              << vertices
                              << "\n[solver]\nthreshold = 0.10\n[stop]\nsew_max_s = 1.0\ndrape_max_s = 0.4\n";
  };
  scene("aline.toml", 600);
  scene("aline-coarse.toml", 150);  // the change under test: a coarser mesh, to run faster
  for (const char* s : {"aline", "aline-coarse"})
    ASSERT_EQ(clothbench("sweep " + file(std::string(s) + ".toml") +
                             " --collider is-cpu,embree --repetitions 2 "
                             "--jobs 2 --out " +
                             file(std::string(s) + "-sweep"),
                         log),
              0)
        << read(log);
  ASSERT_EQ(clothbench("report " + file("aline-sweep") + " --out " + file("report"), log), 0) << read(log);
  const std::string md = read(file("report/sweep.md"));
  EXPECT_NE(md.find("- 2 configurations from "), std::string::npos) << md;
  EXPECT_NE(md.find("- The fastest meeting every limit: aline/"), std::string::npos) << md;
  EXPECT_EQ(clothbench("compare " + file("aline-sweep/merged.json") + " " + file("aline-coarse-sweep/merged.json") +
                           " --pair-by collider",
                       log),
            1)
      << read(log);
  // the coarse mesh crosses the body with either collider: whichever row met the limits before stops meeting them
  EXPECT_NE(read(log).find(": stopped meeting the accuracy limits ("), std::string::npos) << read(log);
}

// the verdict against the accuracy limits: in the summary (never "converged yes" alone), in the
// JSON, and as exit code 4 under --strict
TEST_F(Cli, RunPrintsTheAccuracyVerdictAndStrictExitsFourWhenTheLimitsAreMissed) {
  const std::string json = (dir_ / "r.json").string(), log = (dir_ / "log").string();
  const int rc = clothbench("run --quiet --strict " + kScenes + kSmallRun + " --json " + json, log);
  const auto row = nlohmann::json::parse(read(json))["benchmarks"][0];
  ASSERT_TRUE(row.contains("meets_limits") && row.contains("limit_misses")) << row.dump();
  const bool meets = row["meets_limits"] == 1;
  EXPECT_EQ(meets, row["limit_misses"].empty());
  EXPECT_EQ(rc, meets ? 0 : 4) << read(log);
  std::string misses;
  for (const auto& m : row["limit_misses"]) misses += (misses.empty() ? "" : ", ") + m.get<std::string>();
  const std::string verdict = line_starting(read(log), "  converged ");
  EXPECT_NE(verdict.find(meets ? "; accuracy: meets the limits (inside <= 0.5 %, depth <= 5 mm, crossings <= 1 %"
                               : "; accuracy: MISSES the limits: " + misses),
            std::string::npos)
      << read(log);
  // without --strict the same run exits 0
  EXPECT_EQ(clothbench("run --quiet " + kScenes + kSmallRun, log), 0);
}

TEST(Limits, MissesNameTheValueAndTheLimit) {
  clothbench::RunResult r;
  EXPECT_TRUE(clothbench::limit_misses(r).empty());
  r.accuracy.inside_pct = 6.1;
  r.accuracy.crossings_pct = 1.94;
  r.accuracy.depth_max_mm = 5;  // at the limit: meets it
  EXPECT_EQ(clothbench::limit_misses(r), (std::vector<std::string>{"inside 6.1 % > 0.5 %", "crossings 1.94 % > 1 %"}));
  r = {};
  r.strain_threshold = 0.1;
  r.strain_max = 0.2;
  r.seam_gap_max_mm = NAN;
  EXPECT_EQ(clothbench::limit_misses(r), (std::vector<std::string>{"seam gap - mm > 2 mm", "strain 20 % > 11 %"}));
  EXPECT_EQ(clothbench::limit_misses(r, false), (std::vector<std::string>{"seam gap - mm > 2 mm"}));
  EXPECT_EQ(clothbench::limits_text(r),
            "inside <= 0.5 %, depth <= 5 mm, crossings <= 1 %, seam gap <= 2 mm, strain <= 11 %");
  r.strain_threshold = 0;  // no super-elasticity limit: no strain limit
  EXPECT_EQ(clothbench::limits_text(r), "inside <= 0.5 %, depth <= 5 mm, crossings <= 1 %, seam gap <= 2 mm");
  r.divergence = clothbench::Divergence{};
  EXPECT_EQ(clothbench::limit_misses(r), std::vector<std::string>{"diverged"});
}

// "estimate: sewing and draping at most about 2 min 25 s (brute, 1234 queries/iteration, up to 7000 iterations; ..."
const std::regex kEstimate(R"(estimate: (the animation about [^;]+; )?sewing and draping at most about )"
                           R"((\d+ h \d\d min|(\d+ min )?\d+ s|under 1 s) )"
                           R"(\(brute, \d+ queries/iteration, up to \d+ iterations;)");

TEST_F(Cli, RunEstimatePrintsTheEstimateAndSimulatesNothing) {
  const std::string log = (dir_ / "log").string();
  ASSERT_EQ(clothbench("run --quiet --estimate --collider brute " + kScenes + kSmallRun, log), 0) << read(log);
  EXPECT_TRUE(std::regex_search(read(log), kEstimate)) << read(log);
  EXPECT_EQ(read(log).find("accuracy"), std::string::npos) << read(log);
}

// progress lines (after the first second, once a second) carry an ETA
TEST_F(Cli, ProgressLinesCarryAnEta) {
  const std::string log = (dir_ / "log").string();
  // brute force on the tablecloth: about 30 ms per iteration here, 120 iterations (the drape never settles)
  ASSERT_EQ(clothbench("run --collider brute " + kScenes +
                           "walking/tablecloth_sphere.toml --set garment.vertices=400 --set body.move_s=0 "
                           "--set stop.drape_max_s=100 --set stop.settle_speed=0 --set stop.max_iterations=120",
                       log),
            0);
  const std::string progress = line_starting(read(log), "  [tablecloth-sphere/brute ");
  ASSERT_FALSE(progress.empty()) << read(log);
  EXPECT_TRUE(std::regex_search(
      progress, std::regex(R"(^  \[tablecloth-sphere/brute \d+ s, ETA <= (\d+ h \d\d min|(\d+ min )?\d+ s|under 1 s|\?)\] )")))
      << progress;
}

TEST(Estimate, DurationsForPeople) {
  EXPECT_EQ(clothbench::format_duration(0.37), "under 1 s");
  EXPECT_EQ(clothbench::format_duration(12.4), "12 s");
  EXPECT_EQ(clothbench::format_duration(145), "2 min 25 s");
  EXPECT_EQ(clothbench::format_duration(3725), "1 h 02 min");
  EXPECT_EQ(clothbench::format_duration(NAN), "?");
}

// a run prints its estimate up front when it exceeds estimate_above_s; the results do not depend
// on it (it steps a copy of the simulator and queries the collider), with any collider
TEST(Estimate, PrintedUpFrontAndTheResultsDoNotDependOnIt) {
  for (const std::string& collider : clothbench::available_colliders()) {
    const clothbench::Scene scene = clothbench::load_scene(
        kScenes + "walking/tablecloth_sphere.toml",
        {"garment.vertices=225", "body.move_s=0.05", "stop.drape_max_s=0.1", "collider.name=" + collider});
    clothbench::RunOptions quiet, loud;
    quiet.progress = false;
    loud.estimate_above_s = 0;
    const clothbench::RunResult a = clothbench::run_scene(scene, quiet);
    testing::internal::CaptureStderr();
    const clothbench::RunResult b = clothbench::run_scene(scene, loud);
    const std::string err = testing::internal::GetCapturedStderr();
    EXPECT_NE(err.find("[tablecloth-sphere/" + collider + "] estimate: the animation about "), std::string::npos)
        << err;
    EXPECT_NE(err.find("; sewing and draping at most about "), std::string::npos) << err;
    EXPECT_GT(b.estimate_s, 0) << collider;
    EXPECT_EQ(a.iteration_budget, b.iteration_budget) << collider;
    ASSERT_EQ(a.iterations(), b.iterations()) << collider;
    ASSERT_EQ(a.mesh.positions.size(), b.mesh.positions.size());
    EXPECT_TRUE(a.mesh.positions == b.mesh.positions) << collider << ": bit-identical with and without the estimate";
  }
}

}  // namespace
