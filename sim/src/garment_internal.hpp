#pragma once
// What the parts of garment meshing share (sim/src): outline geometry (pattern_geometry.cpp), the panel
// grid (panel_grid.cpp) and the seam alignment (seam_alignment.cpp), put together by garment.cpp.
#include <array>
#include <cstdint>
#include <set>
#include <utility>
#include <vector>

#include "clothbench/sim/garment.hpp"

namespace clothbench::garment_detail {

// the closest point of an outline to a point: where, how far, on which segment, at which fraction of it
struct Closest {
  Vec2d point;
  double dist = 1e300;
  int segment = -1;
  double t = 0;
};

// the closest point of the closed outline `o` to `p`
Closest closest_on_outline(const std::vector<Vec2d>& o, const Vec2d& p);
// whether `p` lies inside the closed outline `o` (even-odd rule)
bool inside(const std::vector<Vec2d>& o, const Vec2d& p);
// the z component of a x b
double cross(const Vec2d& a, const Vec2d& b);
// Twice the signed area of a closed outline (shoelace): > 0 counter-clockwise [cm^2].
double twice_signed_area(const std::vector<Vec2d>& o);

// One meshed panel: vertices (uv), which are on the outline, per edge the boundary vertices
// ordered by their arc-length position along the edge, and the grid's springs and quads.
struct PanelGrid {
  std::vector<Vec2d> uv;
  std::vector<std::uint8_t> boundary;
  std::vector<std::vector<std::pair<double, int>>> edge_vertices;  // (arc position, local vertex)
  std::vector<std::array<int, 2>> springs;
  std::vector<SpringKind> kinds;
  std::vector<std::array<int, 4>> quads;
};

// the panel's grid at spacing h: nodes inside the outline, the ring around them snapped onto it
PanelGrid grid_panel(const Panel& p, double h);
// The panel's grid at spacing h by Durupinar's construction (section 2, steps 1-6): the outline's points snapped to
// their nearest grid nodes and joined by Bresenham lines, the nodes inside them found by a 4-neighbour fill, so that
// every vertex is a grid node and every structural spring a spacing long; the outline is followed to within half a
// spacing. `smooth`: then Durupinar's step 7 (MeshingOptions::smooth). `drawn` gets the panel with the outline its
// vertices follow: as drawn on the grid, or smoothed, the panel's own (its cells' inside test).
PanelGrid grid_panel_on_grid(const Panel& p, double h, bool smooth, Panel& drawn);
// A new boundary vertex at pattern point `at` on the outline between boundary neighbours u and w: the cell
// that joins them is cut into a triangle and the rest, their spring split in two, and the new vertex joined
// across the cell (where no cell joins them, the triangle u, new, w). Returns its index.
int split_boundary_edge(PanelGrid& g, int u, int w, const Vec2d& at);
// The panel's cloth from its final uv: positions (u, v, 0) [m], rest lengths from the pattern,
// a quarter of each adjacent cell's area per vertex.
ClothMesh panel_mesh(const Panel& p, const PanelGrid& g, double h);

// Sewn edges get their boundary vertices at matching arc fractions, so every seam pair joins the
// same pattern point on both sides (a mismatch would leave a gap the seam can never close). The
// first seam to touch an edge spreads the shorter run evenly and moves the other onto it; an edge
// already placed by an earlier seam stays fixed.
void align_seam_vertices(const Pattern& pat, double h, std::vector<PanelGrid>& grids);
// After alignment, each structural spring still under half a spacing (a sliver, where a millimetre of error is a
// large strain) is lengthened. A seam whose runs are crowded between the vertices on their corners (a later seam's end
// moved onto a corner beside one) spreads both runs alike. An edge no seam placed is spread evenly between the
// vertices that bound it on the outline first: where two of them stand closer than half a spacing, or every such edge
// with `spread_every_open_edge` (smoothing leaves their arc fractions stale, their vertices crowded near corners). Of
// two outline vertices, the one that is no corner moves along its edge to midway between its run neighbours, where that
// leaves both its gaps at least half a spacing (its seam partner keeps its place: the pair then sews across, at most a
// quarter spacing apart or no farther than before); an inside vertex moves away from the outline to half a spacing
// (inside_by_half), and the next one in along their spring if it then comes too near.
void clear_slivers(const Pattern& pat, double h, std::vector<PanelGrid>& grids, bool spread_every_open_edge);
// Where an inside point q nearer the outline than half a spacing h (c: its closest outline point) is moved: straight
// away from the outline to half a spacing, where that takes it farther from the outline; else q.
Vec2d clear_of_outline(const std::vector<Vec2d>& outline, const Vec2d& q, const Closest& c, double h);
// An inner vertex at q at least half a spacing inside the outline: q outside it (a grid node between a staircase
// and the outline) moves across it to half a spacing inside, q inside as clear_of_outline moves it.
Vec2d inside_by_half(const std::vector<Vec2d>& outline, const Vec2d& q, double h);
// Pairs two vertex runs by arc position (fraction of the edge length, so edges of different
// length or count match): every vertex of the shorter run gets the vertex of the longer run
// nearest in relative position (Durupinar section 2: closest vertex on the second panel); driving
// from the shorter run never sews two neighbours of one panel onto one point.
std::vector<std::array<int, 2>> match_runs(const std::vector<std::pair<double, int>>& a,
                                           const std::vector<std::pair<double, int>>& b, bool reversed);
// Edge e's run, with the panel's vertex at either corner of the edge added where the run stops short of it.
std::vector<std::pair<double, int>> run_to_corners(const Panel& p, int e, const PanelGrid& g);
// A seam vertex without a partner vertex, and the two partner-edge vertices around its arc fraction.
struct LooseVertex {
  int v, b0, b1;
};
// The vertices of `run` that no pair names (`paired`), each with the two vertices of the partner run around
// its arc fraction (1 - t when the seam is reversed; the partner's end vertex twice beyond its ends).
std::vector<LooseVertex> loose_vertices(const std::vector<std::pair<double, int>>& run,
                                        const std::vector<std::pair<double, int>>& partner, bool reversed,
                                        const std::set<int>& paired);
// How far apart along the seam the partners of a pair sit in the pattern [cm]: the difference of
// their arc fractions (one reversed) times the mean length of the two edges.
double pair_offset_cm(const Pattern& pat, const Seam& s, const std::vector<std::pair<double, int>>& ra,
                      const std::vector<std::pair<double, int>>& rb, const std::array<int, 2>& pair);

}  // namespace clothbench::garment_detail
