#pragma once
/// Pictures of a dressed body: an orthographic z-buffered render (body grey, cloth coloured per
/// panel, Lambert shading) from the front, side or back, on the CPU.
#include <string>

#include "clothbench/sim/body_frame.hpp"
#include "clothbench/sim/cloth.hpp"
#include "image.hpp"

namespace clothbench {

enum class View { kFront, kSide, kBack };

/// Renders `body` and the cloth (its quads at `cloth.positions`) into a `height`-pixel-tall image
/// framed on the body's bounding box.
Image render_dressed(const BodyFrame& body, const ClothMesh& cloth, int height, View view = View::kFront);

/// Writes the body and the cloth (quads split into triangles, one mesh per panel) as a binary
/// glTF file (assimp's exporter), for Blender or a web viewer.
void export_dressed(const std::string& path, const BodyFrame& body, const ClothMesh& cloth);

/// Several images side by side (same height), with a 4-pixel white gap.
Image side_by_side(const std::vector<Image>& images);

}  // namespace clothbench
