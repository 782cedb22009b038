// clothbench maps: pictures of a body's front/back depth, normal and velocity maps
#include <algorithm>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>

#include "clothbench/collide_is/map_set.hpp"
#include "clothbench/config.h"
#ifdef CLOTHBENCH_WITH_EGL
#include "clothbench/collide_is/egl_collider.hpp"
#endif
#include "clothbench/io/body_loader.hpp"
#include "clothbench/io/errors.hpp"
#include "clothbench/render/map_pictures.hpp"
#include "clothbench/sim/timer.hpp"
#include "commands.hpp"

namespace clothbench::cli {
namespace {

// OpenGL (OSMesa) in builds with CLOTHBENCH_WITH_GL, else the CPU rasteriser
#ifdef CLOTHBENCH_WITH_GL
constexpr const char* kDefaultRenderer = "gl";
#else
constexpr const char* kDefaultRenderer = "cpu";
#endif

struct MapsArgs {
  std::string body;
  std::string animation;
  double at_s = 0;
  std::string renderer = kDefaultRenderer;
  int size = 320;
  std::string png_dir;
};

// the maps by renderer name; egl from its own library
MapSet maps_of(const BodyFrame& frame, const std::string& renderer, const ColliderOptions& options) {
#ifndef CLOTHBENCH_WITH_GL
  if (renderer == "gl")
    throw InputError(
        "maps --renderer gl: this build has no OpenGL renderer (configure with -DCLOTHBENCH_WITH_GL=ON); "
        "--renderer cpu draws the same maps");
#endif
  if (renderer != "egl") return render_maps(frame, renderer, options);
#ifdef CLOTHBENCH_WITH_EGL
  const auto egl = make_egl_map_renderer();
  std::cout << "egl: " << egl->device() << "\n";
  return render_maps(frame, *egl, options);
#else
  throw InputError("maps --renderer egl: this build has no EGL renderer (configure with -DCLOTHBENCH_WITH_EGL=ON)");
#endif
}

int run_maps(const MapsArgs& a) {
  // the body at rest or at one instant of an animation
  const BodyModel model = load_body(a.body);
  BodyFrame frame = model.rest();
  std::string stem = std::filesystem::path(a.body).stem().string();
  if (!a.animation.empty()) {
    frame = model.frame(model.animation_index(a.animation), a.at_s);
    std::ostringstream suffix;
    suffix << "_" << a.animation << "_t" << std::fixed << std::setprecision(2) << a.at_s << "s";
    stem += suffix.str();
  } else {
    stem += "_rest";
  }
  // the maps, side layer included
  ColliderOptions options;
  options.map_size = a.size;
  Stopwatch watch;
  const MapSet m = maps_of(frame, a.renderer, options);
  long covered = 0, side = 0;
  for (const auto k : m.mask) {
    covered += k == MapSet::kBody;
    side += k == MapSet::kSide;
  }
  std::cout << a.body << ": " << a.renderer << " maps " << a.size << "^2 in " << watch.ms()
            << " ms (incl. set-up), pixel " << m.frame.pixel * 1000 << " mm, body pixels " << covered << ", side layer "
            << side << "\n";
  // the pictures
  std::filesystem::create_directories(a.png_dir);
  const std::string base = (std::filesystem::path(a.png_dir) / stem).string();
  for (const std::string& path : write_map_pictures(m, base)) std::cout << "wrote " << path << "\n";
  return 0;
}

}  // namespace

void add_maps_command(CLI::App& app, Action& action) {
  auto args = std::make_shared<MapsArgs>();
  auto* cmd = app.add_subcommand("maps", "Write pictures of a body's front/back depth, normal and velocity maps");
  cmd->add_option("body", args->body, "body file (any format assimp reads)")->required();
  cmd->add_option("--animation", args->animation, "animation name (default: the rest pose)");
  cmd->add_option("--at", args->at_s, "animation time [s]")->check(CLI::NonNegativeNumber);
  cmd->add_option("--renderer", args->renderer,
                  std::string("gl (OSMesa; builds with CLOTHBENCH_WITH_GL), egl (windowless EGL, a GPU where there is "
                              "one; CLOTHBENCH_WITH_EGL) or cpu (default: ") +
                      kDefaultRenderer + ")")
      ->check(CLI::IsMember({"gl", "egl", "cpu"}));
  cmd->add_option("--size", args->size, "map size [pixels]")->check(CLI::Range(8, 8192))->capture_default_str();
  cmd->add_option("--png", args->png_dir, "output folder")->required();
  cmd->callback([&action, args] { action = [args] { return run_maps(*args); }; });
}

}  // namespace clothbench::cli
