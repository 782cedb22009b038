#pragma once
/// Pictures of triangle meshes rendered offscreen with OpenGL through OSMesa (llvmpipe): an
/// orthographic camera, per-vertex normals and colours, one directional light plus ambient,
/// multisampled when the context offers it. Knows nothing of garments or file formats.
#include <array>
#include <cstdint>
#include <memory>
#include <string_view>
#include <vector>

#include "clothbench/render/image.hpp"
#include "clothbench/sim/types.hpp"

namespace clothbench {

/// One mesh to draw. Normals are unit per-vertex normals (3 x nv; outward for closed meshes),
/// colours are per-vertex RGB in [0, 1] (3 x nv). `lines` (2 x ne, optional) are edges drawn on
/// top in the vertex colour scaled by `line_shade`.
struct DrawMesh {
  Points3 positions;        ///< vertex positions [m] (3 x nv)
  Points3 normals;          ///< unit vertex normals (3 x nv)
  Points3 colours;          ///< vertex colours in [0, 1] (3 x nv)
  Tris triangles;           ///< vertex indices (3 x nt)
  Pairs lines;              ///< optional wire edges (2 x ne)
  bool two_sided = false;   ///< light the side facing the camera (cloth); else back faces stay dark
  float line_shade = 0.7f;  ///< line colour = vertex colour x line_shade
};

/// An orthographic camera: the image spans `half_width` x `half_height` [m] around `centre`,
/// with `right` to the right, `up` up and `toward` pointing from the scene to the viewer (all
/// unit, right-handed: right x up = toward).
struct OrthoCamera {
  Vec3 centre = Vec3::Zero();
  Vec3 right = Vec3::UnitX();
  Vec3 up = Vec3::UnitY();
  Vec3 toward = Vec3::UnitZ();
  Real half_width = 1;   ///< [m]
  Real half_height = 1;  ///< [m]
  int width = 256;       ///< [pixels]
  int height = 256;      ///< [pixels]
};

/// Lighting: colour x (ambient + diffuse x max(0, n . light)), light a unit world direction
/// toward the light; two-sided meshes flip n to face the camera first.
struct Lighting {
  Vec3 light = Vec3(0.3f, 0.5f, 1.0f).normalized();
  float ambient = 0.25f;
  float diffuse = 0.75f;
  std::array<float, 3> background{1.0f, 1.0f, 1.0f};  ///< RGB in [0, 1]
};

/// Owns one OSMesa context (GL 3.3 core), its shaders and a framebuffer resized on demand.
/// Non-copyable; use from the thread that created it.
class OffscreenRenderer {
 public:
  /// Creates the context and compiles the shaders; throws std::runtime_error naming the step
  /// that failed (no OSMesa context, shader compile, incomplete framebuffer).
  OffscreenRenderer();
  ~OffscreenRenderer();
  OffscreenRenderer(const OffscreenRenderer&) = delete;
  OffscreenRenderer& operator=(const OffscreenRenderer&) = delete;

  /// Draws the meshes (depth-tested, near/far fitted to them) and reads the picture back.
  /// Throws std::invalid_argument on a non-positive image size or inconsistent mesh arrays, and
  /// std::runtime_error when the framebuffer of that size cannot be made.
  Image render(const std::vector<DrawMesh>& meshes, const OrthoCamera& camera, const Lighting& lighting = {});

  /// Colour samples per pixel the framebuffer uses (1 when the context has no multisampling).
  int samples() const;
  /// The GL renderer string (for example "llvmpipe (LLVM 15.0.6, 256 bits)").
  std::string_view gl_renderer() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace clothbench
