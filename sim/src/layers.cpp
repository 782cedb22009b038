// Layers of garments: an outer garment's start moved out of the dressed cloth under it.
#include "clothbench/sim/layers.hpp"

#include <algorithm>
#include <cmath>

namespace clothbench {

namespace {

// each point's normal: the sum of its cells' (the cross product of a cell's diagonals), normalised, turned so
// that most point away from the middle (x, z) of the cloth
Points3 vertex_normals(const Points3& x, const Quads& cells) {
  Points3 n = Points3::Zero(3, x.cols());
  for (Eigen::Index c = 0; c < cells.cols(); ++c) {
    const Vec3 d1 = x.col(cells(2, c)) - x.col(cells(0, c)), d2 = x.col(cells(3, c)) - x.col(cells(1, c));
    const Vec3 face =
        cells(3, c) == cells(2, c) ? Vec3((x.col(cells(1, c)) - x.col(cells(0, c))).cross(d1)) : Vec3(d1.cross(d2));
    for (int k = 0; k < 4; ++k) n.col(cells(k, c)) += face;
  }
  const Vec3 middle = x.rowwise().mean();
  long out = 0;
  for (Eigen::Index i = 0; i < x.cols(); ++i) {
    if (n.col(i).squaredNorm() > 0) n.col(i).normalize();
    const Vec3 from(x(0, i) - middle.x(), 0, x(2, i) - middle.z());
    out += n.col(i).dot(from) > 0 ? 1 : -1;
  }
  if (out < 0) n = -n;
  return n;
}

}  // namespace

long clear_of_layer(const Points3& inner, const Quads& inner_cells, Points3& outer, Real clearance, Real reach) {
  const Points3 normal = vertex_normals(inner, inner_cells);
  long moved = 0;
  for (Eigen::Index i = 0; i < outer.cols(); ++i) {
    const Vec3 p = outer.col(i);
    Eigen::Index nearest = -1;
    Real best = reach * reach;
    for (Eigen::Index k = 0; k < inner.cols(); ++k) {
      const Real d = (inner.col(k) - p).squaredNorm();
      if (d < best && normal.col(k).squaredNorm() > 0) best = d, nearest = k;
    }
    if (nearest < 0) continue;
    const Real outside = (p - inner.col(nearest)).dot(normal.col(nearest));
    if (outside >= clearance) continue;
    outer.col(i) += (clearance - outside) * normal.col(nearest);
    ++moved;
  }
  return moved;
}

}  // namespace clothbench
