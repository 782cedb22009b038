// clothbench colliders: one line per collider, built or not
#include <iostream>

#include "commands.hpp"
#include "registry.hpp"

namespace clothbench::cli {

void add_colliders_command(CLI::App& app, Action& action) {
  auto* cmd = app.add_subcommand("colliders", "List the collision detection methods built in");
  cmd->callback([&action] {
    action = [] {
      for (const auto& c : all_colliders())
        std::cout << c.name << (c.built ? "  " : "  (not built: -D" + c.option + "=ON)  ") << c.description << "\n";
      return 0;
    };
  });
}

}  // namespace clothbench::cli
