// clothbench: the command line of DESIGN.md
#include <exception>
#include <iostream>
#include <stdexcept>

#include "clothbench/bench/report.hpp"
#include "clothbench/config.h"
#include "clothbench/io/errors.hpp"
#include "commands.hpp"

int main(int argc, char** argv) {
  CLI::App app{"clothbench: garment simulation and cloth-body collision benchmark"};
  app.require_subcommand(1);
  // the source tree's git SHA as the reports record it (git runs only when --version is given)
  app.set_version_flag("--version",
                       [] { return "clothbench " CLOTHBENCH_VERSION " (git " + clothbench::git_sha() + ")"; });
  clothbench::cli::Action action;
  clothbench::cli::add_colliders_command(app, action);
  clothbench::cli::add_demo_command(app, action);
  clothbench::cli::add_maps_command(app, action);
  clothbench::cli::add_garment_command(app, action);
  clothbench::cli::add_body_command(app, action);
  clothbench::cli::add_measure_command(app, action);
  clothbench::cli::add_run_command(app, action);
  clothbench::cli::add_reproduce_command(app, action);
  clothbench::cli::add_compare_command(app, action);
  clothbench::cli::add_sweep_command(app, action);
  clothbench::cli::add_report_command(app, action);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // CLI11 prints help with exit 0 and usage errors with its own code; map errors to 2
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;
  }
  // bad input (a file, a scene value, an option) exits 2; anything else is this program's failure or the
  // machine's (no OpenGL context, a failed library call, a bug), never blamed on the input
  try {
    return action ? action() : 0;
  } catch (const clothbench::InputError& e) {
    std::cerr << "clothbench: error: " << e.what() << "\n";
    return 2;
  } catch (const std::invalid_argument& e) {
    std::cerr << "clothbench: error: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "clothbench: internal error: " << e.what() << "\n";
    return 6;
  }
}
