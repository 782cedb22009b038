// Cloth-cloth crossings: the cloth's triangles in a grid (TriangleGrid, spatial hashing), each spring tested
// against the triangles of the cells its box spans.
#include "clothbench/bench/cloth_crossings.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "clothbench/bench/oracle.hpp"
#include "clothbench/sim/cloth.hpp"
#include "clothbench/sim/timer.hpp"
#include "clothbench/sim/triangle_grid.hpp"

namespace clothbench {

namespace {

bool finite(PointsView v, std::initializer_list<int> points) {
  for (int i : points)
    if (i < 0 || std::size_t(i) >= v.count) throw std::invalid_argument("cloth_crossings: index outside the vertices");
  return std::all_of(points.begin(), points.end(), [&](int i) { return v[std::size_t(i)].allFinite(); });
}

// cells a spring long (the tested springs' mean length), at least a 512th of the cloth's largest extent
double cell_size(PointsView v, const Pairs& segments, const std::vector<Eigen::Index>& tested) {
  double length = 0;
  for (Eigen::Index k : tested)
    length += double((v[std::size_t(segments(1, k))] - v[std::size_t(segments(0, k))]).norm());
  Vec3 lo = Vec3::Constant(INFINITY), hi = -lo;
  for (std::size_t i = 0; i < v.count; ++i)
    if (v[i].allFinite()) lo = lo.cwiseMin(v[i]), hi = hi.cwiseMax(v[i]);
  return std::max({length / double(tested.size()), double((hi - lo).maxCoeff()) / 512, 1e-6});
}

}  // namespace

ClothCrossings cloth_crossings(PointsView v, const Pairs& segments, const Quads& quads,
                               const std::vector<std::vector<int>>& sewn) {
  const Stopwatch clock;
  ClothCrossings out;
  const std::vector<int> point = sewn_point_of(v.count, sewn);
  std::vector<TriangleGrid::Triangle> triangles;
  std::vector<Eigen::Index> quad_of;  // beside triangles
  for (Eigen::Index q = 0; q < quads.cols(); ++q)
    if (finite(v, {quads(0, q), quads(1, q), quads(2, q), quads(3, q)})) {
      triangles.push_back({quads(0, q), quads(1, q), quads(2, q)});
      triangles.push_back({quads(0, q), quads(2, q), quads(3, q)});
      quad_of.insert(quad_of.end(), {q, q});
    }
  std::vector<Eigen::Index> tested;
  for (Eigen::Index k = 0; k < segments.cols(); ++k)
    if (finite(v, {segments(0, k), segments(1, k)})) tested.push_back(k);
  out.segments = tested.size();
  if (tested.empty() || triangles.empty()) return out.ms = clock.ms(), out;
  TriangleGrid grid;
  grid.build(v, triangles, cell_size(v, segments, tested));
  std::vector<Eigen::Index> seen(triangles.size(), -1);  // the last segment that tested each triangle
  for (Eigen::Index k : tested) {
    const int a = segments(0, k), b = segments(1, k);
    // the segment without its ends: a triangle touching it only at a sewn point does not count
    const Vec3 pa = v[std::size_t(a)], pb = v[std::size_t(b)];
    const Vec3 from = pa + Real(1e-4) * (pb - pa), to = pb + Real(1e-4) * (pa - pb);
    const auto at_an_end = [&](int corner) {
      return point[std::size_t(corner)] == point[std::size_t(a)] || point[std::size_t(corner)] == point[std::size_t(b)];
    };
    bool crosses = false;
    grid.near(pa.cwiseMin(pb), pa.cwiseMax(pb), [&](int t) {
      const auto& tri = triangles[std::size_t(t)];
      if (crosses || seen[std::size_t(t)] == k || std::any_of(tri.begin(), tri.end(), at_an_end)) return;
      seen[std::size_t(t)] = k;
      crosses =
          segment_crosses_triangle(from, to, v[std::size_t(tri[0])], v[std::size_t(tri[1])], v[std::size_t(tri[2])]);
      if (crosses) out.where.emplace_back(k, quad_of[std::size_t(t)]);
    });
    out.crossings += crosses ? 1 : 0;
  }
  out.pct = 100.0 * double(out.crossings) / double(out.segments);
  out.ms = clock.ms();
  return out;
}

}  // namespace clothbench
