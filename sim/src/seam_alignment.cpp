// Seam alignment of garment meshing: sewn edges get their boundary vertices at matching arc fractions,
// seam ends snapped onto corners, and the runs of two edges paired (Durupinar section 2).
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <utility>

#include "garment_internal.hpp"

namespace clothbench {

namespace {

using namespace garment_detail;

// Outline indices [s0, s1) of the segments of edge e.
std::pair<int, int> edge_segments(const Panel& p, int e) {
  const int n = static_cast<int>(p.outline.size());
  return {p.edge_begin[static_cast<std::size_t>(e)],
          e + 1 < p.edge_count() ? p.edge_begin[static_cast<std::size_t>(e + 1)] : n};
}

Vec2d outline_point(const Panel& p, int s) { return p.outline[static_cast<std::size_t>(s) % p.outline.size()]; }

// The point at arc fraction t (0..1) of edge e of panel p.
Vec2d point_on_edge(const Panel& p, int e, double t) {
  const auto [s0, s1] = edge_segments(p, e);
  double left = t * edge_length_cm(p, e);
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

// The panel's vertex at pattern point p (-1 when none sits there).
int vertex_at(const PanelGrid& g, const Vec2d& p) {
  const auto v = std::find_if(g.uv.begin(), g.uv.end(), [&](const Vec2d& q) { return (q - p).norm() < 1e-9; });
  return v == g.uv.end() ? -1 : static_cast<int>(v - g.uv.begin());
}

bool occupied(const PanelGrid& g, const Vec2d& p) { return vertex_at(g, p) >= 0; }

// Whether an edge run holds vertex v.
bool holds(const std::vector<std::pair<double, int>>& run, int v) {
  return std::any_of(run.begin(), run.end(), [&](const auto& tv) { return tv.second == v; });
}

// Whether vertex v lies on more than one edge of the panel (a corner, or where edges touch).
bool on_several_edges(const PanelGrid& g, int v) {
  int runs = 0;
  for (const auto& run : g.edge_vertices) runs += holds(run, v);
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
    const bool a_near = std::abs(va.first - ta) * edge_length_cm(pa, s.edge_a) < h && !on_several_edges(ga, va.second);
    const bool b_near = std::abs(vb.first - tb) * edge_length_cm(pb, s.edge_b) < h && !on_several_edges(gb, vb.second);
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
    if (holds(run, j.vertex)) continue;
    run.insert(j.t > 0.5 ? run.end() : run.begin(), {j.t, j.vertex});
  }
}

// Edge e's run with the vertices that bound it on the outline: the panel's vertex on a corner of the edge, or
// else the nearest vertex of the edge meeting it there that is not on the run, at fraction 0 or 1.
std::vector<std::pair<double, int>> bracketing_run(const Panel& p, int e, const PanelGrid& g) {
  auto run = run_to_corners(p, e, g);
  for (const double t : {0.0, 1.0}) {
    const int next = edge_at_corner(p, e, t);
    if (run.empty() || std::abs((t > 0.5 ? run.back() : run.front()).first - t) < 1e-9 || next < 0) continue;
    auto nr = g.edge_vertices[static_cast<std::size_t>(next)];  // from the corner away
    if (t < 0.5) std::reverse(nr.begin(), nr.end());
    const auto v = std::find_if(nr.begin(), nr.end(), [&](const auto& q) { return !holds(run, q.second); });
    if (v != nr.end()) run.insert(t > 0.5 ? run.end() : run.begin(), {t, v->second});
  }
  return run;
}

// Where the two runs of a seam differ in count, the shorter gets a new vertex at the arc fraction of each
// vertex of the longer that the matching of the two leaves without a partner, between its neighbours on the
// shorter edge (a vertex without a partner stands off the seam: sewing pulls pairs). An edge an earlier seam
// placed keeps its vertices.
void even_out_runs(const Pattern& pat, const Seam& s, std::vector<PanelGrid>& grids,
                   const std::set<std::pair<int, int>>& locked) {
  const auto& ra = grids[static_cast<std::size_t>(s.panel_a)].edge_vertices[static_cast<std::size_t>(s.edge_a)];
  const auto& rb = grids[static_cast<std::size_t>(s.panel_b)].edge_vertices[static_cast<std::size_t>(s.edge_b)];
  if (ra.size() == rb.size() || ra.empty() || rb.empty()) return;
  const bool a_short = ra.size() < rb.size();
  const int panel = a_short ? s.panel_a : s.panel_b, edge = a_short ? s.edge_a : s.edge_b;
  if (locked.count({panel, edge}) > 0) return;
  const auto longer = a_short ? rb : ra;
  PanelGrid& g = grids[static_cast<std::size_t>(panel)];
  const Panel& p = pat.panels[static_cast<std::size_t>(panel)];
  auto& shorter = g.edge_vertices[static_cast<std::size_t>(edge)];
  const auto matched = seam_anchors(shorter, longer, s.reversed);  // keyed by the longer run's index
  for (std::size_t j = 0; j < longer.size(); ++j) {
    if (matched.count(static_cast<int>(j)) > 0) continue;
    const double t = s.reversed ? 1 - longer[j].first : longer[j].first;
    const auto run = bracketing_run(p, edge, g);
    const auto k = std::lower_bound(run.begin(), run.end(), t, [](const auto& q, double y) { return q.first < y; });
    if (k == run.end() || (k == run.begin() && k->first > t + 1e-9)) continue;  // beyond the outline's neighbours
    const Vec2d point = point_on_edge(p, edge, t);
    auto lo = k == run.begin() ? k : std::prev(k), hi = k == run.begin() ? std::next(k) : k;
    if (std::abs(k->first - t) < 1e-9) {
      if (holds(shorter, k->second)) continue;  // a vertex of the run is there already
      if (vertex_at(g, point) == k->second) {   // the panel's corner vertex joins the run
        shorter.insert(
            std::lower_bound(shorter.begin(), shorter.end(), t, [](const auto& q, double y) { return q.first < y; }),
            *k);
        continue;
      }
    }
    if (hi == run.end()) continue;
    const int x = split_boundary_edge(g, lo->second, hi->second, point);
    shorter.insert(
        std::upper_bound(shorter.begin(), shorter.end(), t, [](double y, const auto& q) { return y < q.first; }),
        {t, x});
  }
}

// Moves the vertices of an edge run to the pattern points of their arc fractions.
void place_run(const Panel& p, int edge, PanelGrid& g) {
  for (const auto& [t, v] : g.edge_vertices[static_cast<std::size_t>(edge)])
    g.uv[static_cast<std::size_t>(v)] = point_on_edge(p, edge, t);
}

// Whether two neighbours of an edge run lie closer than half a spacing h along the edge.
bool crowded(const Panel& p, int e, const std::vector<std::pair<double, int>>& run, double h) {
  const double len = edge_length_cm(p, e);
  for (std::size_t k = 1; k < run.size(); ++k)
    if ((run[k].first - run[k - 1].first) * len < 0.5 * h) return true;
  return false;
}

// An edge no seam placed whose run is crowded (ring vertices snapped to nearby points of a slanted or curved
// edge, or a seam's end moved onto the corner beside one) is spread evenly along the edge, corners kept: the
// spring between two such neighbours would otherwise be a sliver, where a millimetre of error is a large strain.
// A vertex a seam moved onto the edge's corner joins the run first (it lies on this edge too).
void spread_crowded_runs(const Pattern& pat, double h, std::vector<PanelGrid>& grids,
                         const std::set<std::pair<int, int>>& placed) {
  for (std::size_t pi = 0; pi < grids.size(); ++pi) {
    const Panel& p = pat.panels[pi];
    for (int e = 0; e < p.edge_count(); ++e) {
      auto& run = grids[pi].edge_vertices[static_cast<std::size_t>(e)];
      if (placed.count({static_cast<int>(pi), e}) > 0 || run.empty()) continue;
      for (const double t : {0.0, 1.0}) {
        const int v = vertex_at(grids[pi], point_on_edge(p, e, t));
        if (v >= 0 && !holds(run, v)) run.insert(t > 0.5 ? run.end() : run.begin(), {t, v});
      }
      if (!crowded(p, e, run, h)) continue;
      respace_run(run, {});
      place_run(p, e, grids[pi]);
    }
  }
}

// How many seams sew edge e of panel pi.
long seams_sewing(const Pattern& pat, int pi, int e) {
  return std::count_if(pat.seams.begin(), pat.seams.end(), [&](const Seam& s) {
    return (s.panel_a == pi && s.edge_a == e) || (s.panel_b == pi && s.edge_b == e);
  });
}

// Whether two neighbours of a run stand closer than half a spacing h, where they are.
bool crowded_in_place(const PanelGrid& g, const std::vector<std::pair<double, int>>& run, double h) {
  for (std::size_t k = 1; k < run.size(); ++k)
    if ((g.uv[static_cast<std::size_t>(run[k].second)] - g.uv[static_cast<std::size_t>(run[k - 1].second)]).norm() <
        0.5 * h)
      return true;
  return false;
}

// Each vertex of `run` takes its fraction in `from` (the run respaced with the vertices that bound it).
void take_fractions(std::vector<std::pair<double, int>>& run, const std::vector<std::pair<double, int>>& from) {
  for (auto& tv : run)
    for (const auto& [t, v] : from)
      if (v == tv.second) tv.first = t;
}

// A seam whose edge, with the vertices on its corners, is crowded (a later seam's end moved onto a corner beside this
// edge's free end, half a step from it) spreads both its runs evenly between their corner vertices; where that is
// still crowded, the free ends go onto their free corners. Only where the two runs match vertex for vertex, corners
// included: both then spread alike and their pairs still join the same pattern points.
void spread_crowded_seam(const Pattern& pat, const Seam& s, double h, std::vector<PanelGrid>& grids) {
  const auto panel = [&](int k) -> const Panel& {
    return pat.panels[static_cast<std::size_t>(k ? s.panel_b : s.panel_a)];
  };
  const auto grid = [&](int k) -> PanelGrid& { return grids[static_cast<std::size_t>(k ? s.panel_b : s.panel_a)]; };
  const auto edge = [&](int k) { return k ? s.edge_b : s.edge_a; };
  const auto run = [&](int k) -> auto& { return grid(k).edge_vertices[static_cast<std::size_t>(edge(k))]; };
  if (&run(0) == &run(1) || run(0).empty() || run(0).size() != run(1).size()) return;
  // an edge of several seams stays as they placed it
  if (seams_sewing(pat, s.panel_a, s.edge_a) != 1 || seams_sewing(pat, s.panel_b, s.edge_b) != 1) return;
  std::array<std::vector<std::pair<double, int>>, 2> f{run_to_corners(panel(0), edge(0), grid(0)),
                                                       run_to_corners(panel(1), edge(1), grid(1))};
  const auto is_crowded = [&](int k) { return crowded(panel(k), edge(k), f[static_cast<std::size_t>(k)], h); };
  if (f[0].size() != f[1].size() || !(is_crowded(0) || is_crowded(1))) return;
  // end `end` (0 front, 1 back) of side k's full run: side 1's ends are side 0's, swapped on a reversed seam
  const auto end_of = [&](int k, int end) -> auto& {
    auto& r = f[static_cast<std::size_t>(k)];
    return (k && s.reversed ? 1 - end : end) ? r.back() : r.front();
  };
  const auto corner_of = [&](int k, int end) { return (k && s.reversed ? 1 - end : end) ? 1.0 : 0.0; };
  for (int end : {0, 1})
    if (is_corner(end_of(0, end).first) != is_corner(end_of(1, end).first)) return;
  for (auto& r : f) respace_run(r, {});
  if (is_crowded(0) || is_crowded(1)) {  // still: the free ends go onto their corners where both are free
    for (int end : {0, 1}) {
      const auto free_corner = [&](int k) {
        return !is_corner(end_of(k, end).first) &&
               !occupied(grid(k), point_on_edge(panel(k), edge(k), corner_of(k, end)));
      };
      if (free_corner(0) && free_corner(1))
        for (int k : {0, 1}) end_of(k, end).first = corner_of(k, end);
    }
    for (auto& r : f) respace_run(r, {});
  }
  for (int k : {0, 1}) {
    take_fractions(run(k), f[static_cast<std::size_t>(k)]);
    place_run(panel(k), edge(k), grid(k));
  }
}

// How far vertex v of edge e of panel pi, were it at fraction t, would sit from its seam partners along the seam [cm]
// (0 on an edge no seam sews).
double offset_from_partner(const Pattern& pat, const std::vector<PanelGrid>& grids, int pi, int e, int v, double t) {
  double most = 0;
  for (const auto& s : pat.seams) {
    const bool on_a = s.panel_a == pi && s.edge_a == e, on_b = s.panel_b == pi && s.edge_b == e;
    if (!on_a && !on_b) continue;
    const auto& own = grids[static_cast<std::size_t>(pi)].edge_vertices[static_cast<std::size_t>(e)];
    const int other_panel = on_a ? s.panel_b : s.panel_a, other_edge = on_a ? s.edge_b : s.edge_a;
    const auto& other =
        grids[static_cast<std::size_t>(other_panel)].edge_vertices[static_cast<std::size_t>(other_edge)];
    for (const auto& pr : match_runs(on_a ? own : other, on_a ? other : own, s.reversed)) {
      if (pr[on_a ? 0 : 1] != v) continue;
      const int u = pr[on_a ? 1 : 0];
      for (const auto& [tu, w] : other)
        if (w == u)
          most = std::max(most, std::abs(t - (s.reversed ? 1 - tu : tu)) *
                                    edge_length_cm(pat.panels[static_cast<std::size_t>(pi)], e));
    }
  }
  return most;
}

}  // namespace

double edge_length_cm(const Panel& p, int e) {
  const auto [s0, s1] = edge_segments(p, e);
  double len = 0;
  for (int s = s0; s < s1; ++s) len += (outline_point(p, s + 1) - outline_point(p, s)).norm();
  return len;
}

namespace garment_detail {

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
    even_out_runs(pat, s, grids, done);
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
  spread_crowded_runs(pat, h, grids, done);
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

std::vector<std::pair<double, int>> run_to_corners(const Panel& p, int e, const PanelGrid& g) {
  auto run = g.edge_vertices[static_cast<std::size_t>(e)];
  if (run.empty()) return run;
  const auto corner = [&](double t) { return vertex_at(g, point_on_edge(p, e, t)); };  // -1: none on the corner
  if (!is_corner(run.front().first))
    if (const int c = corner(0); c >= 0) run.insert(run.begin(), {0.0, c});
  if (!is_corner(run.back().first))
    if (const int c = corner(1); c >= 0) run.push_back({1.0, c});
  return run;
}

std::vector<LooseVertex> loose_vertices(const std::vector<std::pair<double, int>>& run,
                                        const std::vector<std::pair<double, int>>& partner, bool reversed,
                                        const std::set<int>& paired) {
  std::vector<LooseVertex> out;
  if (partner.empty()) return out;
  const std::size_t n = partner.size();
  for (const auto& [t, v] : run) {
    if (paired.count(v)) continue;
    const double tp = reversed ? 1 - t : t;
    // partner[j - 1] and partner[j] bracket tp (runs ascend in arc fraction)
    const auto j = static_cast<std::size_t>(
        std::upper_bound(partner.begin(), partner.end(), tp, [](double x, const auto& q) { return x < q.first; }) -
        partner.begin());
    out.push_back({v, partner[j == 0 ? 0 : j - 1].second, partner[j == n ? n - 1 : j].second});
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
  const double la = edge_length_cm(pat.panels[static_cast<std::size_t>(s.panel_a)], s.edge_a);
  const double lb = edge_length_cm(pat.panels[static_cast<std::size_t>(s.panel_b)], s.edge_b);
  return std::abs(ta - (s.reversed ? 1 - tb : tb)) * 0.5 * (la + lb);
}

void clear_slivers(const Pattern& pat, double h, std::vector<PanelGrid>& grids, bool spread_every_open_edge) {
  for (const auto& s : pat.seams) spread_crowded_seam(pat, s, h, grids);
  for (std::size_t pi = 0; pi < grids.size(); ++pi) {
    const Panel& p = pat.panels[pi];
    PanelGrid& g = grids[pi];
    const auto at = [&](int v) -> Vec2d& { return g.uv[static_cast<std::size_t>(v)]; };
    for (int e = 0; e < p.edge_count(); ++e) {
      auto& run = g.edge_vertices[static_cast<std::size_t>(e)];
      const bool sewn = seams_sewing(pat, static_cast<int>(pi), e) > 0;
      // an edge no seam placed spreads between the vertices that bound it on the outline, whichever edge holds them
      if (!sewn && !run.empty()) {
        if (auto spread = bracketing_run(p, e, g); spread_every_open_edge || crowded_in_place(g, spread, h)) {
          respace_run(spread, {});
          take_fractions(run, spread);
          place_run(p, e, g);
        }
      }
      auto full = run_to_corners(p, e, g);
      for (std::size_t k = 1; k + 1 < full.size(); ++k) {
        const int v = full[k].second;
        const Vec2d& a = at(full[k - 1].second);
        const Vec2d& c = at(full[k + 1].second);
        if (!((at(v) - a).norm() < 0.5 * h || (c - at(v)).norm() < 0.5 * h) || on_several_edges(g, v)) continue;
        const double t = 0.5 * (full[k - 1].first + full[k + 1].first);
        const Vec2d q = point_on_edge(p, e, t);
        if ((q - a).norm() < 0.5 * h || (c - q).norm() < 0.5 * h) continue;
        // a sewn vertex stays within a quarter spacing of its partner along the seam, or no farther than it was
        const auto offset = [&](double at_t) {
          return offset_from_partner(pat, grids, static_cast<int>(pi), e, v, at_t);
        };
        if (sewn && offset(t) > std::max(0.25 * h, offset(full[k].first))) continue;
        at(v) = q;
        full[k].first = t;
        for (auto& tv : run)
          if (tv.second == v) tv.first = t;
      }
    }
    // an inside vertex moved clear may come near the next one in, which then moves on along their spring: a few
    // rounds
    bool moved = true;
    for (int round = 0; moved && round < 8; ++round) {
      moved = false;
      for (std::size_t s = 0; s < g.springs.size(); ++s) {
        const auto [a, b] = g.springs[s];
        const Vec2d d = at(b) - at(a);
        if (g.kinds[s] != SpringKind::kStructural || !(d.norm() < 0.5 * h)) continue;
        const bool outline_a = g.boundary[static_cast<std::size_t>(a)],
                   outline_b = g.boundary[static_cast<std::size_t>(b)];
        if (outline_a && outline_b) continue;
        Vec2d to;
        int v;
        if (outline_a != outline_b) {
          v = outline_a ? b : a;
          to = inside_by_half(p.outline, at(v), h);
        } else {  // the one farther from the outline gives way
          const bool b_deeper = closest_on_outline(p.outline, at(b)).dist >= closest_on_outline(p.outline, at(a)).dist;
          v = b_deeper ? b : a;
          const Vec2d from = at(b_deeper ? a : b);
          to = d.norm() > 0 ? Vec2d(from + 0.5 * h * (at(v) - from) / (at(v) - from).norm()) : at(v);
        }
        moved = moved || to != at(v);
        at(v) = to;
      }
    }
  }
}

}  // namespace garment_detail

}  // namespace clothbench
