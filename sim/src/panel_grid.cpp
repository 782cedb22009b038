// The panel grid of garment meshing (dressing section 3): grid nodes inside each panel's outline, the ring
// around them snapped onto it, springs, quads, and the panel's cloth.
#include <algorithm>
#include <cmath>
#include <utility>

#include "garment_internal.hpp"

namespace clothbench {

namespace {

using namespace garment_detail;

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

// The panel's grid: nodes origin + h (i, j), 0 <= i < nx, 0 <= j < ny, a node's index j nx + i.
struct GridFrame {
  Vec2d origin;
  double h = 0;
  int nx = 0, ny = 0;
  Vec2d node(int i, int j) const { return origin + h * Vec2d(i, j); }
};

// The grid over the outline's box and a node beyond it on every side, centred on the box, so mirrored panels get
// mirrored vertices.
GridFrame grid_frame(const Panel& p, double h) {
  Vec2d lo = p.outline[0], hi = p.outline[0];
  for (const auto& q : p.outline) lo = lo.cwiseMin(q), hi = hi.cwiseMax(q);
  // grid cells across the box; a spacing that divides it exactly counts exactly, not one more for
  // the rounding of the division (that would shift the centred grid by h/2 off the outline)
  auto cells = [&](double extent) { return static_cast<int>(std::ceil(extent / h - kOnOutline)); };
  GridFrame f;
  f.h = h;
  f.nx = cells(hi.x() - lo.x()) + 3;
  f.ny = cells(hi.y() - lo.y()) + 3;
  f.origin = 0.5 * (lo + hi) - 0.5 * h * Vec2d(f.nx - 1, f.ny - 1);
  return f;
}

// Grid nodes inside the outline, and the ring around them snapped onto the outline.
void place_grid_vertices(const Panel& p, const GridFrame& f, PanelGrid& g, std::vector<int>& id) {
  const double h = f.h;
  const int nx = f.nx, ny = f.ny;
  auto node = [&](int i, int j) { return f.node(i, j); };
  id.assign(static_cast<std::size_t>(nx * ny), -1);
  // inside nodes farther than h/4 from the outline are kept (those nearer than h/2 moved to h/2 where they can
  // be: clear_of_outline); nodes on the outline (within rounding: a spacing that divides a straight edge's
  // position) are kept too, as boundary vertices, whatever the inside test says there. The ring below would
  // miss such a node at a corner: its 4-neighbours lie on the outline too, none of them an inside node
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const Vec2d q = node(i, j);
      const Closest c = closest_on_outline(p.outline, q);
      const bool on = c.dist <= kOnOutline * h;
      if (!on && !(c.dist > 0.25 * h && inside(p.outline, q))) continue;
      id[static_cast<std::size_t>(j * nx + i)] = static_cast<int>(g.uv.size());
      g.uv.push_back(on ? c.point : clear_of_outline(p.outline, q, c, h));
      g.boundary.push_back(on ? 1 : 0);
      if (on) add_to_edges(p, c.point, id[static_cast<std::size_t>(j * nx + i)], g.edge_vertices);
    }
  // the ring around them is snapped onto the outline (Durupinar's boundary set, made smooth)
  auto near_kept = [&](const Vec2d& q) {
    for (const auto& u : g.uv)
      if ((u - q).norm() < 0.3 * h) return true;
    return false;
  };
  // the ring, in two passes over the nodes as the loop above left them (so that a panel and its mirror image get the
  // same ring: read while it is filled, the ring grew along the scan, one node farther out along an edge the rows
  // climb, leaving no cell between it and the kept nodes): first the nodes next to a kept node, then the nodes next
  // to those that are a kept node's diagonal neighbour (the outside corners of a cell the outline cuts near a corner)
  const auto snap = [&](std::size_t k, int i, int j) {
    const Closest c = closest_on_outline(p.outline, node(i, j));
    if (near_kept(c.point)) return;
    id[k] = static_cast<int>(g.uv.size());
    g.uv.push_back(c.point);
    g.boundary.push_back(1);
    add_to_edges(p, c.point, id[k], g.edge_vertices);
  };
  const auto nx_ = static_cast<std::size_t>(nx);
  const auto any_of = [&](const std::vector<int>& ids, std::size_t k, std::initializer_list<std::ptrdiff_t> steps) {
    for (const auto d : steps)
      if (ids[static_cast<std::size_t>(static_cast<std::ptrdiff_t>(k) + d)] >= 0) return true;
    return false;
  };
  const auto row = static_cast<std::ptrdiff_t>(nx_);
  const std::vector<int> kept = id;
  std::vector<int> first(id.size(), -1);
  for (int j = 1; j + 1 < ny; ++j)
    for (int i = 1; i + 1 < nx; ++i) {
      const auto k = static_cast<std::size_t>(j) * nx_ + static_cast<std::size_t>(i);
      if (kept[k] < 0 && any_of(kept, k, {-1, 1, -row, row})) first[k] = 1, snap(k, i, j);
    }
  for (int j = 1; j + 1 < ny; ++j)
    for (int i = 1; i + 1 < nx; ++i) {
      const auto k = static_cast<std::size_t>(j) * nx_ + static_cast<std::size_t>(i);
      if (kept[k] < 0 && first[k] < 0 && any_of(first, k, {-1, 1, -row, row}) &&
          any_of(kept, k, {-row - 1, -row + 1, row - 1, row + 1}))
        snap(k, i, j);
    }
  for (auto& ev : g.edge_vertices) std::sort(ev.begin(), ev.end());
}

// The cell's middle lies outside the outline (beyond rounding): its corners on the outline span a hollow of it.
bool spans_a_hollow(const Panel& p, const PanelGrid& g, const std::array<int, 4>& c, double h) {
  Vec2d mid = Vec2d::Zero();
  for (const int v : c) mid += 0.25 * g.uv[static_cast<std::size_t>(v)];
  return !inside(p.outline, mid) && closest_on_outline(p.outline, mid).dist > kOnOutline * h;
}

}  // namespace

namespace garment_detail {

// Where an inside node nearer the outline than half a spacing sits: moved straight away from the outline to half a
// spacing from it, where that takes it farther from the outline (a strip narrower than a spacing keeps it). The
// ring vertex snapped onto the outline beside it is then joined to it by a spring of at least half a spacing; a
// shorter one (a sliver) takes a millimetre of error as a large strain.
Vec2d clear_of_outline(const std::vector<Vec2d>& outline, const Vec2d& q, const Closest& c, double h) {
  if (!(c.dist < 0.5 * h)) return q;
  // moved off one segment it may come nearer another (a polygon's corner): moved again off that one
  Vec2d moved = q;
  Closest at = c;
  for (int k = 0; k < 4 && at.dist > 0 && at.dist < (0.5 - 1e-6) * h; ++k) {
    moved = at.point + 0.5 * h / at.dist * (moved - at.point);
    at = closest_on_outline(outline, moved);
  }
  return at.dist > c.dist && inside(outline, moved) ? moved : q;  // `at` is where `moved` is
}

Vec2d inside_by_half(const std::vector<Vec2d>& outline, const Vec2d& q, double h) {
  const Closest c = closest_on_outline(outline, q);
  if (inside(outline, q) || !(c.dist > 0)) return clear_of_outline(outline, q, c, h);
  return c.point + 0.5 * h / c.dist * (c.point - q);
}

namespace {

// Springs and cells between the kept grid nodes `id` (-1: not kept) of panel p.
void connect_grid(const Panel& p, const GridFrame& f, const std::vector<int>& id, PanelGrid& g) {
  const int nx = f.nx, ny = f.ny;
  const double h = f.h;
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
  // leave a staircase of holes along the outline, in the pictures, the face queries and the masses.
  // A cell whose corners all lie on the outline and whose middle lies outside it spans a hollow of the
  // outline (a neckline's dip): it is no cloth, and its midpoint, queried with face queries, would sit in the body
  for (int j = 0; j + 1 < ny; ++j)
    for (int i = 0; i + 1 < nx; ++i) {
      std::array<int, 4> c{at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)};
      const auto kept = std::remove(c.begin(), c.end(), -1);
      if (kept - c.begin() == 3) c[3] = c[2];
      if (kept - c.begin() >= 3 && !spans_a_hollow(p, g, c, h)) g.quads.push_back(c);
    }
}

// The grid node a pattern point is drawn on: the nearest row, and of the two nearest columns the one farther from the
// grid's middle, so that a panel drawn on the grid is no narrower anywhere than its pattern (a waistband rounded in
// would not close round the waist)
std::array<int, 2> drawn_node(const GridFrame& f, const Vec2d& q) {
  const Vec2d at = (q - f.origin) / f.h;
  const double middle = 0.5 * (f.nx - 1),
               column = at.x() > middle ? std::ceil(at.x() - 1e-9) : std::floor(at.x() + 1e-9);
  return {static_cast<int>(column), static_cast<int>(std::lround(at.y()))};
}

// Bresenham's line from node a to node b (8-connected), b included, a not. It is drawn upwards (rightwards when
// level) from whichever end is lower and with the steps' sizes alone (their signs applied after), so that a line
// and its mirror image, and the same line drawn either way, take the same nodes: a seam's two mirrored edges then
// lie on matching staircases, their pairs a spacing apart along both
std::vector<std::array<int, 2>> bresenham(const std::array<int, 2>& a, const std::array<int, 2>& b) {
  const bool down = b[1] < a[1] || (b[1] == a[1] && b[0] < a[0]);
  const std::array<int, 2> from = down ? b : a, to = down ? a : b;
  const int dx = std::abs(to[0] - from[0]), dy = to[1] - from[1], sx = to[0] < from[0] ? -1 : 1;
  std::vector<std::array<int, 2>> path{from};
  int x = 0, y = 0, err = dx - dy;
  while (x != dx || y != dy) {
    const int e2 = 2 * err;
    if (e2 > -dy) err -= dy, ++x;
    if (e2 < dx) err += dx, ++y;
    path.push_back({from[0] + sx * x, from[1] + y});
  }
  if (down) std::reverse(path.begin(), path.end());
  return {path.begin() + 1, path.end()};
}

}  // namespace

PanelGrid grid_panel(const Panel& p, double h) {
  PanelGrid g;
  g.edge_vertices.resize(static_cast<std::size_t>(p.edge_count()));
  std::vector<int> id;
  const GridFrame f = grid_frame(p, h);
  place_grid_vertices(p, f, g, id);
  connect_grid(p, f, id, g);
  return g;
}

namespace {

// Durupinar's steps 1-4: the outline's points on grid nodes (drawn_node), joined by Bresenham lines, their nodes
// kept (`id`) as boundary vertices; each edge's nodes, in order, make its run, at the arc fractions of the staircase
// drawn for it (a seam's mirrored edges, drawn alike, then pair node for node). `staircase` gets the outline drawn.
void draw_outline(const Panel& p, const GridFrame& f, PanelGrid& g, std::vector<int>& id, Panel& staircase) {
  staircase = p;
  staircase.outline.clear();
  staircase.edge_begin.clear();
  const int n = static_cast<int>(p.outline.size());
  const auto vertex = [&](const std::array<int, 2>& node) {
    const auto k = static_cast<std::size_t>(node[1] * f.nx + node[0]);
    if (id[k] < 0) {
      id[k] = static_cast<int>(g.uv.size());
      g.uv.push_back(f.node(node[0], node[1]));
      g.boundary.push_back(1);
    }
    return id[k];
  };
  std::array<int, 2> at = drawn_node(f, p.outline[0]);
  for (int e = 0; e < p.edge_count(); ++e) {
    const int s0 = p.edge_begin[static_cast<std::size_t>(e)];
    const int s1 = e + 1 < p.edge_count() ? p.edge_begin[static_cast<std::size_t>(e + 1)] : n;
    std::vector<std::array<int, 2>> drawn{at};
    for (int s = s0; s < s1; ++s)
      for (const auto& node : bresenham(drawn.back(), drawn_node(f, p.outline[static_cast<std::size_t>((s + 1) % n)])))
        drawn.push_back(node);
    at = drawn.back();
    std::vector<double> arc{0};
    for (std::size_t k = 1; k < drawn.size(); ++k)
      arc.push_back(arc.back() + std::hypot(drawn[k][0] - drawn[k - 1][0], drawn[k][1] - drawn[k - 1][1]));
    auto& run = g.edge_vertices[static_cast<std::size_t>(e)];
    for (std::size_t k = 0; k < drawn.size(); ++k) {
      const int v = vertex(drawn[k]);
      if (std::none_of(run.begin(), run.end(), [&](const auto& tv) { return tv.second == v; }))
        run.push_back({arc.back() > 0 ? arc[k] / arc.back() : 0.0, v});
    }
    std::sort(run.begin(), run.end());
    staircase.edge_begin.push_back(static_cast<int>(staircase.outline.size()));
    for (std::size_t k = 0; k + 1 < drawn.size(); ++k) staircase.outline.push_back(f.node(drawn[k][0], drawn[k][1]));
  }
}

// Durupinar's steps 5-6: the nodes the outside reaches 4-neighbour from the grid's corner (the grid has a column and
// a row clear of the outline all round) without crossing the lines are outside; every other node is kept, inside (a
// 4-neighbour fill cannot pass between two diagonal neighbours of a line)
void fill_inside(const GridFrame& f, PanelGrid& g, std::vector<int>& id) {
  const auto index = [&](int i, int j) { return static_cast<std::size_t>(j * f.nx + i); };
  std::vector<std::uint8_t> outside(id.size(), 0);
  std::vector<std::array<int, 2>> stack{{0, 0}};
  outside[0] = 1;
  while (!stack.empty()) {
    const auto [i, j] = stack.back();
    stack.pop_back();
    for (const auto& [di, dj] : {std::array<int, 2>{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
      const int u = i + di, w = j + dj;
      if (u < 0 || w < 0 || u >= f.nx || w >= f.ny || outside[index(u, w)] || id[index(u, w)] >= 0) continue;
      outside[index(u, w)] = 1;
      stack.push_back({u, w});
    }
  }
  for (int j = 0; j < f.ny; ++j)
    for (int i = 0; i < f.nx; ++i) {
      if (outside[index(i, j)] || id[index(i, j)] >= 0) continue;
      id[index(i, j)] = static_cast<int>(g.uv.size());
      g.uv.push_back(f.node(i, j));
      g.boundary.push_back(0);
    }
}

// Durupinar's step 7, the jagged outline made smooth (she fits Bezier curves to it; here the drafted outline itself
// is the smooth curve): each outline vertex moves to its closest point on the outline, and a vertex within the
// staircase but outside the outline, or inside it nearer than half a spacing, to half a spacing inside it
// (inside_by_half). Where a move would make a structural spring shorter than half a spacing (a sliver, which takes a
// millimetre of error as a large strain) or turn a cell over, its vertices go three quarters, a half or a quarter of
// the way, or stay. Every vertex is judged against its neighbours' moves of the same round, so mirrored panels move
// alike.
void smooth_outline(const Panel& p, double h, PanelGrid& g) {
  const std::size_t n = g.uv.size();
  std::vector<Vec2d> from = g.uv, to = g.uv;
  std::vector<double> share(n, 1);
  for (std::size_t v = 0; v < n; ++v)
    to[v] = g.boundary[v] ? closest_on_outline(p.outline, from[v]).point : inside_by_half(p.outline, from[v], h);
  const auto at = [&](int v) {
    const auto k = static_cast<std::size_t>(v);
    return from[k] + share[k] * (to[k] - from[k]);
  };
  for (bool cut = true; cut;) {
    cut = false;
    std::vector<std::uint8_t> short_of(n, 0);
    for (std::size_t s = 0; s < g.springs.size(); ++s) {
      const auto [a, b] = g.springs[s];
      if (g.kinds[s] == SpringKind::kStructural && (at(a) - at(b)).norm() < 0.5 * h * (1 + 1e-9))
        short_of[static_cast<std::size_t>(a)] = short_of[static_cast<std::size_t>(b)] = 1;
    }
    for (const auto& q : g.quads) {
      std::vector<Vec2d> before(4), after(4);
      for (std::size_t k = 0; k < 4; ++k)
        before[k] = from[static_cast<std::size_t>(q[k])], after[k] = at(q[k]);
      if (twice_signed_area(before) * twice_signed_area(after) > 0) continue;
      for (const int v : q) short_of[static_cast<std::size_t>(v)] = 1;
    }
    for (std::size_t v = 0; v < n; ++v)
      if (short_of[v] && share[v] > 0) share[v] = std::max(0.0, share[v] - 0.25), cut = true;
  }
  for (std::size_t v = 0; v < n; ++v) g.uv[v] = at(static_cast<int>(v));
}

}  // namespace

PanelGrid grid_panel_on_grid(const Panel& p, double h, bool smooth, Panel& drawn) {
  const GridFrame f = grid_frame(p, h);
  PanelGrid g;
  g.edge_vertices.resize(static_cast<std::size_t>(p.edge_count()));
  std::vector<int> id(static_cast<std::size_t>(f.nx * f.ny), -1);
  draw_outline(p, f, g, id, drawn);
  fill_inside(f, g, id);
  connect_grid(drawn, f, id, g);
  if (!smooth) return g;
  smooth_outline(p, h, g);
  drawn = p;
  return g;
}

namespace {

void add_spring(PanelGrid& g, int a, int b, SpringKind kind) {
  g.springs.push_back({a, b});
  g.kinds.push_back(kind);
}

// The cell with u and w as neighbouring corners, and where u or w stands in it (-1 when none has them).
std::pair<int, std::size_t> cell_joining(const PanelGrid& g, int u, int w) {
  for (std::size_t c = 0; c < g.quads.size(); ++c) {
    const auto& q = g.quads[c];
    const std::size_t corners = q[3] == q[2] ? 3 : 4;
    for (std::size_t i = 0; i < corners; ++i) {
      const int a = q[i], b = q[(i + 1) % corners];
      if ((a == u && b == w) || (a == w && b == u)) return {static_cast<int>(c), i};
    }
  }
  return {-1, 0};
}

}  // namespace

int split_boundary_edge(PanelGrid& g, int u, int w, const Vec2d& at) {
  const int x = static_cast<int>(g.uv.size());
  g.uv.push_back(at);
  g.boundary.push_back(1);
  const auto [c, i] = cell_joining(g, u, w);
  if (c < 0) {
    // no cell joins them (a strap one cell wide, a corner cut off): the triangle u x w of the outline,
    // turning the way the grid's cells do
    const Vec2d pu = g.uv[static_cast<std::size_t>(u)], pw = g.uv[static_cast<std::size_t>(w)];
    const bool ccw = cross(at - pu, pw - pu) > 0;
    g.quads.push_back(ccw ? std::array<int, 4>{u, x, w, w} : std::array<int, 4>{w, x, u, u});
    add_spring(g, u, x, SpringKind::kStructural);
    add_spring(g, x, w, SpringKind::kStructural);
    return x;
  }
  const std::array<int, 4> q = g.quads[static_cast<std::size_t>(c)];
  const std::size_t corners = q[3] == q[2] ? 3 : 4;
  std::array<int, 4> ring{};  // the cell's corners from the second of the pair round to the first
  for (std::size_t k = 0; k < corners; ++k) ring[k] = q[(i + 1 + k) % corners];
  // the polygon a x b c (d) becomes the triangle a x (d or c) and the cell x b c (d)
  const int a = q[i], before_a = ring[corners - 2];
  g.quads[static_cast<std::size_t>(c)] = {x, ring[0], ring[1], corners == 4 ? ring[2] : ring[1]};
  g.quads.push_back({a, x, before_a, before_a});
  const auto s = std::find_if(g.springs.begin(), g.springs.end(), [&](const std::array<int, 2>& e) {
    return (e[0] == u && e[1] == w) || (e[0] == w && e[1] == u);
  });
  if (s != g.springs.end()) {
    const SpringKind kind = g.kinds[static_cast<std::size_t>(s - g.springs.begin())];
    *s = {u, x};
    add_spring(g, x, w, kind);
  } else {
    add_spring(g, u, x, SpringKind::kStructural);
    add_spring(g, x, w, SpringKind::kStructural);
  }
  for (std::size_t k = 1; k + 1 < corners; ++k) add_spring(g, x, ring[k], SpringKind::kShear);
  return x;
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
  // a cell whose outline corners moved along the outline (seams aligned, a crowded run spread) may span a
  // hollow now: it is left out as grid_panel leaves out those that did from the start
  std::vector<std::array<int, 4>> cells;
  for (const auto& c : g.quads)
    if (!spans_a_hollow(p, g, c, h)) cells.push_back(c);
  m.quads.resize(4, static_cast<Eigen::Index>(cells.size()));
  m.vertex_area = Scalars::Zero(nv);
  for (std::size_t q = 0; q < cells.size(); ++q) {
    const auto& c = cells[q];
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

}  // namespace garment_detail

}  // namespace clothbench
