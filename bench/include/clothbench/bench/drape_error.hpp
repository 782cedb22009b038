#pragma once
/// Drape error: how far one drape lies from a reference drape of the same garment, whatever the two
/// resolutions. Each cloth is a surface (its quads as two triangles each); every vertex of one is measured to the
/// other's surface and back (a symmetric point-to-surface distance), so a coarse and a fine meshing of the same
/// drape are close, and the error discriminates where "vertices inside the body" is 0 for nearly every run.
#include "clothbench/sim/cloth.hpp"

namespace clothbench {

/// Distances between two drapes [m].
struct DrapeError {
  double rms = 0;   ///< root mean square over both directions' vertex distances
  double max = 0;   ///< largest vertex distance either way (a symmetric Hausdorff distance on the vertices)
  std::size_t points = 0;  ///< vertices measured (both clothes, finite ones)
};

/// The symmetric vertex-to-surface distance between the drapes `a` and `b` (positions and quads of each; a quad
/// whose corner 2 repeats as 3 is a triangle). Throws std::invalid_argument when either has no quad.
DrapeError drape_error(const ClothMesh& a, const ClothMesh& b);

}  // namespace clothbench
