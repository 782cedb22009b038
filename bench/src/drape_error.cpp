// drape_error: vertices of one cloth against the other's triangles through a uniform grid of triangle boxes.
#include "clothbench/bench/drape_error.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <unordered_map>
#include <vector>

#include "clothbench/sim/mesh_query.hpp"

namespace clothbench {

namespace {

// the cloth's surface (ClothMesh::surface_triangles), and a grid of cells (side kCell) listing the triangles whose
// box meets them
class Surface {
 public:
  explicit Surface(const ClothMesh& cloth) : x_(cloth.positions), tris_(cloth.surface_triangles()) {
    if (tris_.cols() == 0) throw std::invalid_argument("drape_error: a cloth without quads has no surface");
    for (Eigen::Index t = 0; t < tris_.cols(); ++t) {
      Eigen::AlignedBox3f box;
      for (int c = 0; c < 3; ++c) box.extend(x_.col(tris_(c, t)));
      const auto lo = cell(box.min()), hi = cell(box.max());
      for (int i = lo[0]; i <= hi[0]; ++i)
        for (int j = lo[1]; j <= hi[1]; ++j)
          for (int k = lo[2]; k <= hi[2]; ++k) grid_[key({i, j, k})].push_back(static_cast<int>(t));
    }
  }

  // distance from p to the surface: rings of cells around p's until the ring is farther than the best found
  double distance(const Vec3& p) const {
    const auto c = cell(p);
    Real best = std::numeric_limits<Real>::infinity();
    for (int r = 0; r < kMaxRing && !(best <= Real(r - 1) * kCell); ++r)
      for (int i = -r; i <= r; ++i)
        for (int j = -r; j <= r; ++j)
          for (int k = -r; k <= r; ++k) {
            if (std::max({std::abs(i), std::abs(j), std::abs(k)}) != r) continue;  // the ring's shell only
            const auto it = grid_.find(key({c[0] + i, c[1] + j, c[2] + k}));
            if (it == grid_.end()) continue;
            for (int t : it->second) best = std::min(best, squared(p, t));
          }
    if (!(best <= Real(kMaxRing - 1) * kCell))  // farther than the rings reach: every triangle
      for (Eigen::Index t = 0; t < tris_.cols(); ++t) best = std::min(best, squared(p, static_cast<int>(t)));
    return std::sqrt(double(best));
  }

 private:
  static constexpr Real kCell = 0.02f;  // [m]
  static constexpr int kMaxRing = 8;
  using Cell = std::array<int, 3>;
  static Cell cell(const Vec3& p) {
    return {int(std::floor(p.x() / kCell)), int(std::floor(p.y() / kCell)), int(std::floor(p.z() / kCell))};
  }
  static long long key(const Cell& c) {
    return ((long long)(c[0] & 0xfffff) << 40) | ((long long)(c[1] & 0xfffff) << 20) | (long long)(c[2] & 0xfffff);
  }
  Real squared(const Vec3& p, int t) const {
    return closest_point_on_triangle(p, x_.col(tris_(0, t)), x_.col(tris_(1, t)), x_.col(tris_(2, t))).dist2;
  }
  const Points3& x_;
  const Tris tris_;
  std::unordered_map<long long, std::vector<int>> grid_;
};

// adds the distances of a's vertices to b's surface
void one_way(const ClothMesh& a, const Surface& b, double& sum2, DrapeError& e) {
  for (Eigen::Index v = 0; v < a.positions.cols(); ++v) {
    if (!a.positions.col(v).allFinite()) continue;
    const double d = b.distance(a.positions.col(v));
    sum2 += d * d;
    e.max = std::max(e.max, d);
    ++e.points;
  }
}

}  // namespace

DrapeError drape_error(const ClothMesh& a, const ClothMesh& b) {
  const Surface sa(a), sb(b);
  DrapeError e;
  double sum2 = 0;
  one_way(a, sb, sum2, e);
  one_way(b, sa, sum2, e);
  e.rms = e.points ? std::sqrt(sum2 / double(e.points)) : 0;
  return e;
}

}  // namespace clothbench
