#pragma once
/// Garment patterns (2D panels in cm, placements, seams) and their meshing into regular grids
/// of mass points (dressing section 3, Durupinar section 2), placed around a body in 3D.
#include <string>
#include <vector>

#include <Eigen/Core>

#include "clothbench/sim/body_frame.hpp"
#include "clothbench/sim/cloth.hpp"

namespace clothbench {

using Vec2d = Eigen::Vector2d;  ///< a pattern point [cm]

/// Where a panel goes around the body. The panel's 2D frame (u right, v up, in cm) is laid in the
/// body's XY plane facing +Z, optionally wrapped around a vertical axis `wrap_radius_cm` behind it,
/// then rotated by `pitch_deg` about +X (positive turns +Y towards +Z; 90 lays a panel flat, e.g. a
/// tablecloth), `roll_deg` about +Z (limb tilt, positive turns +Y towards -X) and `yaw_deg` about +Y
/// (180 = a back panel facing -Z), and finally moved so that the pattern origin (0, 0) lands at
/// the landmark `anchor` (fractions of the body's bounding box, 0..1 per axis) plus `offset_cm`.
struct Placement {
  Vec3 anchor = Vec3(0.5f, 0.5f, 0.5f);  ///< fractions of the body bounding box (x, y, z)
  Vec3 offset_cm = Vec3::Zero();         ///< added after the anchor [cm]
  Real yaw_deg = 0;                      ///< rotation about +Y [deg]
  Real roll_deg = 0;                     ///< rotation about +Z [deg], applied before yaw
  Real pitch_deg = 0;                    ///< rotation about +X [deg], applied before roll
  Real wrap_radius_cm = 0;               ///< 0 = flat; > 0 wraps the panel around a vertical axis [cm]
};

/// One panel: a closed outline (curves already flattened), split into named edges.
struct Panel {
  std::string name;
  std::vector<Vec2d> outline;   ///< outline points [cm], not repeating the first; >= 3
  std::vector<int> edge_begin;  ///< outline index where each edge starts (ascending, first 0)
  Placement placement;
  std::vector<int> attached_edges;      ///< edges whose mesh vertices are bound to the body (Durupinar 3.2)
  std::vector<std::string> edge_names;  ///< as written in the pattern file, one per edge (empty: unnamed)

  int edge_count() const { return static_cast<int>(edge_begin.size()); }
};

/// A seam: edge `edge_a` of panel `panel_a` sewn to edge `edge_b` of panel `panel_b`, both walked
/// in their outline direction, or one against the other when `reversed`.
struct Seam {
  int panel_a = 0, edge_a = 0;
  int panel_b = 0, edge_b = 0;
  bool reversed = true;  ///< true: start of a meets end of b (the usual case for mirrored panels)
};

/// A garment's cutting patterns.
struct Pattern {
  std::string name;
  std::vector<Panel> panels;
  std::vector<Seam> seams;
};

/// Grid resolution: `spacing_cm` > 0 wins; otherwise the spacing is solved so that the whole
/// garment has `target_vertices` vertices (within a few per cent).
struct MeshingOptions {
  double spacing_cm = 0;
  int target_vertices = 0;
  bool attach = true;  ///< honour the panels' attached edges
  /// Durupinar's construction (section 2): the outline drawn on the grid by Bresenham lines between its points
  /// snapped to grid nodes and filled 4-neighbour, every vertex a grid node (no spring under a spacing, the outline
  /// jagged by up to half a spacing), seams paired as drawn; false: the ring snapped onto the outline (mesh_pattern)
  bool on_grid = false;
  /// On the grid: Durupinar's optional step 7, the jagged outline made smooth. Each outline vertex moves to its
  /// closest point on the panel's outline, or as far towards it as keeps every structural spring at it at least half
  /// a spacing long and every cell at it turning the way it did; then, the vertices off their nodes, the seams' runs
  /// are aligned as the ring mesher's are (every seam vertex paired) and any spring left under half a spacing is
  /// lengthened (mesh_pattern)
  bool smooth = false;
};

/// The meshed pattern before placement: the cloth with 2D pattern coordinates kept.
struct MeshedPattern {
  ClothMesh mesh;                      ///< positions hold (u, v, 0) [m] until placed
  Eigen::Matrix2Xd uv;                 ///< pattern coordinates [cm] (2 x nv)
  std::vector<std::uint8_t> boundary;  ///< 1 for vertices placed on the outline (nv)
  std::vector<int> seam_pair_count;    ///< vertex pairs per seam
  std::vector<int> seam_loose_count;   ///< per seam: vertices of its two edges without a partner
  std::vector<double> seam_offset_cm;  ///< per seam pair: its partners' distance along the seam [cm]
  double spacing_cm = 0;
};

/// Throws std::invalid_argument naming the panel/seam when the pattern is malformed: fewer than 3
/// points, bad edge indices, an edge with no segment, an outline that is not a simple polygon
/// (outline_fault), a seam naming a missing panel or edge, or the same edge pair sewn twice.
void validate_pattern(const Pattern& pattern);

/// Outline coordinates beyond +-this [cm] (10 km) are rejected: Boost.Geometry's validity test
/// works on the outline rescaled to integers and overflows past about 1e9.
inline constexpr double kMaxOutlineCoordinateCm = 1e6;

/// Why a closed outline is not a simple polygon with an area, as Boost.Geometry's is_valid sees it
/// (either orientation is accepted). Segment s runs from outline[s] to outline[s + 1], the last one
/// back to outline[0].
struct OutlineFault {
  std::string what;          ///< empty when the outline is valid, else e.g. "intersects itself"
  int segment = -1;          ///< the segment at fault (of two that meet, the later one), or -1
  int other_segment = -1;    ///< the segment it crosses, touches or runs back along, or -1
  Vec2d at = Vec2d::Zero();  ///< where it happens [cm] (when segment >= 0)
};

/// Checks a closed outline (points not repeating the first): finite coordinates within
/// +-kMaxOutlineCoordinateCm, at least 3 points, and no crossing, touching (a figure eight),
/// running back along itself (a zero-width spike) or zero area.
OutlineFault outline_fault(const std::vector<Vec2d>& outline);

/// True when outline_fault finds a fault (the outline crosses, touches or runs back along itself).
bool outline_self_intersects(const std::vector<Vec2d>& outline);

/// Meshes every panel into a regular grid at `spacing_cm` (dressing section 3): grid nodes inside
/// the outline are kept, and so are nodes on it (a spacing that divides a rectangle keeps its whole
/// grid, corners included); the ring of outside nodes 4-adjacent to them (Durupinar's Bresenham
/// boundary) is snapped onto the closest outline point, so boundary vertices lie exactly on the
/// outline. Springs (structural, shear, flexion) join kept grid neighbours, rest lengths from the
/// 2D pattern; quads where all four corners are kept, triangles (quads repeating their third corner)
/// where three are.
MeshedPattern mesh_pattern(const Pattern& pattern, double spacing_cm, bool attach = true, bool on_grid = false,
                           bool smooth = false);

/// The length of edge `e` of a panel along its outline [cm].
double edge_length_cm(const Panel& panel, int e);
/// An edge's name as the pattern file writes it ("e<index>" for an unnamed edge).
std::string edge_name(const Panel& panel, int e);
/// An edge as a seam names it: "panel.edge".
std::string edge_label(const Pattern& pattern, int panel, int edge);
/// One line for each seam whose two edges differ in length by more than `tolerance` of the longer: both edges by
/// name with their lengths (the seam spreads the shorter edge's partners over the longer one's length, so the
/// garment closes only stretched or gathered there).
std::vector<std::string> seam_length_warnings(const Pattern& pattern, double tolerance = 0.05);

/// Structural springs shorter than half the grid spacing (slivers: a millimetre of error there is a large strain):
/// those joining two outline vertices, and those from the outline inward.
struct Slivers {
  int along = 0, inward = 0;
  int total() const { return along + inward; }
};
Slivers slivers(const MeshedPattern& m);

/// Meshes with `options`: a fixed spacing, or the spacing whose vertex count is closest to the target.
MeshedPattern mesh_pattern(const Pattern& pattern, const MeshingOptions& options);

/// Places a meshed pattern around `body` (Placement above) and returns the 3D cloth.
ClothMesh place_garment(const MeshedPattern& meshed, const Pattern& pattern, const BodyFrame& body);

/// mesh_pattern + place_garment.
ClothMesh build_garment(const Pattern& pattern, const MeshingOptions& options, const BodyFrame& body);

/// Distance [cm] from `p` to the closed outline.
double distance_to_outline(const std::vector<Vec2d>& outline, const Vec2d& p);

/// Points of a quadratic (one control point) or cubic (two) Bezier from a to b, excluding a,
/// including b; `segments` >= 1.
std::vector<Vec2d> flatten_bezier(const Vec2d& a, const std::vector<Vec2d>& controls, const Vec2d& b, int segments);

}  // namespace clothbench
