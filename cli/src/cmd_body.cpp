// clothbench body FILE [--animation NAME --at SECONDS] [--walk-in-place] [--json]: what was loaded
#include <algorithm>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>

#include "clothbench/io/body_loader.hpp"
#include "commands.hpp"

namespace clothbench::cli {

namespace {

struct BodyArgs {
  std::string file, animation;
  double at = 0;
  bool walk_in_place = false, json = false, open_ok = false;
};

Real max_speed(const BodyFrame& frame) {
  Real v = 0;
  for (Eigen::Index i = 0; i < frame.velocities.cols(); ++i) v = std::max(v, frame.velocities.col(i).norm());
  return v;
}

std::vector<double> to_vec(const Vec3& v) { return {v.x(), v.y(), v.z()}; }

int run_body(const BodyArgs& a) {
  BodyLoadOptions options;
  options.require_closed = !a.open_ok;
  const BodyModel model = load_body(a.file, options);
  // the frame asked for: the rest mesh unless an animation is named
  BodyFrame frame = model.rest();
  if (!a.animation.empty()) frame = model.frame(model.animation_index(a.animation), a.at, a.walk_in_place);
  const Box3 box = bounding_box(frame.positions);
  const EdgeCheck edges = check_edges(frame.triangles);
  nlohmann::json j;
  j["file"] = a.file;
  j["vertices"] = frame.positions.cols();
  j["triangles"] = frame.triangles.cols();
  j["closed"] = edges.closed();
  j["boundary_edges"] = edges.boundary_edges;
  j["bbox_min"] = to_vec(box.min);
  j["bbox_max"] = to_vec(box.max);
  j["height_m"] = box.size().y();
  j["dropped_parts"] = model.dropped_parts();
  j["dropped_vertices"] = model.dropped_vertices();
  j["bones"] = model.bone_count();
  j["animations"] = nlohmann::json::array();
  for (const auto& anim : model.animations()) j["animations"].push_back({{"name", anim.name}, {"duration_s", anim.duration_s}});
  if (!a.animation.empty()) {
    j["animation"] = a.animation;
    j["at_s"] = a.at;
  }
  j["max_speed_mps"] = max_speed(frame);
  j["notes"] = model.notes();
  if (a.json) {
    std::cout << j.dump(2) << "\n";
    return 0;
  }
  std::cout << a.file << "\n"
            << "  vertices " << j["vertices"] << ", triangles " << j["triangles"] << ", "
            << (edges.closed() ? "closed" : "open (" + std::to_string(edges.boundary_edges) + " boundary edges)") << "\n"
            << "  bounding box " << j["bbox_min"] << " .. " << j["bbox_max"] << " m, height " << box.size().y() << " m\n"
            << "  small open parts dropped " << model.dropped_parts() << " (" << model.dropped_vertices() << " vertices)\n"
            << "  bones " << model.bone_count() << ", animations " << model.animations().size() << "\n";
  for (const auto& anim : model.animations()) std::cout << "    " << anim.name << "  " << anim.duration_s << " s\n";
  if (!a.animation.empty())
    std::cout << "  at " << a.at << " s of " << a.animation << (a.walk_in_place ? " (walking in place)" : "") << ": ";
  std::cout << "  max vertex speed " << j["max_speed_mps"] << " m/s\n";
  for (const std::string& n : model.notes()) std::cout << "  " << n << "\n";
  return 0;
}

}  // namespace

void add_body_command(CLI::App& app, Action& action) {
  auto args = std::make_shared<BodyArgs>();
  auto* cmd = app.add_subcommand("body", "Load a body (any format assimp reads) and print what was loaded");
  cmd->add_option("file", args->file, "body mesh file")->required();
  cmd->add_option("--animation", args->animation, "animation name (default: the rest pose)");
  cmd->add_option("--at", args->at, "time in the animation [s]")->check(CLI::NonNegativeNumber);
  cmd->add_flag("--walk-in-place", args->walk_in_place, "remove the root's horizontal travel");
  cmd->add_flag("--open-ok", args->open_ok, "accept a mesh that is not closed");
  cmd->add_flag("--json", args->json, "print JSON");
  cmd->callback([&action, args] { action = [args] { return run_body(*args); }; });
}

}  // namespace clothbench::cli
