// Cloth-cloth crossings by spatial hashing (Teschner et al. 2003): triangles into the cells their boxes span,
// each spring tested against the triangles of the cells its box spans.
#include "clothbench/bench/cloth_crossings.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <utility>
#include <vector>

#include "clothbench/bench/oracle.hpp"
#include "clothbench/sim/timer.hpp"

namespace clothbench {

namespace {

using Cell = std::array<long, 3>;
using Triangle = std::array<int, 4>;  // three corners and the quad

// a cell's key: 21 bits an axis (cells up to a million away from the origin's)
std::uint64_t key(long x, long y, long z) {
  constexpr long kOffset = 1L << 20;
  const auto axis = [](long c) { return static_cast<std::uint64_t>(std::clamp(c + kOffset, 0L, 2 * kOffset - 1)); };
  return axis(x) << 42 | axis(y) << 21 | axis(z);
}

// the grid: the cloth's triangles by the keys of the cells their boxes span, sorted
class Grid {
 public:
  Grid(PointsView v, const std::vector<Triangle>& triangles, double cell) : v_(v), cell_(cell) {
    for (std::size_t t = 0; t < triangles.size(); ++t) {
      const auto [lo, hi] = span({triangles[t][0], triangles[t][1], triangles[t][2]});
      for (long x = lo[0]; x <= hi[0]; ++x)
        for (long y = lo[1]; y <= hi[1]; ++y)
          for (long z = lo[2]; z <= hi[2]; ++z) entries_.emplace_back(key(x, y, z), static_cast<int>(t));
    }
    std::sort(entries_.begin(), entries_.end());
  }
  // the cells the box of the points spans
  std::pair<Cell, Cell> span(std::initializer_list<int> points) const {
    Cell lo{}, hi{};
    for (int a = 0; a < 3; ++a) {
      double mn = INFINITY, mx = -INFINITY;
      for (int i : points)
        mn = std::min(mn, double(v_[std::size_t(i)][a])), mx = std::max(mx, double(v_[std::size_t(i)][a]));
      lo[a] = static_cast<long>(std::floor(mn / cell_)), hi[a] = static_cast<long>(std::floor(mx / cell_));
    }
    return {lo, hi};
  }
  // f(triangle) for every triangle in cell (x, y, z)
  template <class F>
  void in_cell(long x, long y, long z, F&& f) const {
    const std::uint64_t k = key(x, y, z);
    auto it = std::lower_bound(entries_.begin(), entries_.end(), std::make_pair(k, -1));
    for (; it != entries_.end() && it->first == k; ++it) f(it->second);
  }

 private:
  PointsView v_;
  double cell_;
  std::vector<std::pair<std::uint64_t, int>> entries_;
};

bool finite(PointsView v, std::initializer_list<int> points) {
  for (int i : points)
    if (i < 0 || std::size_t(i) >= v.count) throw std::invalid_argument("cloth_crossings: index outside the vertices");
  return std::all_of(points.begin(), points.end(), [&](int i) { return v[std::size_t(i)].allFinite(); });
}

}  // namespace

ClothCrossings cloth_crossings(PointsView v, const Pairs& segments, const Quads& quads,
                               const std::vector<std::vector<int>>& sewn) {
  const Stopwatch clock;
  ClothCrossings out;
  std::vector<int> point(v.count);  // each vertex's point: its own index, or its sewn group's first vertex
  for (std::size_t i = 0; i < v.count; ++i) point[i] = int(i);
  for (const auto& group : sewn)
    for (int i : group)
      if (i >= 0 && std::size_t(i) < v.count) point[std::size_t(i)] = group.front();
  std::vector<Triangle> triangles;
  for (Eigen::Index q = 0; q < quads.cols(); ++q)
    if (finite(v, {quads(0, q), quads(1, q), quads(2, q), quads(3, q)}))
      triangles.push_back({quads(0, q), quads(1, q), quads(2, q)}),
          triangles.push_back({quads(0, q), quads(2, q), quads(3, q)});
  // cells a spring long (its mean length), at least a 512th of the cloth's extent along an axis
  double length = 0, extent = 0;
  std::vector<Eigen::Index> tested;
  for (Eigen::Index k = 0; k < segments.cols(); ++k)
    if (finite(v, {segments(0, k), segments(1, k)})) {
      tested.push_back(k);
      length += double((v[std::size_t(segments(1, k))] - v[std::size_t(segments(0, k))]).norm());
    }
  for (int a = 0; a < 3; ++a) {
    double mn = INFINITY, mx = -INFINITY;
    for (std::size_t i = 0; i < v.count; ++i)
      if (v[i].allFinite()) mn = std::min(mn, double(v[i][a])), mx = std::max(mx, double(v[i][a]));
    extent = std::max(extent, mx - mn);
  }
  out.segments = tested.size();
  if (tested.empty() || triangles.empty()) return out.ms = clock.ms(), out;
  const Grid grid(v, triangles, std::max({length / double(tested.size()), extent / 512, 1e-6}));
  std::vector<Eigen::Index> seen(triangles.size(), -1);  // the last segment that tested each triangle
  for (Eigen::Index k : tested) {
    const int a = segments(0, k), b = segments(1, k);
    // the segment without its ends: a triangle touching it only at a sewn point does not count
    const Vec3 pa = v[std::size_t(a)], pb = v[std::size_t(b)];
    const Vec3 from = pa + Real(1e-4) * (pb - pa), to = pb + Real(1e-4) * (pa - pb);
    bool crosses = false;
    const auto test = [&](int t) {
      const Triangle& tri = triangles[std::size_t(t)];
      const auto at_an_end = [&](int corner) {
        return point[std::size_t(corner)] == point[std::size_t(a)] ||
               point[std::size_t(corner)] == point[std::size_t(b)];
      };
      if (crosses || seen[std::size_t(t)] == k || std::any_of(tri.begin(), tri.begin() + 3, at_an_end)) return;
      seen[std::size_t(t)] = k;
      crosses =
          segment_crosses_triangle(from, to, v[std::size_t(tri[0])], v[std::size_t(tri[1])], v[std::size_t(tri[2])]);
      if (crosses) out.where.emplace_back(k, tri[3]);
    };
    const auto [lo, hi] = grid.span({a, b});
    for (long x = lo[0]; x <= hi[0] && !crosses; ++x)
      for (long y = lo[1]; y <= hi[1] && !crosses; ++y)
        for (long z = lo[2]; z <= hi[2] && !crosses; ++z) grid.in_cell(x, y, z, test);
    out.crossings += crosses ? 1 : 0;
  }
  out.pct = 100.0 * double(out.crossings) / double(out.segments);
  out.ms = clock.ms();
  return out;
}

}  // namespace clothbench
