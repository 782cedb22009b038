// pictures: the meshed garments (results/garments) and the body maps (results/maps), drawn by the
// `garment` and `maps` commands of this same executable so `reproduce` regenerates them too.
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <iostream>

#include "clothbench/config.h"
#include "clothbench/experiments/experiment.hpp"
#include "clothbench/io/data_root.hpp"
#include "clothbench/io/errors.hpp"

namespace clothbench {

namespace {

namespace fs = std::filesystem;

std::string self() {
  std::error_code ec;
  const fs::path p = fs::read_symlink("/proc/self/exe", ec);
  if (ec) throw InputError("cannot find the clothbench executable (/proc/self/exe): " + ec.message());
  return p.string();
}

std::vector<std::string> sorted_files(const std::string& dir, const std::string& extension) {
  std::vector<std::string> out;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().extension() == extension) out.push_back(e.path().string());
  std::sort(out.begin(), out.end());
  return out;
}

void command(const std::string& args) {
  const std::string line = "'" + self() + "' " + args + " > /dev/null";
  if (std::system(line.c_str()) != 0) throw InputError("picture command failed: clothbench " + args);
}

void pictures(ExperimentContext& ctx) {
  std::vector<std::string> written;
  // every garment file (in name order), and the GarmentCode specifications of the data root
  for (const auto& file : sorted_files(std::string(CLOTHBENCH_SOURCE_DIR) + "/scenes/garments", ".pattern")) {
    const std::string png = ctx.path("garments/" + fs::path(file).stem().string() + ".png");
    command("garment '" + file + "' --png '" + png + "'");
    written.push_back(png);
  }
  const fs::path gc = data_path("garments/garmentcode");
  std::error_code ec;
  if (fs::is_directory(gc, ec))
    for (const auto& file : sorted_files(gc.string(), ".json")) {
      std::string stem = fs::path(file).stem().string();
      stem = stem.substr(0, stem.rfind("_specification"));
      const std::string png = ctx.path("garments/garmentcode_" + stem + ".png");
      command("garment '" + file + "' --png '" + png + "'");
      written.push_back(png);
    }
  // maps of the walking body at rest and in a walking frame (Debian's body when the data root is absent)
  const std::string walker = data_path("body/mh_female_walk.glb");
  const std::string maps = ctx.folder("maps");
  if (fs::exists(walker)) {
    command("maps '" + walker + "' --png '" + maps + "'");
    command("maps '" + walker + "' --animation walk_07_01 --at 2 --png '" + maps + "'");
  } else {
    command("maps '" + std::string(kDebianHumanBody) + "' --png '" + maps + "'");
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
  ctx.write("pictures", "Garment meshes and body maps", body);
}

}  // namespace

void add_picture_experiments(std::vector<Experiment>& out) {
  out.push_back({"pictures", "Garment meshes and body maps", pictures});
}

}  // namespace clothbench
