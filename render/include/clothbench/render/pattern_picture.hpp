#pragma once
/// A picture of a meshed garment pattern (`clothbench garment FILE --png`, results/garments): the
/// panels side by side in pattern space (v up, a gap of a tenth of the tallest panel between them),
/// at most 960 x 480 pixels with a 12-pixel margin: structural springs grey, outlines black, seam
/// pairs dotted in one colour per seam (the first, middle and last pair of a seam joined by a line:
/// they cross where a seam is reversed), attached vertices red.
#include "clothbench/render/image.hpp"
#include "clothbench/sim/garment.hpp"

namespace clothbench {

/// Draws `meshed` (mesh_pattern of `pattern`). Throws std::invalid_argument when the pattern has no panels.
Image draw_pattern(const Pattern& pattern, const MeshedPattern& meshed);

}  // namespace clothbench
