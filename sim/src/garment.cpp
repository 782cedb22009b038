#include "clothbench/sim/garment.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <stdexcept>
#include <typeinfo>
#include <utility>

#include <boost/geometry/algorithms/is_valid.hpp>
#include <boost/geometry/geometries/point_xy.hpp>
#include <boost/geometry/geometries/ring.hpp>

namespace clothbench {

namespace {

struct Closest {
  Vec2d point;
  double dist = 1e300;
  int segment = -1;
  double t = 0;
};

Closest closest_on_outline(const std::vector<Vec2d>& o, const Vec2d& p) {
  Closest best;
  const int n = static_cast<int>(o.size());
  for (int i = 0; i < n; ++i) {
    const Vec2d a = o[static_cast<std::size_t>(i)], b = o[static_cast<std::size_t>((i + 1) % n)];
    const Vec2d d = b - a;
    const double len2 = d.squaredNorm();
    const double t = len2 > 0 ? std::clamp((p - a).dot(d) / len2, 0.0, 1.0) : 0.0;
    const Vec2d q = a + t * d;
    const double dist = (p - q).norm();
    if (dist < best.dist) best = {q, dist, i, t};
  }
  return best;
}

bool inside(const std::vector<Vec2d>& o, const Vec2d& p) {
  bool in = false;
  const std::size_t n = o.size();
  for (std::size_t i = 0, j = n - 1; i < n; j = i++)
    if ((o[i].y() > p.y()) != (o[j].y() > p.y()) &&
        p.x() < (o[j].x() - o[i].x()) * (p.y() - o[i].y()) / (o[j].y() - o[i].y()) + o[i].x())
      in = !in;
  return in;
}

double cross(const Vec2d& a, const Vec2d& b) { return a.x() * b.y() - a.y() * b.x(); }

namespace bg = boost::geometry;

// Boost.Geometry's is_valid visitor: keeps the failure it reports (it stops at the first) and where it
// is: the two segments of a self-intersection, the apex of a spike. Consecutive duplicate points are
// no failure.
class FaultVisitor {
 public:
  bg::validity_failure_type failure = bg::no_failure;
  int segment = -1, other_segment = -1;  // of a self-intersection
  bool located = false;                  // `at` holds the self-intersection point or spike apex
  Vec2d at = Vec2d::Zero();

  template <bg::validity_failure_type Failure>
  bool apply() {
    return keep(Failure);
  }
  // self-intersections come with their turns, duplicate points with one of them
  template <bg::validity_failure_type Failure, typename Data>
  bool apply(const Data& data) {
    if constexpr (Failure == bg::failure_self_intersections) {
      if (!data.empty()) {
        const auto& turn = *data.begin();
        const int a = static_cast<int>(turn.operations[0].seg_id.segment_index);
        const int b = static_cast<int>(turn.operations[1].seg_id.segment_index);
        segment = std::max(a, b), other_segment = std::min(a, b);
        locate(turn.point);
      }
    }
    return keep(Failure);
  }
  // spikes come with (is the geometry linear, the spike's apex)
  template <bg::validity_failure_type Failure, typename Data1, typename Data2>
  bool apply(const Data1&, const Data2& apex) {
    if constexpr (Failure == bg::failure_spikes) locate(apex);
    return keep(Failure);
  }

 private:
  bool keep(bg::validity_failure_type f) {
    failure = f == bg::failure_duplicate_points ? bg::no_failure : f;
    return failure == bg::no_failure;
  }
  template <typename Point>
  void locate(const Point& p) {
    at = Vec2d(bg::get<0>(p), bg::get<1>(p));
    located = true;
  }
};

// Runs is_valid on the outline as an open ring of the given orientation.
template <bool Clockwise>
FaultVisitor check_ring(const std::vector<Vec2d>& o) {
  bg::model::ring<bg::model::d2::point_xy<double>, Clockwise, false> ring;
  for (const auto& p : o) ring.push_back({p.x(), p.y()});
  FaultVisitor visitor;
  bg::is_valid(ring, visitor, bg::default_strategy());
  return visitor;
}

// Twice the signed area of a closed outline (shoelace): > 0 counter-clockwise [cm^2].
double twice_signed_area(const std::vector<Vec2d>& o) {
  double a = 0;
  for (std::size_t i = 0; i < o.size(); ++i) a += cross(o[i], o[(i + 1) % o.size()]);
  return a;
}

// Grid nodes this close to the outline lie on it [fraction of the grid spacing]: rounding of the node
// positions, far below any distance the mesher resolves.
constexpr double kOnOutline = 1e-6;

// Adds a boundary vertex at `q` to every edge it lies on (corners belong to two), keyed by its
// arc position along the edge as a fraction of the edge length.
void add_to_edges(const Panel& p, const Vec2d& q, int v, std::vector<std::vector<std::pair<double, int>>>& ev) {
  const int n = static_cast<int>(p.outline.size());
  for (int e = 0; e < p.edge_count(); ++e) {
    const int s0 = p.edge_begin[static_cast<std::size_t>(e)];
    const int s1 = e + 1 < p.edge_count() ? p.edge_begin[static_cast<std::size_t>(e + 1)] : n;
    double len = 0, at = -1;
    for (int s = s0; s < s1; ++s) {
      const Vec2d a = p.outline[static_cast<std::size_t>(s)], b = p.outline[static_cast<std::size_t>((s + 1) % n)];
      const double l = (b - a).norm();
      const double t = l > 0 ? std::clamp((q - a).dot(b - a) / (l * l), 0.0, 1.0) : 0.0;
      if (at < 0 && (a + t * (b - a) - q).norm() < 1e-9 * (1 + l)) at = len + t * l;
      len += l;
    }
    if (at >= 0 && len > 0) ev[static_cast<std::size_t>(e)].push_back({at / len, v});
  }
}

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

// Grid nodes inside the outline, and the ring around them snapped onto the outline.
void place_grid_vertices(const Panel& p, double h, PanelGrid& g, std::vector<int>& id, int& nx, int& ny) {
  Vec2d lo = p.outline[0], hi = p.outline[0];
  for (const auto& q : p.outline) lo = lo.cwiseMin(q), hi = hi.cwiseMax(q);
  // grid cells across the box; a spacing that divides it exactly counts exactly, not one more for
  // the rounding of the division (that would shift the centred grid by h/2 off the outline)
  auto cells = [&](double extent) { return static_cast<int>(std::ceil(extent / h - kOnOutline)); };
  nx = cells(hi.x() - lo.x()) + 3;
  ny = cells(hi.y() - lo.y()) + 3;
  // the grid is centred on the outline's box, so mirrored panels get mirrored vertices
  const Vec2d origin = 0.5 * (lo + hi) - 0.5 * h * Vec2d(nx - 1, ny - 1);
  auto node = [&](int i, int j) -> Vec2d { return origin + h * Vec2d(i, j); };
  id.assign(static_cast<std::size_t>(nx * ny), -1);
  // inside nodes farther than h/4 from the outline are kept as they are; nodes on the outline (within
  // rounding: a spacing that divides a straight edge's position) are kept too, as boundary vertices,
  // whatever the inside test says there. The ring below would miss such a node at a corner: its
  // 4-neighbours lie on the outline too, none of them an inside node
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const Vec2d q = node(i, j);
      const Closest c = closest_on_outline(p.outline, q);
      const bool on = c.dist <= kOnOutline * h;
      if (!on && !(c.dist > 0.25 * h && inside(p.outline, q))) continue;
      id[static_cast<std::size_t>(j * nx + i)] = static_cast<int>(g.uv.size());
      g.uv.push_back(on ? c.point : q);
      g.boundary.push_back(on ? 1 : 0);
      if (on) add_to_edges(p, c.point, id[static_cast<std::size_t>(j * nx + i)], g.edge_vertices);
    }
  // the ring around them is snapped onto the outline (Durupinar's boundary set, made smooth)
  auto near_kept = [&](const Vec2d& q) {
    for (const auto& u : g.uv)
      if ((u - q).norm() < 0.3 * h) return true;
    return false;
  };
  for (int j = 1; j + 1 < ny; ++j)
    for (int i = 1; i + 1 < nx; ++i) {
      const auto k = static_cast<std::size_t>(j * nx + i);
      if (id[k] >= 0) continue;
      const bool ring = id[k - 1] >= 0 || id[k + 1] >= 0 || id[k - static_cast<std::size_t>(nx)] >= 0 ||
                        id[k + static_cast<std::size_t>(nx)] >= 0;
      if (!ring) continue;
      const Closest c = closest_on_outline(p.outline, node(i, j));
      if (near_kept(c.point)) continue;
      id[k] = static_cast<int>(g.uv.size());
      g.uv.push_back(c.point);
      g.boundary.push_back(1);
      add_to_edges(p, c.point, id[k], g.edge_vertices);
    }
  for (auto& ev : g.edge_vertices) std::sort(ev.begin(), ev.end());
}

PanelGrid grid_panel(const Panel& p, double h) {
  PanelGrid g;
  g.edge_vertices.resize(static_cast<std::size_t>(p.edge_count()));
  std::vector<int> id;
  int nx = 0, ny = 0;
  place_grid_vertices(p, h, g, id, nx, ny);
  // springs and quads between kept grid neighbours
  auto at = [&](int i, int j) {
    return (i < 0 || j < 0 || i >= nx || j >= ny) ? -1 : id[static_cast<std::size_t>(j * nx + i)];
  };
  auto add = [&](int a, int b, SpringKind kind) {
    if (a < 0 || b < 0) return;
    g.springs.push_back({a, b});
    g.kinds.push_back(kind);
  };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int a = at(i, j);
      if (a < 0) continue;
      add(a, at(i + 1, j), SpringKind::kStructural);
      add(a, at(i, j + 1), SpringKind::kStructural);
      add(a, at(i + 1, j + 1), SpringKind::kShear);
      add(at(i + 1, j), at(i, j + 1), SpringKind::kShear);
      add(a, at(i + 2, j), SpringKind::kFlexion);
      add(a, at(i, j + 2), SpringKind::kFlexion);
    }
  // cells: four kept corners make a quad; three (a cell the outline cuts, along a slanted or curved
  // edge) make a triangle, stored as a quad whose last corner repeats its third; left out, they would
  // leave a staircase of holes along the outline, in the pictures, the face queries and the masses
  for (int j = 0; j + 1 < ny; ++j)
    for (int i = 0; i + 1 < nx; ++i) {
      std::array<int, 4> c{at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)};
      const auto kept = std::remove(c.begin(), c.end(), -1);
      if (kept - c.begin() == 3) c[3] = c[2];
      if (kept - c.begin() >= 3) g.quads.push_back(c);
    }
  return g;
}

// The panel's cloth from its final uv: positions (u, v, 0) [m], rest lengths from the pattern,
// a quarter of each adjacent cell's area per vertex.
ClothMesh panel_mesh(const Panel& p, const PanelGrid& g, double h) {
  ClothMesh m;
  const auto nv = static_cast<Eigen::Index>(g.uv.size());
  m.positions.resize(3, nv);
  for (Eigen::Index v = 0; v < nv; ++v)
    m.positions.col(v) = Vec3(static_cast<Real>(g.uv[static_cast<std::size_t>(v)].x() / 100),
                              static_cast<Real>(g.uv[static_cast<std::size_t>(v)].y() / 100), 0);
  std::vector<Eigen::Index> kept;
  for (std::size_t s = 0; s < g.springs.size(); ++s)
    if ((g.uv[static_cast<std::size_t>(g.springs[s][0])] - g.uv[static_cast<std::size_t>(g.springs[s][1])]).norm() >=
        1e-4)
      kept.push_back(static_cast<Eigen::Index>(s));
  m.springs.resize(2, static_cast<Eigen::Index>(kept.size()));
  m.rest_length.resize(static_cast<Eigen::Index>(kept.size()));
  for (std::size_t k = 0; k < kept.size(); ++k) {
    const auto& e = g.springs[static_cast<std::size_t>(kept[k])];
    m.springs.col(static_cast<Eigen::Index>(k)) << e[0], e[1];
    m.rest_length[static_cast<Eigen::Index>(k)] =
        static_cast<Real>((g.uv[static_cast<std::size_t>(e[0])] - g.uv[static_cast<std::size_t>(e[1])]).norm() / 100.0);
    m.kind.push_back(g.kinds[static_cast<std::size_t>(kept[k])]);
  }
  m.quads.resize(4, static_cast<Eigen::Index>(g.quads.size()));
  m.vertex_area = Scalars::Zero(nv);
  for (std::size_t q = 0; q < g.quads.size(); ++q) {
    const auto& c = g.quads[q];
    m.quads.col(static_cast<Eigen::Index>(q)) << c[0], c[1], c[2], c[3];
    double area = 0;  // shoelace [cm^2]
    for (std::size_t k = 0; k < 4; ++k)
      area += cross(g.uv[static_cast<std::size_t>(c[k])], g.uv[static_cast<std::size_t>(c[(k + 1) % 4])]);
    const std::size_t corners = c[3] == c[2] ? 3 : 4;  // a triangle's area goes to its three corners
    for (std::size_t k = 0; k < corners; ++k)
      m.vertex_area[c[k]] += static_cast<Real>(std::abs(area) / 2e4 / double(corners));
  }
  const Real floor_area = static_cast<Real>(0.05 * h * h / 1e4);  // vertices touching no cell
  for (Eigen::Index v = 0; v < nv; ++v) m.vertex_area[v] = std::max(m.vertex_area[v], floor_area);
  m.panel.assign(static_cast<std::size_t>(nv), 0);
  m.panel_names = {p.name};
  m.seam_pairs.resize(2, 0);
  return m;
}

// Outline indices [s0, s1) of the segments of edge e.
std::pair<int, int> edge_segments(const Panel& p, int e) {
  const int n = static_cast<int>(p.outline.size());
  return {p.edge_begin[static_cast<std::size_t>(e)],
          e + 1 < p.edge_count() ? p.edge_begin[static_cast<std::size_t>(e + 1)] : n};
}

Vec2d outline_point(const Panel& p, int s) { return p.outline[static_cast<std::size_t>(s) % p.outline.size()]; }

double edge_length(const Panel& p, int e) {
  const auto [s0, s1] = edge_segments(p, e);
  double len = 0;
  for (int s = s0; s < s1; ++s) len += (outline_point(p, s + 1) - outline_point(p, s)).norm();
  return len;
}

// The point at arc fraction t (0..1) of edge e of panel p.
Vec2d point_on_edge(const Panel& p, int e, double t) {
  const auto [s0, s1] = edge_segments(p, e);
  double left = t * edge_length(p, e);
  for (int s = s0; s < s1; ++s) {
    const Vec2d a = outline_point(p, s), b = outline_point(p, s + 1);
    const double l = (b - a).norm();
    if (left <= l || s + 1 == s1) return l > 0 ? Vec2d(a + std::min(left / l, 1.0) * (b - a)) : a;
    left -= l;
  }
  return outline_point(p, s1);
}

// Edge runs whose vertices sit at arc fractions 0 or 1 are panel corners: they stay.
bool is_corner(double t) { return t < 1e-9 || t > 1 - 1e-9; }

// Moves the vertices of a run (sorted by arc fraction) to new fractions: corners stay, `anchors`
// (run index -> fraction) are met exactly, and the others spread evenly by index between them;
// a run's free ends lie half a spacing from the edge's ends.
void respace_run(std::vector<std::pair<double, int>>& run, std::map<int, double> anchors) {
  const int n = static_cast<int>(run.size());
  if (n == 0) return;
  std::vector<std::pair<double, double>> knots;  // (index, fraction), ascending in both
  knots.push_back(is_corner(run.front().first) ? std::pair{0.0, run.front().first} : std::pair{-0.5, 0.0});
  for (int i = 0; i < n; ++i)
    if (is_corner(run[static_cast<std::size_t>(i)].first)) anchors.erase(i);
  for (const auto& [i, t] : anchors)
    if (t > knots.back().second && i > knots.back().first) knots.push_back({double(i), t});
  const auto last = is_corner(run.back().first) ? std::pair{double(n - 1), run.back().first} : std::pair{n - 0.5, 1.0};
  while (knots.size() > 1 && !(knots.back().first < last.first && knots.back().second < last.second)) knots.pop_back();
  knots.push_back(last);
  std::size_t k = 0;
  for (int i = 0; i < n; ++i) {
    if (is_corner(run[static_cast<std::size_t>(i)].first)) continue;
    while (k + 2 < knots.size() && knots[k + 1].first < i) ++k;
    const auto [i0, t0] = knots[k];
    const auto [i1, t1] = knots[k + 1];
    run[static_cast<std::size_t>(i)].first = t0 + (t1 - t0) * (i - i0) / (i1 - i0);
  }
}

// Anchors of a free run on a fixed one: the smaller run is matched index by index to the larger
// (monotone, nearest in arc fraction), and the free run's matched vertices take the fixed
// partners' fractions (1 - t when the seam is reversed).
std::map<int, double> seam_anchors(const std::vector<std::pair<double, int>>& fixed,
                                   const std::vector<std::pair<double, int>>& free_run, bool reversed) {
  std::vector<double> f;  // fixed fractions in the free run's direction, ascending
  for (const auto& [t, v] : fixed) f.push_back(reversed ? 1 - t : t);
  std::sort(f.begin(), f.end());
  const bool free_smaller = free_run.size() <= f.size();
  const std::size_t m = std::min(free_run.size(), f.size()), big = std::max(free_run.size(), f.size());
  std::map<int, double> anchors;
  std::size_t lo = 0;
  for (std::size_t k = 0; k < m; ++k) {
    const double t = free_smaller ? free_run[k].first : f[k];
    std::size_t best = lo;
    for (std::size_t j = lo; j + (m - k) <= big; ++j) {
      const double tj = free_smaller ? f[j] : free_run[j].first;
      const double tb = free_smaller ? f[best] : free_run[best].first;
      if (std::abs(tj - t) < std::abs(tb - t)) best = j;
    }
    lo = best + 1;
    if (free_smaller)
      anchors[static_cast<int>(k)] = f[best];
    else
      anchors[static_cast<int>(best)] = f[k];
  }
  return anchors;
}

// Whether some vertex of the panel sits at pattern point p.
bool occupied(const PanelGrid& g, const Vec2d& p) {
  return std::any_of(g.uv.begin(), g.uv.end(), [&](const Vec2d& q) { return (q - p).norm() < 1e-9; });
}

// Whether vertex v lies on more than one edge of the panel (a corner, or where edges touch).
bool on_several_edges(const PanelGrid& g, int v) {
  int runs = 0;
  for (const auto& run : g.edge_vertices)
    runs += std::any_of(run.begin(), run.end(), [&](const auto& tv) { return tv.second == v; });
  return runs > 1;
}

// The edge that shares edge e's end `t` (0: its start, 1: its end) as a corner: the one before or after it
// on the closed outline (-1 for a panel of one edge, whose ends meet each other).
int edge_at_corner(const Panel& p, int e, double t) {
  const int n = p.edge_count();
  if (n < 2) return -1;
  return t > 0.5 ? (e + 1) % n : (e + n - 1) % n;
}

// Where one edge of a seam has a vertex on a corner and the other's end vertex lies less than a
// grid spacing h short of the matching corner, that vertex moves onto the corner (when its panel has no vertex there
// and its edge was not aligned by an earlier seam), so the seam's end pairs join corner to corner. The moved
// vertex now lies on the edge that meets this one at the corner too, and joins that edge's run there:
// otherwise a later seam along that edge pairs its own end vertex, a fraction of a spacing from the
// corner, with what is sewn to the corner, and the two seams together draw two neighbouring vertices of
// one panel onto one point (their spring squeezed to nothing, the seam gap stuck at millimetres).
void snap_seam_ends(const Pattern& pat, const Seam& s, double h, std::vector<PanelGrid>& grids,
                    const std::set<std::pair<int, int>>& locked) {
  const bool a_locked = locked.count({s.panel_a, s.edge_a}) > 0, b_locked = locked.count({s.panel_b, s.edge_b}) > 0;
  PanelGrid& ga = grids[static_cast<std::size_t>(s.panel_a)];
  PanelGrid& gb = grids[static_cast<std::size_t>(s.panel_b)];
  auto& ra = ga.edge_vertices[static_cast<std::size_t>(s.edge_a)];
  auto& rb = gb.edge_vertices[static_cast<std::size_t>(s.edge_b)];
  if (ra.empty() || rb.empty()) return;
  const Panel& pa = pat.panels[static_cast<std::size_t>(s.panel_a)];
  const Panel& pb = pat.panels[static_cast<std::size_t>(s.panel_b)];
  struct Joined {
    int panel, edge, vertex;
    double t;  // the corner's fraction on `edge`
  };
  std::vector<Joined> joined;  // added after the loop: the runs' references stay valid until then
  for (const double ta : {0.0, 1.0}) {
    const double tb = s.reversed ? 1 - ta : ta;
    auto& va = ta > 0.5 ? ra.back() : ra.front();
    auto& vb = tb > 0.5 ? rb.back() : rb.front();
    const bool a_on = std::abs(va.first - ta) < 1e-9, b_on = std::abs(vb.first - tb) < 1e-9;
    const bool a_near = std::abs(va.first - ta) * edge_length(pa, s.edge_a) < h && !on_several_edges(ga, va.second);
    const bool b_near = std::abs(vb.first - tb) * edge_length(pb, s.edge_b) < h && !on_several_edges(gb, vb.second);
    if (a_on && !b_on && b_near && !b_locked && !occupied(gb, point_on_edge(pb, s.edge_b, tb))) {
      vb.first = tb;
      joined.push_back({s.panel_b, edge_at_corner(pb, s.edge_b, tb), vb.second, 1 - tb});
    }
    if (b_on && !a_on && a_near && !a_locked && !occupied(ga, point_on_edge(pa, s.edge_a, ta))) {
      va.first = ta;
      joined.push_back({s.panel_a, edge_at_corner(pa, s.edge_a, ta), va.second, 1 - ta});
    }
  }
  for (const Joined& j : joined) {
    if (j.edge < 0 || locked.count({j.panel, j.edge}) > 0) continue;
    auto& run = grids[static_cast<std::size_t>(j.panel)].edge_vertices[static_cast<std::size_t>(j.edge)];
    if (std::any_of(run.begin(), run.end(), [&](const auto& tv) { return tv.second == j.vertex; })) continue;
    run.insert(j.t > 0.5 ? run.end() : run.begin(), {j.t, j.vertex});
  }
}

// Moves the vertices of an edge run to the pattern points of their arc fractions.
void place_run(const Panel& p, int edge, PanelGrid& g) {
  for (const auto& [t, v] : g.edge_vertices[static_cast<std::size_t>(edge)])
    g.uv[static_cast<std::size_t>(v)] = point_on_edge(p, edge, t);
}

// Sewn edges get their boundary vertices at matching arc fractions, so every seam pair joins the
// same pattern point on both sides (a mismatch would leave a gap the seam can never close). The
// first seam to touch an edge spreads the shorter run evenly and moves the other onto it; an edge
// already placed by an earlier seam stays fixed.
void align_seam_vertices(const Pattern& pat, double h, std::vector<PanelGrid>& grids) {
  std::set<std::pair<int, int>> done;
  for (const auto& s : pat.seams) {
    auto& ra = grids[static_cast<std::size_t>(s.panel_a)].edge_vertices[static_cast<std::size_t>(s.edge_a)];
    auto& rb = grids[static_cast<std::size_t>(s.panel_b)].edge_vertices[static_cast<std::size_t>(s.edge_b)];
    const bool a_done = done.count({s.panel_a, s.edge_a}) > 0, b_done = done.count({s.panel_b, s.edge_b}) > 0;
    if ((a_done && b_done) || &ra == &rb) continue;
    snap_seam_ends(pat, s, h, grids, done);
    const bool a_fixed = a_done || (!b_done && ra.size() <= rb.size());
    auto& fixed = a_fixed ? ra : rb;
    auto& free_run = a_fixed ? rb : ra;
    if (!(a_fixed ? a_done : b_done)) respace_run(fixed, {});
    respace_run(free_run, seam_anchors(fixed, free_run, s.reversed));
    place_run(pat.panels[static_cast<std::size_t>(s.panel_a)], s.edge_a, grids[static_cast<std::size_t>(s.panel_a)]);
    place_run(pat.panels[static_cast<std::size_t>(s.panel_b)], s.edge_b, grids[static_cast<std::size_t>(s.panel_b)]);
    done.insert({s.panel_a, s.edge_a});
    done.insert({s.panel_b, s.edge_b});
  }
}

// Pairs two vertex runs by arc position (fraction of the edge length, so edges of different
// length or count match): every vertex of the shorter run gets the vertex of the longer run
// nearest in relative position (Durupinar section 2: closest vertex on the second panel); driving
// from the shorter run never sews two neighbours of one panel onto one point.
std::vector<std::array<int, 2>> match_runs(const std::vector<std::pair<double, int>>& a,
                                           const std::vector<std::pair<double, int>>& b, bool reversed) {
  std::vector<std::array<int, 2>> out;
  if (a.empty() || b.empty()) return out;
  auto rel = [](const std::vector<std::pair<double, int>>& r, std::size_t i) { return r[i].first; };
  const bool a_drives = a.size() < b.size();  // 'lo' drives: the shorter run
  const auto& lo = a_drives ? a : b;
  const auto& sh = a_drives ? b : a;
  for (std::size_t i = 0; i < lo.size(); ++i) {
    double t = rel(lo, i);
    if (reversed) t = 1 - t;
    std::size_t best = 0;
    for (std::size_t j = 1; j < sh.size(); ++j)
      if (std::abs(rel(sh, j) - t) < std::abs(rel(sh, best) - t)) best = j;
    out.push_back(a_drives ? std::array<int, 2>{lo[i].second, sh[best].second}
                           : std::array<int, 2>{sh[best].second, lo[i].second});
  }
  return out;
}

// How far apart along the seam the partners of a pair sit in the pattern [cm]: the difference of
// their arc fractions (one reversed) times the mean length of the two edges.
double pair_offset_cm(const Pattern& pat, const Seam& s, const std::vector<std::pair<double, int>>& ra,
                      const std::vector<std::pair<double, int>>& rb, const std::array<int, 2>& pair) {
  auto fraction = [](const std::vector<std::pair<double, int>>& r, int v) {
    for (const auto& [t, u] : r)
      if (u == v) return t;
    return 0.0;
  };
  const double ta = fraction(ra, pair[0]), tb = fraction(rb, pair[1]);
  const double la = edge_length(pat.panels[static_cast<std::size_t>(s.panel_a)], s.edge_a);
  const double lb = edge_length(pat.panels[static_cast<std::size_t>(s.panel_b)], s.edge_b);
  return std::abs(ta - (s.reversed ? 1 - tb : tb)) * 0.5 * (la + lb);
}

Eigen::Matrix3f placement_rotation(const Placement& pl) {
  const float d2r = static_cast<float>(M_PI / 180.0);
  return (Eigen::AngleAxisf(pl.yaw_deg * d2r, Vec3::UnitY()) * Eigen::AngleAxisf(pl.roll_deg * d2r, Vec3::UnitZ()) *
          Eigen::AngleAxisf(pl.pitch_deg * d2r, Vec3::UnitX()))
      .toRotationMatrix();
}

}  // namespace

OutlineFault outline_fault(const std::vector<Vec2d>& o) {
  OutlineFault f;
  for (std::size_t i = 0; i < o.size(); ++i)
    if (!(o[i].cwiseAbs().maxCoeff() <= kMaxOutlineCoordinateCm)) {  // NaN too
      f.what = o[i].allFinite() ? "has a point beyond +-1e6 cm (10 km)" : "has a point that is not finite";
      f.segment = static_cast<int>(i), f.at = o[i];
      return f;
    }
  // Boost's polygons have one orientation: take the outline's own (a zero area fails anyway)
  FaultVisitor v;
  try {
    v = twice_signed_area(o) < 0 ? check_ring<true>(o) : check_ring<false>(o);
  } catch (const std::bad_cast& e) {  // Boost rescales the outline to integers: a factor out of range
    f.what = "is too small to check (" + std::string(e.what()) + ")";
    return f;
  }
  switch (v.failure) {
    case bg::no_failure: return f;
    case bg::failure_few_points: f.what = "has fewer than 3 points"; break;
    case bg::failure_wrong_topological_dimension: f.what = "has no area (fewer than 3 distinct points)"; break;
    case bg::failure_spikes: f.what = "runs back along itself"; break;
    case bg::failure_self_intersections: f.what = "intersects itself"; break;
    case bg::failure_wrong_orientation: f.what = "has no area"; break;
    default: f.what = "is not a simple polygon (Boost.Geometry validity failure " + std::to_string(v.failure) + ")";
  }
  if (!v.located) return f;
  f.at = v.at;
  if (v.failure == bg::failure_self_intersections) {
    f.segment = v.segment, f.other_segment = v.other_segment;
  } else {
    // a spike: the segment leaving its apex runs back along the one arriving there
    const int n = static_cast<int>(o.size());
    for (int i = 0; i < n && f.segment < 0; ++i)
      if (o[static_cast<std::size_t>(i)] == v.at) f.segment = i, f.other_segment = (i + n - 1) % n;
  }
  return f;
}

bool outline_self_intersects(const std::vector<Vec2d>& o) { return !outline_fault(o).what.empty(); }

double distance_to_outline(const std::vector<Vec2d>& outline, const Vec2d& p) {
  return closest_on_outline(outline, p).dist;
}

std::vector<Vec2d> flatten_bezier(const Vec2d& a, const std::vector<Vec2d>& c, const Vec2d& b, int segments) {
  std::vector<Vec2d> out;
  for (int s = 1; s <= segments; ++s) {
    const double t = double(s) / segments, u = 1 - t;
    if (c.size() == 1)
      out.push_back(u * u * a + 2 * u * t * c[0] + t * t * b);
    else if (c.size() == 2)
      out.push_back(u * u * u * a + 3 * u * u * t * c[0] + 3 * u * t * t * c[1] + t * t * t * b);
    else
      out.push_back(u * a + t * b);
  }
  return out;
}

void validate_pattern(const Pattern& pat) {
  auto fail = [&](const std::string& m) { throw std::invalid_argument("pattern " + pat.name + ": " + m); };
  if (pat.panels.empty()) fail("no panels");
  std::set<std::string> names;
  for (const auto& p : pat.panels) {
    if (!names.insert(p.name).second) fail("duplicate panel '" + p.name + "'");
    const int n = static_cast<int>(p.outline.size());
    if (n < 3) fail("panel '" + p.name + "' has fewer than 3 outline points");
    if (p.edge_begin.empty() || p.edge_begin[0] != 0) fail("panel '" + p.name + "': first edge must start at 0");
    for (std::size_t e = 1; e < p.edge_begin.size(); ++e)
      if (p.edge_begin[e] <= p.edge_begin[e - 1] || p.edge_begin[e] >= n)
        fail("panel '" + p.name + "': bad edge start");
    const OutlineFault fault = outline_fault(p.outline);
    if (!fault.what.empty()) fail("panel '" + p.name + "' outline " + fault.what);
    for (int e : p.attached_edges)
      if (e < 0 || e >= p.edge_count()) fail("panel '" + p.name + "': attached edge out of range");
  }
  std::set<std::array<int, 4>> seen;
  for (const auto& s : pat.seams) {
    const int np = static_cast<int>(pat.panels.size());
    if (s.panel_a < 0 || s.panel_a >= np || s.panel_b < 0 || s.panel_b >= np) fail("seam names a missing panel");
    if (s.edge_a < 0 || s.edge_a >= pat.panels[static_cast<std::size_t>(s.panel_a)].edge_count() || s.edge_b < 0 ||
        s.edge_b >= pat.panels[static_cast<std::size_t>(s.panel_b)].edge_count())
      fail("seam names a missing edge");
    std::array<int, 4> key{s.panel_a, s.edge_a, s.panel_b, s.edge_b};
    if (key[0] > key[2] || (key[0] == key[2] && key[1] > key[3])) key = {s.panel_b, s.edge_b, s.panel_a, s.edge_a};
    if (!seen.insert(key).second) fail("duplicated seam");
  }
}

MeshedPattern mesh_pattern(const Pattern& pat, double h, bool attach) {
  validate_pattern(pat);
  if (!(h > 0)) throw std::invalid_argument("pattern " + pat.name + ": grid spacing must be > 0");
  MeshedPattern out;
  out.spacing_cm = h;
  std::vector<PanelGrid> grids;
  for (const auto& p : pat.panels) grids.push_back(grid_panel(p, h));
  align_seam_vertices(pat, h, grids);
  std::vector<int> offset;
  for (std::size_t pi = 0; pi < grids.size(); ++pi) {
    const Panel& p = pat.panels[pi];
    offset.push_back(out.mesh.vertex_count());
    out.mesh.append(panel_mesh(p, grids[pi], h));
    for (const auto& q : grids[pi].uv) {
      out.uv.conservativeResize(2, out.uv.cols() + 1);
      out.uv.col(out.uv.cols() - 1) = q;
    }
    out.boundary.insert(out.boundary.end(), grids[pi].boundary.begin(), grids[pi].boundary.end());
    if (attach)
      for (int e : p.attached_edges)
        for (const auto& [s, v] : grids[pi].edge_vertices[static_cast<std::size_t>(e)])
          out.mesh.attached.push_back(v + offset.back());
  }
  std::vector<std::array<int, 2>> pairs;
  for (const auto& s : pat.seams) {
    const auto& ra = grids[static_cast<std::size_t>(s.panel_a)].edge_vertices[static_cast<std::size_t>(s.edge_a)];
    const auto& rb = grids[static_cast<std::size_t>(s.panel_b)].edge_vertices[static_cast<std::size_t>(s.edge_b)];
    // a vertex never pairs with itself (the shared tip of a dart)
    int count = 0;
    for (const auto& pr : match_runs(ra, rb, s.reversed)) {
      const int a = pr[0] + offset[static_cast<std::size_t>(s.panel_a)],
                b = pr[1] + offset[static_cast<std::size_t>(s.panel_b)];
      if (a == b) continue;
      pairs.push_back({a, b});
      out.seam_offset_cm.push_back(pair_offset_cm(pat, s, ra, rb, pr));
      ++count;
    }
    out.seam_pair_count.push_back(count);
  }
  out.mesh.seam_pairs.resize(2, static_cast<Eigen::Index>(pairs.size()));
  for (std::size_t i = 0; i < pairs.size(); ++i)
    out.mesh.seam_pairs.col(static_cast<Eigen::Index>(i)) << pairs[i][0], pairs[i][1];
  out.mesh.validate("pattern " + pat.name);
  return out;
}

MeshedPattern mesh_pattern(const Pattern& pat, const MeshingOptions& o) {
  if (o.spacing_cm > 0) return mesh_pattern(pat, o.spacing_cm, o.attach);
  if (o.target_vertices < 8)
    throw std::invalid_argument("pattern " + pat.name + ": need a spacing or >= 8 target vertices");
  // area / spacing^2 ~ vertices: start there, then search the spacing on a log scale
  // (each panel's area counts positive, whichever way its outline turns)
  double area = 0;
  for (const auto& p : pat.panels) area += 0.5 * std::abs(twice_signed_area(p.outline));
  const double h0 = std::sqrt(area / o.target_vertices);
  MeshedPattern best;
  double best_err = 1e300;
  // nearest spacings first: 0, +1, -1, +2, ... steps of 1 %
  for (int i = 0; i <= 80; ++i) {
    const int k = i % 2 ? (i + 1) / 2 : -i / 2;
    const double h = h0 * std::pow(1.01, k);
    MeshedPattern m = mesh_pattern(pat, h, o.attach);
    const double err = std::abs(m.mesh.vertex_count() - o.target_vertices);
    if (err < best_err) best_err = err, best = std::move(m);
    if (err <= 0.01 * o.target_vertices) break;
  }
  return best;
}

ClothMesh place_garment(const MeshedPattern& meshed, const Pattern& pat, const BodyFrame& body) {
  const Box3 box = bounding_box(body.positions);
  ClothMesh c = meshed.mesh;
  for (int v = 0; v < c.vertex_count(); ++v) {
    const Placement& pl = pat.panels[static_cast<std::size_t>(c.panel[static_cast<std::size_t>(v)])].placement;
    const double u = meshed.uv(0, v), w = meshed.uv(1, v), r = pl.wrap_radius_cm;
    Vec3 local = r > 0 ? Vec3(static_cast<Real>(r * std::sin(u / r)), static_cast<Real>(w),
                              static_cast<Real>(r * std::cos(u / r) - r))
                       : Vec3(static_cast<Real>(u), static_cast<Real>(w), 0);
    const Vec3 anchor = box.min + pl.anchor.cwiseProduct(box.size());
    c.positions.col(v) = anchor + (placement_rotation(pl) * local + pl.offset_cm) / 100.f;
  }
  c.validate("garment " + pat.name);
  return c;
}

ClothMesh build_garment(const Pattern& pat, const MeshingOptions& o, const BodyFrame& body) {
  return place_garment(mesh_pattern(pat, o), pat, body);
}

}  // namespace clothbench
