#pragma once
/// Pictures of a dressed body: an orthographic z-buffered render (body grey, cloth coloured per
/// panel, a directional light plus ambient) from the front, side or back. Two renderers draw the
/// same camera: OpenGL through OSMesa (clothbench::render; smooth per-vertex normals, two-sided
/// cloth, 4x multisampling, cloth grid lines where cells are at least 5 pixels wide), used
/// whenever the build has CLOTHBENCH_WITH_GL, and a small CPU rasteriser (flat shading, one
/// sample per pixel), the fallback of builds without it. `picture_renderer_name` says which.
#include <string>
#include <vector>

#include "clothbench/bench/image.hpp"
#include "clothbench/sim/body_frame.hpp"
#include "clothbench/sim/cloth.hpp"

namespace clothbench {

enum class View { kFront, kSide, kBack };

/// Which renderer draws a picture.
enum class PictureRenderer { kGl, kCpu };

/// The renderer `render_dressed` uses by default: kGl in builds with CLOTHBENCH_WITH_GL, else kCpu.
PictureRenderer default_picture_renderer();

/// Whether this build has `renderer` (kCpu always; kGl with CLOTHBENCH_WITH_GL).
bool has_picture_renderer(PictureRenderer renderer);

/// A one-line name of `renderer` for reports: "OpenGL (OSMesa, <GL renderer>, N samples)" or
/// "CPU rasteriser". Naming kGl creates its context; throws as `render_dressed` does.
std::string picture_renderer_name(PictureRenderer renderer);

/// Renders `body` and the cloth (its quads at `cloth.positions`) into a `height`-pixel-tall image
/// framed on the bounding box of both, with the default renderer.
Image render_dressed(const BodyFrame& body, const ClothMesh& cloth, int height, View view = View::kFront);

/// As above with a chosen renderer. The OpenGL one keeps one OSMesa context for the process
/// (created on first use, from one thread at a time); throws std::runtime_error when this build
/// lacks it or no OSMesa context can be created.
Image render_dressed(const BodyFrame& body, const ClothMesh& cloth, int height, View view, PictureRenderer renderer);

/// The colour of a cloth panel in every picture and 3-D file (a palette of six, repeated).
Rgb panel_colour(int panel);
/// The panel of a cloth vertex (0 for a cloth without panels).
int vertex_panel(const ClothMesh& cloth, Eigen::Index v);

/// Several images side by side (same height), with a 4-pixel white gap.
Image side_by_side(const std::vector<Image>& images);

}  // namespace clothbench
