// clothbench colliders [--json]: every collider, built or not, as an aligned table or as JSON
#include <algorithm>
#include <cstdio>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "clothbench/bench/registry.hpp"
#include "commands.hpp"

namespace clothbench::cli {

namespace {

// "yes", or how to build it
std::string built_text(const ColliderInfo& c) { return c.built ? "yes" : "no (-D" + c.option + "=ON)"; }

void print_table(const std::vector<ColliderInfo>& colliders) {
  std::size_t name_w = 4, built_w = 5;
  for (const auto& c : colliders) {
    name_w = std::max(name_w, c.name.size());
    built_w = std::max(built_w, built_text(c).size());
  }
  const int nw = static_cast<int>(name_w), bw = static_cast<int>(built_w);
  std::printf("%-*s  %-*s  %s\n", nw, "name", bw, "built", "description");
  for (const auto& c : colliders)
    std::printf("%-*s  %-*s  %s\n", nw, c.name.c_str(), bw, built_text(c).c_str(), c.description.c_str());
}

nlohmann::ordered_json as_json(const std::vector<ColliderInfo>& colliders) {
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (const auto& c : colliders)
    list.push_back({{"name", c.name}, {"built", c.built}, {"option", c.option}, {"description", c.description}});
  return list;
}

}  // namespace

void add_colliders_command(CLI::App& app, Action& action) {
  auto json = std::make_shared<bool>(false);
  auto* cmd = app.add_subcommand("colliders", "List the collision detection methods built in");
  cmd->add_flag("--json", *json, "print the list as JSON (name, built, option, description)");
  cmd->callback([&action, json] {
    action = [json] {
      if (*json) {
        std::cout << as_json(all_colliders()).dump(2) << "\n";
      } else {
        print_table(all_colliders());
      }
      return 0;
    };
  });
}

}  // namespace clothbench::cli
