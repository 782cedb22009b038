#include "clothbench/sim/triangle_grid.hpp"

namespace clothbench {

void TriangleGrid::build(PointsView points, const std::vector<Triangle>& triangles, double cell) {
  cell_ = cell;
  count_ = static_cast<int>(triangles.size());
  entries_.clear();
  beside_.clear();
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    Vec3 lo = points[std::size_t(triangles[t][0])], hi = lo;
    bool finite = true;
    for (int k = 0; k < 3; ++k) {
      const Vec3 p = points[std::size_t(triangles[t][std::size_t(k)])];
      finite = finite && p.allFinite(), lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
    }
    const Cell a = cell_of(lo), b = cell_of(hi);
    if (!finite || cells(a, b) > kMostCells) {
      beside_.push_back(static_cast<int>(t));
      continue;
    }
    for (long x = a[0]; x <= b[0]; ++x)
      for (long y = a[1]; y <= b[1]; ++y)
        for (long z = a[2]; z <= b[2]; ++z) entries_.emplace_back(key(x, y, z), static_cast<int>(t));
  }
  std::sort(entries_.begin(), entries_.end());
}

}  // namespace clothbench
