#include "clothbench/sim/garment.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <stdexcept>
#include <utility>

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

bool segments_cross(const Vec2d& a, const Vec2d& b, const Vec2d& c, const Vec2d& d) {
  const double d1 = cross(b - a, c - a), d2 = cross(b - a, d - a);
  const double d3 = cross(d - c, a - c), d4 = cross(d - c, b - c);
  return ((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0)) && d1 != 0 && d2 != 0 && d3 != 0 && d4 != 0;
}


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

// One meshed panel: vertices (uv), which are on the outline, and per edge the boundary vertices
// ordered by their arc-length position along the edge.
struct PanelGrid {
  std::vector<Vec2d> uv;
  std::vector<std::uint8_t> boundary;
  std::vector<std::vector<std::pair<double, int>>> edge_vertices;  // (arc position, local vertex)
  ClothMesh mesh;
};

PanelGrid grid_panel(const Panel& p, double h) {
  PanelGrid g;
  g.edge_vertices.resize(static_cast<std::size_t>(p.edge_count()));
  Vec2d lo = p.outline[0], hi = p.outline[0];
  for (const auto& q : p.outline) lo = lo.cwiseMin(q), hi = hi.cwiseMax(q);
  const int nx = static_cast<int>(std::ceil((hi.x() - lo.x()) / h)) + 3;
  const int ny = static_cast<int>(std::ceil((hi.y() - lo.y()) / h)) + 3;
  // the grid is centred on the outline's box, so mirrored panels get mirrored vertices and their
  // seams pair vertex for vertex
  const Vec2d origin = 0.5 * (lo + hi) - 0.5 * h * Vec2d(nx - 1, ny - 1);
  auto node = [&](int i, int j) -> Vec2d { return origin + h * Vec2d(i, j); };
  std::vector<int> in(static_cast<std::size_t>(nx * ny), 0);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) in[static_cast<std::size_t>(j * nx + i)] = inside(p.outline, node(i, j)) ? 1 : 0;
  std::vector<int> id(static_cast<std::size_t>(nx * ny), -1);
  // inside nodes farther than h/4 from the outline are kept as they are
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const Vec2d q = node(i, j);
      if (in[static_cast<std::size_t>(j * nx + i)] && closest_on_outline(p.outline, q).dist > 0.25 * h) {
        id[static_cast<std::size_t>(j * nx + i)] = static_cast<int>(g.uv.size());
        g.uv.push_back(q);
        g.boundary.push_back(0);
      }
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
  // springs and quads between kept grid neighbours, rest lengths from the pattern
  std::vector<std::array<int, 2>> ends;
  std::vector<Real> rest;
  auto at = [&](int i, int j) { return (i < 0 || j < 0 || i >= nx || j >= ny) ? -1 : id[static_cast<std::size_t>(j * nx + i)]; };
  auto add = [&](int a, int b, SpringKind kind) {
    if (a < 0 || b < 0) return;
    const double l = (g.uv[static_cast<std::size_t>(a)] - g.uv[static_cast<std::size_t>(b)]).norm() / 100.0;
    if (l < 1e-6) return;
    ends.push_back({a, b});
    rest.push_back(static_cast<Real>(l));
    g.mesh.kind.push_back(kind);
  };
  std::vector<std::array<int, 4>> quads;
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
      if (at(i + 1, j) >= 0 && at(i + 1, j + 1) >= 0 && at(i, j + 1) >= 0)
        quads.push_back({a, at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  const auto nv = static_cast<Eigen::Index>(g.uv.size());
  ClothMesh& m = g.mesh;
  m.positions.resize(3, nv);
  m.vertex_area = Scalars::Zero(nv);
  for (Eigen::Index v = 0; v < nv; ++v)
    m.positions.col(v) = Vec3(static_cast<Real>(g.uv[static_cast<std::size_t>(v)].x() / 100),
                              static_cast<Real>(g.uv[static_cast<std::size_t>(v)].y() / 100), 0);
  m.springs.resize(2, static_cast<Eigen::Index>(ends.size()));
  m.rest_length.resize(static_cast<Eigen::Index>(ends.size()));
  for (std::size_t s = 0; s < ends.size(); ++s) {
    m.springs.col(static_cast<Eigen::Index>(s)) << ends[s][0], ends[s][1];
    m.rest_length[static_cast<Eigen::Index>(s)] = rest[s];
  }
  m.quads.resize(4, static_cast<Eigen::Index>(quads.size()));
  for (std::size_t q = 0; q < quads.size(); ++q) {
    const auto& c = quads[q];
    m.quads.col(static_cast<Eigen::Index>(q)) << c[0], c[1], c[2], c[3];
    // a vertex carries a quarter of each adjacent cell's area (shoelace, m^2)
    double area = 0;
    for (int k = 0; k < 4; ++k)
      area += cross(g.uv[static_cast<std::size_t>(c[static_cast<std::size_t>(k)])],
                    g.uv[static_cast<std::size_t>(c[static_cast<std::size_t>((k + 1) % 4)])]);
    for (int k = 0; k < 4; ++k) m.vertex_area[c[static_cast<std::size_t>(k)]] += static_cast<Real>(std::abs(area) / 8e4);
  }
  const Real floor_area = static_cast<Real>(0.05 * h * h / 1e4);  // vertices touching no full cell
  for (Eigen::Index v = 0; v < nv; ++v) m.vertex_area[v] = std::max(m.vertex_area[v], floor_area);
  m.panel.assign(static_cast<std::size_t>(nv), 0);
  m.panel_names = {p.name};
  m.seam_pairs.resize(2, 0);
  return g;
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

Eigen::Matrix3f placement_rotation(const Placement& pl) {
  const float d2r = static_cast<float>(M_PI / 180.0);
  return (Eigen::AngleAxisf(pl.yaw_deg * d2r, Vec3::UnitY()) * Eigen::AngleAxisf(pl.roll_deg * d2r, Vec3::UnitZ()) *
          Eigen::AngleAxisf(pl.pitch_deg * d2r, Vec3::UnitX()))
      .toRotationMatrix();
}

}  // namespace

bool outline_self_intersects(const std::vector<Vec2d>& o) {
  const std::size_t n = o.size();
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;
      if (segments_cross(o[i], o[(i + 1) % n], o[j], o[(j + 1) % n])) return true;
    }
  return false;
}

double distance_to_outline(const std::vector<Vec2d>& outline, const Vec2d& p) {
  return closest_on_outline(outline, p).dist;
}

std::vector<Vec2d> flatten_bezier(const Vec2d& a, const std::vector<Vec2d>& c, const Vec2d& b, int segments) {
  std::vector<Vec2d> out;
  for (int s = 1; s <= segments; ++s) {
    const double t = double(s) / segments, u = 1 - t;
    if (c.size() == 1) out.push_back(u * u * a + 2 * u * t * c[0] + t * t * b);
    else if (c.size() == 2) out.push_back(u * u * u * a + 3 * u * u * t * c[0] + 3 * u * t * t * c[1] + t * t * t * b);
    else out.push_back(u * a + t * b);
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
      if (p.edge_begin[e] <= p.edge_begin[e - 1] || p.edge_begin[e] >= n) fail("panel '" + p.name + "': bad edge start");
    if (outline_self_intersects(p.outline)) fail("panel '" + p.name + "' outline intersects itself");
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
  std::vector<int> offset;
  for (const auto& p : pat.panels) {
    grids.push_back(grid_panel(p, h));
    offset.push_back(out.mesh.vertex_count());
    out.mesh.append(grids.back().mesh);
    for (const auto& q : grids.back().uv) {
      out.uv.conservativeResize(2, out.uv.cols() + 1);
      out.uv.col(out.uv.cols() - 1) = q;
    }
    out.boundary.insert(out.boundary.end(), grids.back().boundary.begin(), grids.back().boundary.end());
    if (attach)
      for (int e : p.attached_edges)
        for (const auto& [s, v] : grids.back().edge_vertices[static_cast<std::size_t>(e)])
          out.mesh.attached.push_back(v + offset.back());
  }
  std::vector<std::array<int, 2>> pairs;
  for (const auto& s : pat.seams) {
    const auto m = match_runs(grids[static_cast<std::size_t>(s.panel_a)].edge_vertices[static_cast<std::size_t>(s.edge_a)],
                              grids[static_cast<std::size_t>(s.panel_b)].edge_vertices[static_cast<std::size_t>(s.edge_b)],
                              s.reversed);
    // a vertex never pairs with itself (the shared tip of a dart)
    int count = 0;
    for (const auto& pr : m) {
      const int a = pr[0] + offset[static_cast<std::size_t>(s.panel_a)], b = pr[1] + offset[static_cast<std::size_t>(s.panel_b)];
      if (a == b) continue;
      pairs.push_back({a, b});
      ++count;
    }
    out.seam_pair_count.push_back(count);
  }
  out.mesh.seam_pairs.resize(2, static_cast<Eigen::Index>(pairs.size()));
  for (std::size_t i = 0; i < pairs.size(); ++i) out.mesh.seam_pairs.col(static_cast<Eigen::Index>(i)) << pairs[i][0], pairs[i][1];
  out.mesh.validate("pattern " + pat.name);
  return out;
}

MeshedPattern mesh_pattern(const Pattern& pat, const MeshingOptions& o) {
  if (o.spacing_cm > 0) return mesh_pattern(pat, o.spacing_cm, o.attach);
  if (o.target_vertices < 8) throw std::invalid_argument("pattern " + pat.name + ": need a spacing or >= 8 target vertices");
  // area / spacing^2 ~ vertices: start there, then search the spacing on a log scale
  // (each panel's area counts positive, whichever way its outline turns)
  double area = 0;
  for (const auto& p : pat.panels) {
    double a = 0;
    for (std::size_t i = 0; i < p.outline.size(); ++i) a += 0.5 * cross(p.outline[i], p.outline[(i + 1) % p.outline.size()]);
    area += std::abs(a);
  }
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
    Vec3 local = r > 0 ? Vec3(static_cast<Real>(r * std::sin(u / r)), static_cast<Real>(w), static_cast<Real>(r * std::cos(u / r) - r))
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
