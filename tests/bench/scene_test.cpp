// Scene files: defaults, every section read, unknown keys and bad values located at file:line, --set.
#include <gtest/gtest.h>

#include <unistd.h>
#include <filesystem>
#include <fstream>
#include <string>

#include "clothbench/bench/scene.hpp"
#include "clothbench/config.h"
#include "clothbench/io/errors.hpp"
#include "clothbench/sim/param_fields.hpp"

namespace clothbench {
namespace {

std::string error_of(const std::string& text, const std::vector<std::string>& sets = {}) {
  try {
    parse_scene(text, "s.toml", sets);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(Scene, DefaultsWhenEmpty) {
  const Scene s = parse_scene("", "empty.toml");
  EXPECT_EQ(s.name, "empty");
  EXPECT_EQ(s.collider, "is-cpu");
  EXPECT_EQ(s.body.file, "debian:human");
  EXPECT_TRUE(s.garments.empty());
  EXPECT_EQ(s.solver.limit, "impulses");
  EXPECT_EQ(s.collider_options.map_size, 320);
}

TEST(Scene, ReadsEverySection) {
  const Scene s = parse_scene(R"(
[scene]
name = "x"
[body]
file = "data:body/mh_female_walk.glb"
animation = "walk_07_01"
start_s = 1.0
end_s = 1.5
fps = 30
[[garment]]
file = "garments/skirt.pattern"
vertices = 336
[[garment]]
file = "garments/shirt.pattern"
spacing_cm = 3
[material]
k_structural = 40
[solver]
dt = 0.0002
limit = "directional"
threshold = 0.05
face_queries = true
gravity = [0, -9.81, 0]
[collider]
name = "embree"
map_size = 512
[stop]
drape_max_s = 0.5
)",
                              "s.toml");
  EXPECT_EQ(s.name, "x");
  EXPECT_EQ(s.body.animation, "walk_07_01");
  EXPECT_DOUBLE_EQ(s.body.fps, 30);
  ASSERT_EQ(s.garments.size(), 2u);
  EXPECT_EQ(s.garments[0].vertices, 336);
  EXPECT_DOUBLE_EQ(s.garments[1].spacing_cm, 3);
  EXPECT_FLOAT_EQ(s.material.k_structural, 40);
  EXPECT_FLOAT_EQ(s.solver.dt, 0.0002f);
  EXPECT_EQ(s.solver.limit, "directional");
  EXPECT_TRUE(s.solver.face_queries);
  EXPECT_EQ(s.collider, "embree");
  EXPECT_EQ(s.collider_options.map_size, 512);
  EXPECT_DOUBLE_EQ(s.stop.drape_max_s, 0.5);
}

TEST(Scene, ErrorsNameFileLineAndKey) {
  EXPECT_NE(error_of("[solver]\nlimt = \"velocity\"\n").find("s.toml:2: solver.limt"), std::string::npos);
  EXPECT_NE(error_of("[solver]\n\nlimit = \"fast\"\n").find("s.toml:3: solver.limit"), std::string::npos);
  EXPECT_NE(error_of("[material]\ndensity = -1\n").find("s.toml:2: material.density: must be in"), std::string::npos);
  EXPECT_NE(error_of("[material]\ndensity = nan\n").find("s.toml:2"), std::string::npos);
  EXPECT_NE(error_of("[collider]\nmap_size = 320.5\n").find("expected an integer"), std::string::npos);
  EXPECT_NE(error_of("[bodyy]\n").find("s.toml:1: unknown section 'bodyy'"), std::string::npos);
  EXPECT_NE(error_of("[body\n").find("s.toml:1"), std::string::npos);
  EXPECT_NE(error_of("[[garment]]\nvertices = 5\n").find("give a pattern file or a fit (neither"), std::string::npos);
  EXPECT_NE(error_of("[[garment]]\nfile = \"a.pattern\"\nfit = \"skirt\"\n")
                .find("s.toml:1: garment: give a pattern "
                      "file or a fit, not both"),
            std::string::npos);
  EXPECT_NE(error_of("[[garment]]\nfit = \"cape\"\n").find("garment.fit: expected a drafted garment type (skirt"),
            std::string::npos);
  EXPECT_NE(error_of("[[garment]]\nfit = \"skirt\"\nsize = \"XXL\"\n").find("S, M, L, XL"), std::string::npos);
  EXPECT_NE(error_of("[[garment]]\nfit = \"skirt\"\nease_cm = -0.5\n").find("expected -1 (the size's) or 0 to 100"),
            std::string::npos);
  EXPECT_EQ(error_of("[[garment]]\nfit = \"skirt\"\nsize = \"XL\"\nease_cm = 20\n"), "");
  EXPECT_NE(error_of("[solver]\nface_queries = 1\n").find("expected true or false"), std::string::npos);
}

TEST(Scene, SetOverridesAndItsErrors) {
  const Scene s = parse_scene("[[garment]]\nfile = \"a.pattern\"\n", "s.toml",
                              {"solver.limit=none", "garment.vertices=1800", "collider.name=fcl", "stop.sew=false"});
  EXPECT_EQ(s.solver.limit, "none");
  EXPECT_EQ(s.garments[0].vertices, 1800);
  EXPECT_EQ(s.collider, "fcl");
  EXPECT_FALSE(s.stop.sew);
  EXPECT_NE(error_of("", {"solver.nope=1"}).find("solver.nope (from --set): unknown key"), std::string::npos);
  EXPECT_NE(error_of("", {"novalue"}).find("expected section.key=value"), std::string::npos);
  EXPECT_NE(error_of("", {"garment.vertices=3"}).find("no [[garment]]"), std::string::npos);
  EXPECT_NE(error_of("", {"solver.threshold=abc"}).find("expected a number"), std::string::npos);
}

// a misspelt key names the nearest known key of its table, in a file and through --set
TEST(Scene, UnknownKeySuggestsTheNearestKnownKey) {
  const std::string file = error_of("[[garment]]\nfile = \"a.pattern\"\nvertice = 5\n");
  EXPECT_NE(file.find("s.toml:3: garment.vertice: unknown key `vertice` (did you mean `vertices`?)"), std::string::npos)
      << file;
  EXPECT_NE(error_of("[solver]\nthreshhold = 0.1\n").find("(did you mean `threshold`?)"), std::string::npos);
  EXPECT_NE(error_of("[collider]\nmapsize = 64\n").find("(did you mean `map_size`?)"), std::string::npos);
  const std::string set = error_of("[[garment]]\nfile = \"a.pattern\"\n", {"garment.vertice=5"});
  EXPECT_NE(set.find("garment.vertice (from --set): unknown key `vertice` (did you mean `vertices`?)"),
            std::string::npos)
      << set;
  // nothing close: the known keys of that table
  const std::string far = error_of("", {"stop.nope=1"});
  EXPECT_EQ(far.find("did you mean"), std::string::npos) << far;
  EXPECT_NE(far.find("(known: drape_max_s, max_iterations, "), std::string::npos) << far;
  EXPECT_NE(error_of("[bodyy]\n").find("unknown section 'bodyy' (did you mean `body`?)"), std::string::npos);
}

// the hash of the effective configuration: what the values are, not how the file spells them
TEST(Scene, ConfigHashFollowsTheEffectiveConfiguration) {
  const std::string text = "[[garment]]\nfile = \"a.pattern\"\nvertices = 400\n[solver]\nthreshold = 0.05\n";
  const Scene base = parse_scene(text, "s.toml");
  const std::string hash = config_hash(base);
  EXPECT_EQ(hash.size(), 16u);
  EXPECT_EQ(hash.find_first_not_of("0123456789abcdef"), std::string::npos) << hash;
  // the same values: another file name, a name, keys in another order, a default spelt out, --set to the same value
  EXPECT_EQ(config_hash(parse_scene(text, "other.toml")), hash);
  EXPECT_EQ(config_hash(parse_scene("[scene]\nname = \"x\"\n[solver]\nthreshold = 0.05\nlimit = \"impulses\"\n"
                                    "[[garment]]\nvertices = 400\nfile = \"a.pattern\"\n",
                                    "s.toml")),
            hash);
  EXPECT_EQ(config_hash(parse_scene(text, "s.toml", {"garment.vertices=400"})), hash);
  // any field of any section changes it
  for (const char* set :
       {"body.fps=30", "garment.vertices=401", "material.density=0.2", "solver.threshold=0.06",
        "solver.face_queries=true", "collider.name=brute", "collider.map_size=512", "collider.views=4",
        "collider.layers=3", "collider.side_layer_mm=3", "collider.tangent_plane=false", "stop.drape_max_s=0.5",
        "stop.max_iterations=10", "body.collision_triangles=8000"})
    EXPECT_NE(config_hash(parse_scene(text, "s.toml", {set})), hash) << set;
  Scene with_collider = base;
  with_collider.collider = "embree";  // `run --collider` after loading
  EXPECT_NE(config_hash(with_collider), hash);
  EXPECT_NE(config_text(base).find("garment.vertices = 400\n"), std::string::npos) << config_text(base);
}

// the files a run reads are part of its configuration: an edited pattern is another hash, the same bytes the same
TEST(Scene, ConfigHashFollowsTheBytesOfTheFilesItNames) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("cb_hash_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string pattern = (dir / "mine.pattern").string();
  const auto write = [&](const std::string& text) { std::ofstream(pattern, std::ios::trunc) << text; };
  const std::string scene = "[[garment]]\nfile = \"" + pattern + "\"\n";
  write("panel front\n  outline 0 0, 50 0, 50 110, 0 110\n");
  const std::string first = config_hash(parse_scene(scene, "s.toml"));
  write("panel front\n  outline 0 0, 50 0, 50 130, 0 130\n");
  const std::string edited = config_hash(parse_scene(scene, "s.toml"));
  EXPECT_NE(edited, first);
  write("panel front\n  outline 0 0, 50 0, 50 110, 0 110\n");
  EXPECT_EQ(config_hash(parse_scene(scene, "s.toml")), first);
  std::filesystem::remove_all(dir);
}

// image space beyond the papers: views 2, 4 or 6 only, the side layer's width in millimetres
TEST(Scene, ColliderViewsAndSideLayerWidth) {
  const Scene s = parse_scene("[collider]\nviews = 6\nside_layer_mm = 3\n", "s.toml");
  EXPECT_EQ(s.collider_options.views, 6);
  EXPECT_FLOAT_EQ(s.collider_options.side_layer_mm, 3.0f);
  EXPECT_EQ(parse_scene("", "s.toml").collider_options.views, 2);
  EXPECT_NE(config_text(s).find("collider.views = 6\n"), std::string::npos) << config_text(s);
  for (const char* bad : {"3", "1", "8", "0"}) {
    const std::string e = error_of(std::string("[collider]\nviews = ") + bad + "\n");
    EXPECT_NE(e.find("s.toml:2"), std::string::npos) << e;
    EXPECT_NE(e.find("collider.views"), std::string::npos) << e;
    EXPECT_NE(e.find("2 (front/back), 4 (+ left/right) or 6 (+ top/bottom), got " + std::string(bad)),
              std::string::npos)
        << e;
  }
  EXPECT_NE(error_of("", {"collider.views=3"}).find("collider.views (from --set): must be 2"), std::string::npos);
  EXPECT_NE(error_of("[collider]\nside_layer_mm = -1\n").find("collider.side_layer_mm"), std::string::npos);
  // peeled layers: 1 (the papers' nearest surface) to 8, whole numbers
  EXPECT_EQ(parse_scene("", "s.toml").collider_options.layers, 1);
  EXPECT_EQ(parse_scene("[collider]\nlayers = 3\n", "s.toml").collider_options.layers, 3);
  for (const char* bad : {"0", "9", "2.5"}) {
    const std::string e = error_of(std::string("[collider]\nlayers = ") + bad + "\n");
    EXPECT_NE(e.find("s.toml:2"), std::string::npos) << e;
    EXPECT_NE(e.find("collider.layers"), std::string::npos) << e;
  }
}

// the moving body's skin must stay below the hit distance, or every contact would be pushed out
TEST(Scene, BodySkinIsReadAndMustStayBelowTheHitDistance) {
  const Scene s = parse_scene("[body]\nskin_mm = 4\n", "s.toml");
  EXPECT_EQ(s.body.skin_mm, 4);
  EXPECT_EQ(parse_scene("", "s.toml").body.skin_mm, 0);
  EXPECT_NE(config_text(s).find("body.skin_mm = 4\n"), std::string::npos) << config_text(s);
  const std::string e = error_of("[body]\nskin_mm = 5\n");
  EXPECT_NE(e.find("body.skin_mm"), std::string::npos) << e;
  EXPECT_NE(e.find("below collider.tol"), std::string::npos) << e;
  EXPECT_EQ(error_of("[body]\nskin_mm = 7\n[collider]\ntol = 0.008\n"), "");
  EXPECT_NE(error_of("[body]\nskin_mm = -1\n").find("body.skin_mm"), std::string::npos);
}

TEST(Scene, BodyPoseFpsIsZeroOrAWholeMultipleOfFps) {
  const Scene s = parse_scene("[body]\nfps = 30\npose_fps = 90\n", "s.toml");
  EXPECT_EQ(poses_per_frame(s.body), 3);
  EXPECT_EQ(poses_per_frame(parse_scene("", "s.toml").body), 1);
  EXPECT_EQ(config_text(parse_scene("", "s.toml")).find("pose_fps"), std::string::npos) << "unset, it is not hashed";
  EXPECT_NE(config_hash(s), config_hash(parse_scene("[body]\nfps = 30\n", "s.toml")));
  for (const char* bad : {"45", "20", "-30"}) {
    const std::string e = error_of(std::string("[body]\nfps = 30\npose_fps = ") + bad + "\n");
    EXPECT_NE(e.find("body.pose_fps"), std::string::npos) << bad << ": " << e;
  }
  const std::string e = error_of("[body]\nfps = 30\npose_fps = 45\n");
  EXPECT_NE(e.find("pose_fps = 45: must be 0 (once per frame) or a whole multiple of body.fps (30)"), std::string::npos)
      << e;
}

// jittered placements for claims' spread
TEST(Scene, GarmentJitterAndSeedAreReadAndHashed) {
  const std::string text = "[[garment]]\nfile = \"a.pattern\"\njitter_mm = 5\nseed = 3\n";
  const Scene s = parse_scene(text, "s.toml");
  ASSERT_EQ(s.garments.size(), 1u);
  EXPECT_EQ(s.garments[0].jitter_mm, 5);
  EXPECT_EQ(s.garments[0].seed, 3);
  EXPECT_NE(config_hash(s), config_hash(parse_scene(text, "s.toml", {"garment.seed=4"})));
  EXPECT_NE(error_of(text, {"garment.jitter_mm=-1"}).find("garment.jitter_mm"), std::string::npos);
}

TEST(Scene, MissingFileAndPathResolution) {
  EXPECT_THROW(load_scene("/nonexistent/scene.toml"), InputError);
  Scene s;
  s.path = std::string(CLOTHBENCH_SOURCE_DIR) + "/scenes/dressing/shirt.toml";
  EXPECT_EQ(resolve_scene_path(s, "debian:human"), "/usr/share/assimp/models/Collada/human.zae");
  EXPECT_TRUE(std::filesystem::exists(resolve_scene_path(s, "garments/shirt.pattern")));
}

// the field tables read, check and hash every key; the scene reference must name each one
TEST(Scene, ReadmeDocumentsEveryKey) {
  std::ifstream in(std::string(CLOTHBENCH_SOURCE_DIR) + "/scenes/README.md");
  const std::string readme((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string table = readme.substr(readme.find("## Scene files"));
  const std::vector<SceneKey> keys = scene_keys();
  EXPECT_GT(keys.size(), 80u);
  for (const SceneKey& k : keys) {
    EXPECT_NE(table.find("`" + k.key + "`"), std::string::npos) << k.section << "." << k.key << " (" << k.doc << ")";
    EXPECT_FALSE(k.doc.empty()) << k.section << "." << k.key;
  }
}

// a value the reader accepts is one the simulator accepts: both check the same rows
TEST(Scene, ReaderAndSimulatorShareTheBounds) {
  EXPECT_NE(error_of("[solver]\nthreshold = 1.5\n").find("solver.threshold: must be in [0.0001, 1]"),
            std::string::npos);
  EXPECT_NE(error_of("[solver]\nbounds_margin = 0\n").find("solver.bounds_margin: must be in"), std::string::npos);
  Scene s = parse_scene("[solver]\nthreshold = 1\nbounds_margin = 7\n", "s.toml");
  EXPECT_EQ(s.solver.bounds_margin, 7.f);
  EXPECT_NE(config_text(s).find("solver.bounds_margin = 7\n"), std::string::npos);
  // Simulator's validation (fields::check_fields) on the same rows
  SolverParams p;
  p.threshold = 1.5f;
  EXPECT_THROW(fields::check_fields(p), std::invalid_argument);
  p.threshold = 1;
  EXPECT_NO_THROW(fields::check_fields(p));
}

// every default and every preset lies within its rows' bounds
TEST(Scene, DefaultsAndPresetsAreValid) {
  for (const Regime r : {Regime::kStable, Regime::kPapers}) {
    Material m;
    SolverParams p;
    apply_regime(r, m, p);
    EXPECT_NO_THROW(fields::check_fields(m)) << to_string(r);
    EXPECT_NO_THROW(fields::check_fields(p)) << to_string(r);
  }
  EXPECT_NO_THROW(fields::check_fields(ColliderOptions{}));
}

// a regime given with --set other than the file's own runs the scene under that preset: the file's values of the keys
// the presets decide differently give way (not those they leave alone), and --set keys still apply after it
TEST(Scene, ARegimeGivenWithSetOverridesTheFilesPresetKeys) {
  const std::string text =
      "[solver]\nlimit_passes = 16\nmerge_distance = 0.004\nthreshold = 0.08\n"
      "[material]\nk_structural = 90\ndamping = 5\n";
  const Scene own = parse_scene(text, "s.toml");
  EXPECT_EQ(own.solver.limit_passes, 16);
  EXPECT_EQ(own.material.k_structural, 90.f);
  Material pm;
  SolverParams pp;
  apply_regime(Regime::kPapers, pm, pp);
  const Scene papers = parse_scene(text, "s.toml", {"solver.regime=papers"});
  EXPECT_EQ(papers.solver.regime, Regime::kPapers);
  EXPECT_EQ(papers.solver.limit_passes, pp.limit_passes);
  EXPECT_EQ(papers.solver.merge_distance, pp.merge_distance);
  EXPECT_EQ(papers.solver.dt, pp.dt);
  EXPECT_EQ(papers.material.k_structural, pm.k_structural);
  // keys the presets leave alone stay the file's
  EXPECT_EQ(papers.solver.threshold, 0.08f);
  EXPECT_EQ(papers.material.damping, 5.f);
  const Scene more = parse_scene(text, "s.toml", {"solver.regime=papers", "solver.limit_passes=4"});
  EXPECT_EQ(more.solver.limit_passes, 4);
  // the file's own regime given again changes nothing
  EXPECT_EQ(parse_scene(text, "s.toml", {"solver.regime=stable"}).solver.limit_passes, 16);
  const std::string papers_file = "[solver]\nregime = \"papers\"\nlimit_passes = 4\n";
  EXPECT_EQ(parse_scene(papers_file, "s.toml", {"solver.regime=papers"}).solver.limit_passes, 4);
  EXPECT_EQ(parse_scene(papers_file, "s.toml", {"solver.regime=\"papers\""}).solver.limit_passes, 4);  // TOML text
  EXPECT_EQ(parse_scene(papers_file, "s.toml", {"solver.regime=stable"}).solver.limit_passes,
            SolverParams{}.limit_passes);
}

TEST(Scene, EveryCommittedSceneParses) {
  int n = 0;
  for (const auto& e : std::filesystem::recursive_directory_iterator(std::string(CLOTHBENCH_SOURCE_DIR) + "/scenes"))
    if (e.path().extension() == ".toml") {
      const Scene s = load_scene(e.path().string());
      for (const auto& g : s.garments)
        if (g.fit.empty()) {
          EXPECT_TRUE(std::filesystem::exists(resolve_scene_path(s, g.file))) << g.file;
        }
      ++n;
    }
  EXPECT_GE(n, 8);
}

}  // namespace
}  // namespace clothbench
