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

const char* family_text(Family f) {
  switch (f) {
    case Family::kImageSpace: return "image space";
    case Family::kObjectSpace: return "object space";
    case Family::kReference: return "reference";
  }
  return "?";
}

const char* needs_text(Needs n) {
  switch (n) {
    case Needs::kNothing: return "nothing";
    case Needs::kOpenGl: return "OpenGL";
    case Needs::kGpu: return "EGL (a GPU, or Mesa's software renderer)";
  }
  return "?";
}

void print_table(const std::vector<ColliderInfo>& colliders) {
  std::size_t name_w = 4, built_w = 5, family_w = 6;
  for (const auto& c : colliders) {
    name_w = std::max(name_w, c.name.size());
    built_w = std::max(built_w, built_text(c).size());
    family_w = std::max(family_w, std::string(family_text(c.family)).size());
  }
  const int nw = static_cast<int>(name_w), bw = static_cast<int>(built_w), fw = static_cast<int>(family_w);
  std::printf("%-*s  %-*s  %-*s  %s\n", nw, "name", bw, "built", fw, "family", "description");
  for (const auto& c : colliders)
    std::printf("%-*s  %-*s  %-*s  %s\n", nw, c.name.c_str(), bw, built_text(c).c_str(), fw, family_text(c.family),
                c.description.c_str());
}

nlohmann::ordered_json as_json(const std::vector<ColliderInfo>& colliders) {
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (const auto& c : colliders)
    list.push_back({{"name", c.name},
                    {"built", c.built},
                    {"option", c.option},
                    {"description", c.description},
                    {"family", family_text(c.family)},
                    {"exact", c.exact},
                    {"in_tables", c.in_tables},
                    {"needs", needs_text(c.needs)},
                    {"coherent", c.coherent},
                    {"face_normals", c.face_normals},
                    {"slow_update", c.slow_update}});
  return list;
}

}  // namespace

void add_colliders_command(CLI::App& app, Action& action) {
  auto json = std::make_shared<bool>(false);
  auto* cmd = app.add_subcommand("colliders", "List the collision detection methods built in");
  cmd->add_flag("--json", *json,
                "print the list as JSON (name, built, option, description and the registry's traits: family, exact, "
                "in_tables, needs, coherent, face_normals, slow_update)");
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
