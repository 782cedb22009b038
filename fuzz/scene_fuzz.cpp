// libFuzzer target: scene files (TOML) through parse_scene. InputError is the expected answer
// to bad input; any other exception, crash or sanitizer report is a finding.
#include <cstddef>
#include <cstdint>
#include <string>

#include "clothbench/bench/scene.hpp"
#include "clothbench/io/errors.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // the input as scene text; a name with a folder exercises scene-relative paths
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const clothbench::Scene scene = clothbench::parse_scene(text, "fuzz/scene.toml");
    // a parsed scene resolves its references (InputError when a file is absent)
    clothbench::resolve_scene_path(scene, scene.body.file);
    for (const clothbench::GarmentSpec& g : scene.garments) clothbench::resolve_scene_path(scene, g.file);
  } catch (const clothbench::InputError&) {
  }
  return 0;
}
