#pragma once
/// Pictures of a body's image-space maps (`clothbench maps BODY --png DIR`, results/maps): front
/// (left) and back (right) side by side, each as its camera sees it, +y up. Depth as the z-buffer
/// value through the colour map (dark near, light far; walking Fig. 4), side layer red; normals and
/// velocities as their 8-bit colours (dressing Eq. 6, walking Eq. 9; velocity over `max_speed`);
/// empty pixels white.
#include <string>
#include <vector>

namespace clothbench {

struct MapSet;

/// Writes BASE_depth.png, BASE_normal.png and, for a moving body (`has_velocity`), BASE_velocity.png;
/// returns the paths written, in that order. Throws std::runtime_error naming a file that cannot be written.
std::vector<std::string> write_map_pictures(const MapSet& maps, const std::string& base);

}  // namespace clothbench
