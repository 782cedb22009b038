#pragma once
/// The dressed body as binary glTF for the report's 3-D viewer: io's write_viewer_gltf with the
/// pictures' panel colours (render) and the accuracy oracle's signed distances (`_DISTANCE`).
#include <string>
#include <vector>

#include "clothbench/io/viewer_gltf.hpp"

namespace clothbench {

/// write_viewer_gltf(path, body, cloth, style, frames, max_frames) with panel_colour and Oracle::signed_distance.
void export_viewer_gltf(const std::string& path, const BodyFrame& body, const ClothMesh& cloth,
                        const std::vector<ViewerFrame>& frames = {}, int max_frames = 16);

}  // namespace clothbench
