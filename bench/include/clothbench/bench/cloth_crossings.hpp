#pragma once
/// Cloth against cloth, measured: the structural springs of a cloth that pass through one of its own triangles
/// (each quad split in two) that does not have either end of the spring as a corner, where a fold or a sleeve went
/// through the cloth. Found by spatial hashing of the triangles into a uniform grid of cells about a spring long
/// (Teschner et al. 2003), each candidate tested exactly (segment_crosses_triangle). Springs and triangles meeting
/// only at a sewn point are not counted: the vertices of a merged seam are one point (`sewn`), and the segment is
/// tested without its ends.
#include <cstddef>
#include <utility>
#include <vector>

#include "clothbench/sim/cloth.hpp"
#include "clothbench/sim/collider.hpp"

namespace clothbench {

struct ClothCrossings {
  std::size_t segments = 0;   ///< finite structural springs tested
  std::size_t crossings = 0;  ///< those that pass through a triangle of the cloth not incident to them
  double pct = 0;             ///< crossings / segments [%]; 0 when none were tested
  double ms = 0;              ///< what measuring them cost [ms]
  /// each crossing: the segment's index and the quad of the triangle it passes through
  std::vector<std::pair<Eigen::Index, Eigen::Index>> where;
};

/// The crossings of `segments` (2 x n indices into `vertices` [m]) through the triangles of `quads` (4 x nq) that
/// have no corner at one of the segment's points (`sewn`: groups of vertices that are one point);
/// segments or quads with a non-finite corner are skipped. Throws std::invalid_argument for an index outside the
/// vertices.
ClothCrossings cloth_crossings(PointsView vertices, const Pairs& segments, const Quads& quads,
                               const std::vector<std::vector<int>>& sewn = {});

}  // namespace clothbench
