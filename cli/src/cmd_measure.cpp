// clothbench measure BODY [--animation NAME --at SECONDS] [--json]: the body's girths and lengths as a tailor takes
// them (Durupinar section 2), found from its mesh
#include <iomanip>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>

#include "clothbench/io/body_loader.hpp"
#include "clothbench/sim/body_measure.hpp"
#include "commands.hpp"

namespace clothbench::cli {

namespace {

struct MeasureArgs {
  std::string file, animation;
  double at = 0;
  bool json = false;
};

int run_measure(const MeasureArgs& a) {
  const BodyModel model = load_body(a.file);
  const BodyFrame frame =
      a.animation.empty() ? model.rest() : model.frame(model.animation_index(a.animation), a.at, true);
  const BodyMeasurements m = measure_body(frame);
  if (a.json) {
    nlohmann::json j{{"file", a.file}, {"measurements", nlohmann::json::array()}};
    if (!a.animation.empty()) j["animation"] = a.animation, j["at_s"] = a.at;
    for (const Measurement& x : m.all)
      j["measurements"].push_back({{"name", x.name}, {"value_m", x.value_m}, {"height_m", x.height_m}, {"how", x.how}});
    std::cout << j.dump(2) << "\n";
    return 0;
  }
  std::cout << a.file;
  if (a.animation.empty())
    std::cout << " (rest pose)\n";
  else
    std::cout << " at " << a.at << " s of " << a.animation << "\n";
  for (const Measurement& x : m.all)
    std::cout << "  " << std::left << std::setw(18) << x.name << std::right << std::fixed << std::setprecision(1)
              << std::setw(7) << 100 * x.value_m << " cm   at " << std::setw(6) << 100 * x.height_m << " cm   " << x.how
              << "\n";
  for (const std::string& n : model.notes()) std::cout << "  " << n << "\n";
  return 0;
}

}  // namespace

void add_measure_command(CLI::App& app, Action& action) {
  auto args = std::make_shared<MeasureArgs>();
  auto* cmd = app.add_subcommand(
      "measure", "A body's girths and lengths from its mesh (standing, arms away from the torso below the armpits)");
  cmd->add_option("file", args->file, "body mesh file, or a data reference (debian:human)")->required();
  cmd->add_option("--animation", args->animation, "animation name (default: the rest pose)");
  cmd->add_option("--at", args->at, "time in the animation [s]")->check(CLI::NonNegativeNumber);
  cmd->add_flag("--json", args->json, "print JSON");
  cmd->callback([&action, args] { action = [args] { return run_measure(*args); }; });
}

}  // namespace clothbench::cli
