// pictures: the meshed garments (results/garments) and the body maps (results/maps), drawn by render/'s
// library functions, the ones the `garment --png` and `maps --png` commands use.
#include <algorithm>
#include <filesystem>
#include <iomanip>
#include <sstream>

#include "clothbench/collide_is/map_set.hpp"
#include "clothbench/config.h"
#include "clothbench/experiments/experiment.hpp"
#include "clothbench/io/body_loader.hpp"
#include "clothbench/io/data_root.hpp"
#include "clothbench/io/pattern_file.hpp"
#include "clothbench/io/pattern_loader.hpp"
#include "clothbench/render/map_pictures.hpp"
#include "clothbench/render/pattern_picture.hpp"
#include "experiment_list.hpp"

namespace clothbench {

namespace {

namespace fs = std::filesystem;

// the renderer `maps` uses by default: OpenGL (OSMesa) in builds with CLOTHBENCH_WITH_GL, else the CPU rasteriser
#ifdef CLOTHBENCH_WITH_GL
constexpr const char* kMapRenderer = "gl";
#else
constexpr const char* kMapRenderer = "cpu";
#endif
// the grid spacing `garment` meshes at when no vertex count is given [cm]
constexpr double kGarmentSpacingCm = 2.0;

std::vector<std::string> sorted_files(const std::string& dir, const std::string& extension) {
  std::vector<std::string> out;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().extension() == extension) out.push_back(e.path().string());
  std::sort(out.begin(), out.end());
  return out;
}

// as `clothbench garment FILE --png PNG`
void garment_picture(const std::string& file, const std::string& png) {
  const Pattern pattern = load_pattern(file);
  MeshingOptions options;
  options.spacing_cm = kGarmentSpacingCm;
  draw_pattern(pattern, mesh_pattern(pattern, options)).write_png(png);
}

// as `clothbench maps BODY [--animation NAME --at SECONDS] --png DIR` (320^2, the default renderer)
void map_pictures(const std::string& body, const std::string& dir, const std::string& animation = "", double at_s = 0) {
  const BodyModel model = load_body(body);
  BodyFrame frame = model.rest();
  std::string stem = fs::path(body).stem().string();
  if (!animation.empty()) {
    frame = model.frame(model.animation_index(animation), at_s);
    std::ostringstream suffix;
    suffix << "_" << animation << "_t" << std::fixed << std::setprecision(2) << at_s << "s";
    stem += suffix.str();
  } else {
    stem += "_rest";
  }
  ColliderOptions options;
  options.map_size = 320;
  write_map_pictures(render_maps(frame, kMapRenderer, options), (fs::path(dir) / stem).string());
}

void pictures(ExperimentContext& ctx) {
  std::vector<std::string> written;
  // every garment file (in name order), and the GarmentCode specifications of the data root
  for (const auto& file : sorted_files(std::string(CLOTHBENCH_SOURCE_DIR) + "/scenes/garments", ".pattern")) {
    const std::string png = ctx.path("garments/" + fs::path(file).stem().string() + ".png");
    garment_picture(file, png);
    written.push_back(png);
  }
  const fs::path gc = data_path("garments/garmentcode");
  std::error_code ec;
  if (fs::is_directory(gc, ec))
    for (const auto& file : sorted_files(gc.string(), ".json")) {
      std::string stem = fs::path(file).stem().string();
      stem = stem.substr(0, stem.rfind("_specification"));
      const std::string png = ctx.path("garments/garmentcode_" + stem + ".png");
      garment_picture(file, png);
      written.push_back(png);
    }
  // maps of the walking body at rest and in a walking frame (Debian's body when the data root is absent)
  const std::string walker = data_path("body/mh_female_walk.glb");
  const std::string maps = ctx.folder("maps");
  if (fs::exists(walker)) {
    map_pictures(walker, maps);
    map_pictures(walker, maps, "walk_07_01", 2);
  } else {
    map_pictures(kDebianHumanBody, maps);
  }
  std::string body = "Meshed garment patterns (`clothbench garment FILE --png`, default spacing) and front/back body "
                     "maps (`clothbench maps BODY --png DIR`: depth, normal and, for a moving frame, velocity).\n\n";
  for (const auto& png : written) {
    const std::string rel = fs::relative(png, ctx.folder(".")).string();
    body += "![" + rel + "](" + rel + ")\n";
  }
  for (const auto& file : sorted_files(maps, ".png")) {
    const std::string name = fs::path(file).filename().string();
    body += "![maps/" + name + "](maps/" + name + ")\n";
  }
  ctx.write("pictures", "Garment meshes and body maps", body,
            {"The papers: cutting patterns meshed into regular grids (dressing section 3, Durupinar section 2) and "
             "the body's depth, normal and velocity maps (dressing section 5, walking section 2).",
             "Ours: " + std::to_string(written.size()) + " garment pictures and " +
                 std::to_string(sorted_files(maps, ".png").size()) + " map pictures, drawn by this run.",
             "No verdict: the pictures show what the other pages measure."});
}

}  // namespace

void add_pictures_experiments(std::vector<Experiment>& out) {
  out.push_back({"pictures", "Garment meshes and body maps", pictures});
}

}  // namespace clothbench
