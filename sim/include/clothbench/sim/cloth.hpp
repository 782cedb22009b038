#pragma once
/// The cloth of the papers: a regular mass-spring mesh (dressing section 3, walking 2.2).
#include <cstdint>
#include <string>
#include <vector>

#include "clothbench/sim/types.hpp"

namespace clothbench {

/// The three spring kinds of dressing section 3; seam springs join panels while sewing.
enum class SpringKind : std::uint8_t { kStructural = 0, kShear = 1, kFlexion = 2 };
inline constexpr int kSpringKinds = 3;
const char* to_string(SpringKind kind);

/// Topology and rest state of a garment or cloth piece, as meshed from its patterns.
/// Arrays are flat (no per-element objects) so the solver streams through them.
struct ClothMesh {
  Points3 positions;             ///< initial vertex positions [m] (3 x nv)
  Scalars vertex_area;           ///< cloth area carried by each vertex [m^2] (nv); mass = area x density
  Pairs springs;                 ///< spring end vertices (2 x ns)
  Scalars rest_length;           ///< natural length l0 per spring [m] (ns)
  std::vector<SpringKind> kind;  ///< kind per spring (ns)
  Quads quads;                   ///< grid cells, for face-body queries (4 x nq); a triangle repeats corner 2 as 3
  Pairs seam_pairs;              ///< vertex pairs to sew together (2 x np)
  /// Seam vertices without a partner vertex (the edge with more vertices has some; 3 x nl): the vertex and
  /// the two partner-edge vertices around its arc fraction (the same vertex twice beyond the partner edge's
  /// last one). The seam is closed there when the vertex lies on the segment between those two.
  Triples seam_loose;
  std::vector<std::int32_t> panel;       ///< panel index per vertex (nv)
  std::vector<std::string> panel_names;  ///< one per panel
  std::vector<std::int32_t> attached;    ///< vertices bound to the body (Durupinar 3.2)

  int vertex_count() const { return static_cast<int>(positions.cols()); }
  int spring_count() const { return static_cast<int>(springs.cols()); }
  /// Springs of one kind.
  int count(SpringKind k) const;
  /// The shortest rest length of the springs of one kind [m] (0 when there are none).
  Real shortest(SpringKind k) const;
  /// The cloth's surface: every quad as two triangles (0 1 2, 0 2 3), a triangle cell (corner 2 repeated as 3)
  /// as one (3 x nt).
  Tris surface_triangles() const;
  /// Appends another mesh (indices shifted); used to assemble panels into a garment.
  void append(const ClothMesh& other);
  /// Throws std::invalid_argument naming `what` on inconsistent sizes or bad indices.
  void validate(const std::string& what) const;
};

/// A regular grid cloth of nx x ny vertices spaced `spacing` [m] in the plane through
/// `origin` spanned by unit vectors `u` and `v`: structural, shear and flexion springs and quads.
ClothMesh make_grid_cloth(int nx, int ny, Real spacing, const Vec3& origin, const Vec3& u, const Vec3& v);

/// Cells as triangles: every quad as two (0 1 2, 0 2 3), a triangle cell (corner 2 repeated as 3) as one (3 x nt).
Tris surface_triangles(const Quads& quads);

/// Sewn points (Durupinar 3.1): per vertex of `vertex_count`, the point it moves as, its own index or its sewn
/// group's first member (`Simulator::sewn_points()`; members out of range are skipped).
std::vector<int> sewn_point_of(std::size_t vertex_count, const std::vector<std::vector<int>>& groups);

}  // namespace clothbench
