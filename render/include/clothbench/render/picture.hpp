#pragma once
/// Pictures of a dressed body: an orthographic z-buffered render (body grey, cloth coloured per
/// panel, a directional light plus ambient) from the front, side or back. Two renderers draw the
/// same camera behind one interface (PictureRenderer): OpenGL through OSMesa (OffscreenRenderer;
/// smooth per-vertex normals, two-sided cloth, 4x multisampling, cloth grid lines where cells are at
/// least 5 pixels wide), the default whenever the build has CLOTHBENCH_WITH_GL, and a small CPU
/// rasteriser (flat shading, one sample per pixel), the fallback of builds without it.
#include <memory>
#include <string>
#include <vector>

#include "clothbench/render/image.hpp"
#include "clothbench/sim/body_frame.hpp"
#include "clothbench/sim/cloth.hpp"

namespace clothbench {

enum class View { kFront, kSide, kBack };

/// Which renderer draws a picture.
enum class PictureBackend { kGl, kCpu };

/// The backend make_picture_renderer uses by default: kGl in builds with CLOTHBENCH_WITH_GL, else kCpu.
PictureBackend default_picture_backend();

/// Whether this build has `backend` (kCpu always; kGl with CLOTHBENCH_WITH_GL).
bool has_picture_backend(PictureBackend backend);

/// Draws pictures of dressed bodies. Whoever draws keeps one renderer and draws every picture with it
/// (the OpenGL one owns an OSMesa context, its shaders and framebuffer: create and use it on one thread).
class PictureRenderer {
 public:
  virtual ~PictureRenderer() = default;
  virtual PictureBackend backend() const = 0;
  /// A one-line name for reports: "OpenGL (OSMesa, <GL renderer>, N samples)" or "CPU rasteriser".
  virtual std::string name() const = 0;
  /// Renders `body` and the cloth (its quads at `cloth.positions`) into a `height`-pixel-tall image
  /// framed on the bounding box of both (5 % margin), seen from `view`.
  virtual Image render(const BodyFrame& body, const ClothMesh& cloth, int height, View view = View::kFront) = 0;
};

/// A renderer of `backend`. Throws std::runtime_error when this build lacks it or (OpenGL) no OSMesa
/// context can be created.
std::unique_ptr<PictureRenderer> make_picture_renderer(PictureBackend backend = default_picture_backend());

/// The colour of a cloth panel in every picture and 3-D file (a palette of six, repeated).
Rgb panel_colour(int panel);
/// The panel of a cloth vertex (0 for a cloth without panels).
int vertex_panel(const ClothMesh& cloth, Eigen::Index v);

/// Several images side by side (same height), with a 4-pixel white gap.
Image side_by_side(const std::vector<Image>& images);

}  // namespace clothbench
