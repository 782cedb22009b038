// libFuzzer target: `--set section.key=value` overrides applied to committed scenes through
// parse_scene. The first byte picks the scene, the rest are the overrides, separated by NUL bytes
// (a command line cannot pass NUL inside one argument). InputError is the expected answer to a bad
// override; any other exception, crash or sanitizer report is a finding.
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "clothbench/bench/scene.hpp"
#include "clothbench/config.h"
#include "clothbench/io/errors.hpp"

namespace {

// a static mesh body, an animated body (walking), a moving analytic sphere
const std::array<std::string, 3> kScenes = {
    std::string(CLOTHBENCH_SOURCE_DIR) + "/scenes/dressing/skirt.toml",
    std::string(CLOTHBENCH_SOURCE_DIR) + "/scenes/walking/dress_sleeves.toml",
    std::string(CLOTHBENCH_SOURCE_DIR) + "/scenes/walking/tablecloth_sphere.toml"};

std::array<std::string, 3> g_texts;  // the scenes' text, read once

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  // the committed scenes; without them the run cannot start
  for (std::size_t i = 0; i < kScenes.size(); ++i) {
    std::ifstream in(kScenes[i], std::ios::binary);
    if (!in) {
      std::fprintf(stderr, "overrides_fuzz: cannot read %s\n", kScenes[i].c_str());
      std::exit(2);
    }
    std::ostringstream buf;
    buf << in.rdbuf();
    g_texts[i] = buf.str();
  }
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // the scene, then the overrides between NUL bytes
  if (size == 0) return 0;
  const std::size_t scene = data[0] % kScenes.size();
  std::vector<std::string> overrides(1);
  for (std::size_t i = 1; i < size; ++i) {
    if (data[i] == 0)
      overrides.emplace_back();
    else
      overrides.back() += static_cast<char>(data[i]);
  }
  try {
    const clothbench::Scene s = clothbench::parse_scene(g_texts[scene], kScenes[scene], overrides);
    // an overridden scene still resolves its references (InputError when a file is absent)
    clothbench::resolve_scene_path(s, s.body.file);
    for (const clothbench::GarmentSpec& g : s.garments) clothbench::resolve_scene_path(s, g.file);
  } catch (const clothbench::InputError&) {
  }
  return 0;
}
