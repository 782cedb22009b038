#pragma once
/// The dressed body as binary glTF 2.0 for the report's 3-D viewer (results/index.html) and Blender:
/// our own small writer (assimp's exporter has no morph-target animation). Meshes: "body" and one per
/// cloth panel (named after it, the panel colours of the pictures). Every cloth vertex carries two
/// scalar attributes of the end state: `_STRAIN` (the largest strain of its structural springs, a
/// fraction, < 0 compressed) and `_DISTANCE` (signed distance to the body [m], < 0 inside, measured by
/// the caller's ViewerStyle::signed_distance: io knows no oracle). With frames, the file is animated: every mesh has one morph target per kept frame
/// (position offsets from the first frame, int16 under KHR_mesh_quantization where they fit within
/// 1 m, else float) and the animation "walk" steps the weights through them (linear between frames).
#include <array>
#include <functional>
#include <string>
#include <vector>

#include "clothbench/sim/body_frame.hpp"
#include "clothbench/sim/cloth.hpp"

namespace clothbench {

/// One animation frame of a dressed body: animation time, body and cloth vertex positions [m]
/// (the topology of the BodyFrame and ClothMesh handed to export_viewer_gltf).
struct ViewerFrame {
  double t_s = 0;
  Points3 body, cloth;
};

/// What the file shows beside the geometry, supplied by the caller (bench's export_viewer_gltf: the
/// pictures' panel colours, the accuracy oracle's distances).
struct ViewerStyle {
  /// The colour of cloth panel `panel`, RGB in [0, 1].
  std::function<std::array<float, 3>(int panel)> panel_colour;
  /// Signed distance [m] (< 0 inside) of every point of `points` (3 x n) to `body` into `out` (n values; non-finite
  /// ones are written as 0).
  std::function<void(const BodyFrame& body, const Points3& points, std::vector<Real>& out)> signed_distance;
};

/// Writes PATH (PATH.tmp, then renamed). Without frames: the end state (body.positions,
/// cloth.positions) with _STRAIN and _DISTANCE. With frames: the first kept frame as the base pose,
/// the fields measured on it, and the animation; at most `max_frames` frames are kept, evenly spread
/// over the clip, first and last included (the body is 13,380 vertices: about 107 kB per frame).
/// Throws std::invalid_argument on sizes that do not match the topology, InputError when the file
/// cannot be written.
void write_viewer_gltf(const std::string& path, const BodyFrame& body, const ClothMesh& cloth, const ViewerStyle& style,
                       const std::vector<ViewerFrame>& frames = {}, int max_frames = 16);

/// The frames write_viewer_gltf keeps of `count`: at most `max_frames` indices, evenly spread,
/// first and last included, ascending.
std::vector<std::size_t> kept_frames(std::size_t count, int max_frames);

}  // namespace clothbench
