// clothbench measure BODY [--animation NAME --at SECONDS] [--json] [--draft TYPE [--size S|M|L|XL | --ease CM]
// --out FILE.pattern]: the body's girths and lengths as a tailor takes them (Durupinar section 2), found from its
// mesh, and a garment drafted from them
#include <fstream>
#include <iomanip>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>

#include "clothbench/io/body_loader.hpp"
#include "clothbench/io/errors.hpp"
#include "clothbench/io/pattern_file.hpp"
#include "clothbench/sim/body_measure.hpp"
#include "clothbench/sim/garment_draft.hpp"
#include "commands.hpp"

namespace clothbench::cli {

namespace {

struct MeasureArgs {
  std::string file, animation, draft, size = "M", out;
  double at = 0, ease_cm = -1;  // ease < 0: the size's
  bool json = false;
};

// the drafted garment's pattern file; what it is, on stderr
void write_draft(const MeasureArgs& a, const BodyFrame& frame, const BodyMeasurements& m) {
  if (a.out.empty()) throw InputError("measure: --draft needs --out FILE.pattern");
  const double ease = a.ease_cm >= 0 ? a.ease_cm : size_ease_cm(a.size);
  const Pattern p = draft_garment(a.draft, frame, m, ease);
  std::ofstream out(a.out);
  out << "# " << a.draft << " drafted by `clothbench measure " << a.file << " --draft " << a.draft << "` with " << ease
      << " cm of ease at the hip (Durupinar section 2: the panels from the body's measurements)\n"
      << write_pattern(p);
  if (!out) throw InputError("measure: cannot write " + a.out);
  std::cerr << "wrote " << a.out << ": " << a.draft << ", " << ease << " cm of ease at the hip\n";
}

int run_measure(const MeasureArgs& a) {
  const BodyModel model = load_body(a.file);
  const BodyFrame frame =
      a.animation.empty() ? model.rest() : model.frame(model.animation_index(a.animation), a.at, true);
  const BodyMeasurements m = measure_body(frame);
  if (!a.draft.empty()) write_draft(a, frame, m);
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
  std::string types;
  for (const std::string& t : draft_types()) types += (types.empty() ? "" : ", ") + t;
  cmd->add_option("--draft", args->draft, "draft a garment from the measurements: " + types);
  auto* size =
      cmd->add_option("--size", args->size, "the garment's size: its ease at the hip, S 4, M 8, L 12, XL 16 cm")
          ->check(CLI::IsMember(draft_sizes()))
          ->capture_default_str();
  cmd->add_option("--ease", args->ease_cm, "the ease at the hip [cm], instead of --size")
      ->check(CLI::Range(0.0, 100.0))
      ->excludes(size);
  cmd->add_option("--out", args->out, "the drafted garment's pattern file (with --draft)");
  cmd->callback([&action, args] { action = [args] { return run_measure(*args); }; });
}

}  // namespace clothbench::cli
