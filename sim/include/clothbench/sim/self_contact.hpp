#pragma once
/// Cloth against itself, answered: a point of the cloth closer than a thickness to a triangle of the cloth (a quad's
/// half) without a corner at that point, and moving towards it, is stopped by an inelastic impulse along the
/// triangle's normal shared with the triangle's corners by their barycentric weights (Bridson, Fedkiw and Anderson
/// 2002, section 7.1). Candidates, the pairs within twice the thickness, come from a grid of the triangles
/// (TriangleGrid), found again once a point has moved half a thickness since.
#include <utility>
#include <vector>

#include "clothbench/sim/cloth.hpp"
#include "clothbench/sim/triangle_grid.hpp"

namespace clothbench {

class SelfContacts {
 public:
  /// One pass over the points: `v` changed where a point approaches a triangle closer than `thickness` [m] at `x`.
  /// `sewn`: groups of vertices that are one point (a point is never near a triangle with a corner at it, nor at its
  /// seam partner's);
  /// vertices with inv_m 0 do not move. Returns the number of (point, triangle) pairs answered.
  long respond(const ClothMesh& mesh, const std::vector<std::vector<int>>& sewn, const Points3& x, Points3& v,
               const Scalars& inv_m, Real thickness);

 private:
  void group_points(const ClothMesh& mesh, const std::vector<std::vector<int>>& sewn);
  // the (point, triangle) pairs nearer than `reach` at x
  void find_candidates(const ClothMesh& mesh, const Points3& x, Real reach);
  // the impulse that stops point i's approach to triangle c, where nearer than the thickness
  static bool stop(Eigen::Index i, const TriangleGrid::Triangle& c, const Points3& x, Points3& v, const Scalars& inv_m,
                   Real thickness);

  std::vector<TriangleGrid::Triangle> triangles_;  // two per quad
  std::vector<int> point_;                         // per vertex: its point (sewn groups and seam pairs joined)
  std::vector<std::vector<int>> grouped_;          // the sewn groups point_ was made from
  std::vector<Eigen::Index> seen_;                 // per triangle: the last point that tested it
  TriangleGrid grid_;
  Points3 built_;                                         // the positions the candidates were found at
  std::vector<std::pair<Eigen::Index, int>> candidates_;  // (point, triangle) pairs within twice the thickness
};

}  // namespace clothbench
