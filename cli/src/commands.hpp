#pragma once
/// The CLI of DESIGN.md: one file per subcommand (cmd_<name>.cpp), each adding itself to the app.
/// A command's action runs after parsing and returns the exit code (0 ok, 1 regression, 2 bad input,
/// 3 diverged, 4 accuracy limits missed under `run --strict`, 5 sweep points failed or missing, 6 an internal error:
/// the machine's or the program's, not the input's).
#include <functional>

#include <CLI/CLI.hpp>

namespace clothbench::cli {

using Action = std::function<int()>;

void add_colliders_command(CLI::App& app, Action& action);
void add_demo_command(CLI::App& app, Action& action);
void add_maps_command(CLI::App& app, Action& action);
void add_garment_command(CLI::App& app, Action& action);
void add_body_command(CLI::App& app, Action& action);
void add_measure_command(CLI::App& app, Action& action);
void add_run_command(CLI::App& app, Action& action);
void add_reproduce_command(CLI::App& app, Action& action);
void add_compare_command(CLI::App& app, Action& action);
void add_sweep_command(CLI::App& app, Action& action);  // and merge
void add_report_command(CLI::App& app, Action& action);

}  // namespace clothbench::cli
