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

  /// Rebuilds the grid for `triangles` (corner indices into `points`, all finite) with cells `cell` wide [m].
  void build(PointsView points, const std::vector<Triangle>& triangles, double cell);
  /// f(t) for each triangle t in a cell that the box [lo, hi] spans (a triangle may come once per shared cell).
  template <class F>
  void near(const Vec3& lo, const Vec3& hi, F&& f) const {
    const Cell a = cell_of(lo), b = cell_of(hi);
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
  Cell cell_of(const Vec3& p) const {
    return {long(std::floor(double(p.x()) / cell_)), long(std::floor(double(p.y()) / cell_)),
            long(std::floor(double(p.z()) / cell_))};
  }
  // 21 bits an axis: cells up to a million from the origin's
  static std::uint64_t key(long x, long y, long z) {
    constexpr long kOffset = 1L << 20;
    const auto axis = [](long c) { return static_cast<std::uint64_t>(std::clamp(c + kOffset, 0L, 2 * kOffset - 1)); };
    return axis(x) << 42 | axis(y) << 21 | axis(z);
  }

  double cell_ = 1;
  std::vector<std::pair<std::uint64_t, int>> entries_;
};

}  // namespace clothbench
