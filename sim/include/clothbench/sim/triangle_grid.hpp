#pragma once
/// Triangles in a uniform grid of cells, by spatial hashing (Teschner et al. 2003): each triangle under the key of
/// every cell its box spans, the keys sorted; a box's query visits the triangles of the cells it spans. What
/// cloth-against-cloth detection looks candidates up in (the oracle's measure, the simulator's self contacts).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "clothbench/sim/collider.hpp"

namespace clothbench {

class TriangleGrid {
 public:
  using Triangle = std::array<int, 3>;

  /// Rebuilds the grid for `triangles` (corner indices into `points`) with cells `cell` wide [m]. A triangle whose
  /// box spans more than kMostCells cells (a cloth torn apart, a non-finite corner) is kept beside the grid.
  void build(PointsView points, const std::vector<Triangle>& triangles, double cell);
  /// f(t) for each triangle t in a cell that the box [lo, hi] spans (a triangle may come once per shared cell), and
  /// for those kept beside the grid; a box over more than kMostCells cells visits every triangle.
  template <class F>
  void near(const Vec3& lo, const Vec3& hi, F&& f) const {
    for (int t : beside_) f(t);
    const Cell a = cell_of(lo), b = cell_of(hi);
    if (cells(a, b) > kMostCells) {
      for (int t = 0; t < count_; ++t) f(t);
      return;
    }
    for (long x = a[0]; x <= b[0]; ++x)
      for (long y = a[1]; y <= b[1]; ++y)
        for (long z = a[2]; z <= b[2]; ++z) {
          const std::uint64_t k = key(x, y, z);
          auto it = std::lower_bound(entries_.begin(), entries_.end(), std::make_pair(k, -1));
          for (; it != entries_.end() && it->first == k; ++it) f(it->second);
        }
  }

 private:
  using Cell = std::array<long, 3>;
  static constexpr long kOffset = 1L << 20;
  static constexpr double kMostCells = 4096;
  // the cell of p, within a million cells of the origin's on each axis (NaN: the lowest)
  Cell cell_of(const Vec3& p) const {
    Cell c;
    for (int a = 0; a < 3; ++a) {
      const double u = std::floor(double(p[a]) / cell_);
      c[std::size_t(a)] = !(u > -kOffset) ? -kOffset : !(u < kOffset - 1) ? kOffset - 1 : long(u);
    }
    return c;
  }
  static double cells(const Cell& a, const Cell& b) {
    return double(b[0] - a[0] + 1) * double(b[1] - a[1] + 1) * double(b[2] - a[2] + 1);
  }
  // 21 bits an axis
  static std::uint64_t key(long x, long y, long z) {
    const auto axis = [](long c) { return static_cast<std::uint64_t>(c + kOffset); };
    return axis(x) << 42 | axis(y) << 21 | axis(z);
  }

  double cell_ = 1;
  int count_ = 0;
  std::vector<std::pair<std::uint64_t, int>> entries_;
  std::vector<int> beside_;  // triangles over more than kMostCells cells
};

}  // namespace clothbench
