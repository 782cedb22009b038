// mesh_pattern and place_garment: a pattern's panels gridded (panel_grid.cpp), its seams aligned and paired
// (seam_alignment.cpp), the panels placed around the body; outline geometry and validation: pattern_geometry.cpp.
#include "clothbench/sim/garment.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <stdexcept>
#include <utility>

#include "garment_internal.hpp"

namespace clothbench {

namespace {

using namespace garment_detail;

Eigen::Matrix3f placement_rotation(const Placement& pl) {
  const float d2r = static_cast<float>(M_PI / 180.0);
  return (Eigen::AngleAxisf(pl.yaw_deg * d2r, Vec3::UnitY()) * Eigen::AngleAxisf(pl.roll_deg * d2r, Vec3::UnitZ()) *
          Eigen::AngleAxisf(pl.pitch_deg * d2r, Vec3::UnitX()))
      .toRotationMatrix();
}

// Seam pairs, and the vertices of sewn edges left without a partner, in the garment's vertex indices.
void pair_seams(const Pattern& pat, const std::vector<PanelGrid>& grids, const std::vector<int>& offset,
                MeshedPattern& out) {
  std::vector<std::array<int, 2>> pairs;
  std::vector<LooseVertex> loose;
  for (const auto& s : pat.seams) {
    const auto pa = static_cast<std::size_t>(s.panel_a), pb = static_cast<std::size_t>(s.panel_b);
    const auto& ra = grids[pa].edge_vertices[static_cast<std::size_t>(s.edge_a)];
    const auto& rb = grids[pb].edge_vertices[static_cast<std::size_t>(s.edge_b)];
    std::set<int> paired_a, paired_b;
    int count = 0;
    for (const auto& pr : match_runs(ra, rb, s.reversed)) {
      paired_a.insert(pr[0]), paired_b.insert(pr[1]);
      const int a = pr[0] + offset[pa], b = pr[1] + offset[pb];
      if (a == b) continue;  // a vertex never pairs with itself (the shared tip of a dart)
      pairs.push_back({a, b});
      out.seam_offset_cm.push_back(pair_offset_cm(pat, s, ra, rb, pr));
      ++count;
    }
    out.seam_pair_count.push_back(count);
    const std::size_t before = loose.size();
    const auto add = [&](const LooseVertex& l, int own, int other) {
      const LooseVertex g{l.v + own, l.b0 + other, l.b1 + other};
      if (g.v != g.b0 && g.v != g.b1) loose.push_back(g);  // a dart's tip is on both of its edges
    };
    for (auto l : loose_vertices(ra, run_to_corners(pat.panels[pb], s.edge_b, grids[pb]), s.reversed, paired_a))
      add(l, offset[pa], offset[pb]);
    for (auto l : loose_vertices(rb, run_to_corners(pat.panels[pa], s.edge_a, grids[pa]), s.reversed, paired_b))
      add(l, offset[pb], offset[pa]);
    out.seam_loose_count.push_back(static_cast<int>(loose.size() - before));
  }
  out.mesh.seam_pairs.resize(2, static_cast<Eigen::Index>(pairs.size()));
  for (std::size_t i = 0; i < pairs.size(); ++i)
    out.mesh.seam_pairs.col(static_cast<Eigen::Index>(i)) << pairs[i][0], pairs[i][1];
  out.mesh.seam_loose.resize(3, static_cast<Eigen::Index>(loose.size()));
  for (std::size_t i = 0; i < loose.size(); ++i)
    out.mesh.seam_loose.col(static_cast<Eigen::Index>(i)) << loose[i].v, loose[i].b0, loose[i].b1;
}

}  // namespace

MeshedPattern mesh_pattern(const Pattern& pat, double h, bool attach, bool on_grid, bool smooth) {
  validate_pattern(pat);
  if (!(h > 0)) throw std::invalid_argument("pattern " + pat.name + ": grid spacing must be > 0");
  if (smooth && !on_grid)
    throw std::invalid_argument("pattern " + pat.name + ": smoothing (Durupinar's step 7) needs the outline drawn on "
                                "the grid (garment.on_grid, --on-grid): the ring mesher's outline is smooth already");
  MeshedPattern out;
  out.spacing_cm = h;
  std::vector<PanelGrid> grids;
  std::vector<Panel> drawn(on_grid ? pat.panels.size() : 0);  // on the grid: each panel's outline as drawn there
  for (std::size_t pi = 0; pi < pat.panels.size(); ++pi)
    grids.push_back(on_grid ? grid_panel_on_grid(pat.panels[pi], h, smooth, drawn[pi]) : grid_panel(pat.panels[pi], h));
  // on the grid the vertices stay on their nodes; smoothed, they have left them, and the seams' runs are aligned as
  // the ring's are (a sleeve cap's and an armhole's staircases differ in count: a vertex left without a partner
  // stands off the seam); then no structural spring is left under half a spacing where a vertex can move
  if (!on_grid || smooth) {
    align_seam_vertices(pat, h, grids);
    clear_slivers(pat, h, grids, smooth);
  }
  std::vector<int> offset;
  for (std::size_t pi = 0; pi < grids.size(); ++pi) {
    const Panel& p = pat.panels[pi];
    offset.push_back(out.mesh.vertex_count());
    out.mesh.append(panel_mesh(on_grid ? drawn[pi] : p, grids[pi], h));
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
  pair_seams(pat, grids, offset, out);
  out.mesh.validate("pattern " + pat.name);
  return out;
}

MeshedPattern mesh_pattern(const Pattern& pat, const MeshingOptions& o) {
  if (o.spacing_cm > 0) return mesh_pattern(pat, o.spacing_cm, o.attach, o.on_grid, o.smooth);
  if (o.target_vertices < 8)
    throw std::invalid_argument("pattern " + pat.name + ": need a spacing or >= 8 target vertices");
  // area / spacing^2 ~ vertices: start there (each panel's area counts positive, whichever way its outline
  // turns), rescale the spacing by sqrt(count / target) while that closes in, then search steps of 1 % around
  // the best spacing, nearest first, until a count lies within 1 % of the target or counts on both sides of it
  // are seen (the count falls as the spacing grows: farther steps only go farther off)
  double area = 0;
  for (const auto& p : pat.panels) area += 0.5 * std::abs(twice_signed_area(p.outline));
  MeshedPattern best;
  double best_err = 1e300, best_h = std::sqrt(area / o.target_vertices);
  const auto close_enough = [&](double err) { return err <= 0.01 * o.target_vertices; };
  const auto mesh_at = [&](double h) {
    MeshedPattern m = mesh_pattern(pat, h, o.attach, o.on_grid, o.smooth);
    const int n = m.mesh.vertex_count();
    const double err = std::abs(n - o.target_vertices);
    if (err < best_err) best_err = err, best_h = h, best = std::move(m);
    return n;
  };
  for (int i = 0, n = mesh_at(best_h); i < 6 && !close_enough(best_err); ++i) {
    const double h = best_h * std::sqrt(double(n) / o.target_vertices);
    const double before = best_err;
    n = mesh_at(h);
    if (!(best_err < before)) break;
  }
  // a count at or above the target seen, one at or below
  bool over = best.mesh.vertex_count() >= o.target_vertices, under = best.mesh.vertex_count() <= o.target_vertices;
  const double h0 = best_h;
  for (int i = 1; i <= 40 && !close_enough(best_err) && !(over && under); ++i) {
    const int k = i % 2 ? (i + 1) / 2 : -i / 2;
    const int n = mesh_at(h0 * std::pow(1.01, k));
    over = over || n >= o.target_vertices, under = under || n <= o.target_vertices;
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

std::string edge_name(const Panel& panel, int e) {
  const auto i = static_cast<std::size_t>(e);
  return i < panel.edge_names.size() && !panel.edge_names[i].empty() ? panel.edge_names[i] : "e" + std::to_string(e);
}

std::string edge_label(const Pattern& pattern, int panel, int edge) {
  const Panel& p = pattern.panels[static_cast<std::size_t>(panel)];
  return p.name + "." + edge_name(p, edge);
}

std::vector<std::string> seam_length_warnings(const Pattern& pattern, double tolerance) {
  std::vector<std::string> out;
  for (const Seam& s : pattern.seams) {
    const double a = edge_length_cm(pattern.panels[static_cast<std::size_t>(s.panel_a)], s.edge_a);
    const double b = edge_length_cm(pattern.panels[static_cast<std::size_t>(s.panel_b)], s.edge_b);
    if (!(std::abs(a - b) > tolerance * std::max(a, b))) continue;
    char line[256];
    std::snprintf(line, sizeof line, "seam %s (%.1f cm) <-> %s (%.1f cm): the edges differ by %.0f %% of the longer",
                  edge_label(pattern, s.panel_a, s.edge_a).c_str(), a, edge_label(pattern, s.panel_b, s.edge_b).c_str(),
                  b, 100 * std::abs(a - b) / std::max(a, b));
    out.push_back(line);
  }
  return out;
}

ClothMesh build_garment(const Pattern& pat, const MeshingOptions& o, const BodyFrame& body) {
  return place_garment(mesh_pattern(pat, o), pat, body);
}

Slivers slivers(const MeshedPattern& m) {
  Slivers out;
  const ClothMesh& c = m.mesh;
  for (Eigen::Index s = 0; s < c.springs.cols(); ++s) {
    if (c.kind[static_cast<std::size_t>(s)] != SpringKind::kStructural) continue;
    if (!(100 * double(c.rest_length[s]) < (0.5 - 1e-4) * m.spacing_cm)) continue;  // float rest lengths
    const bool both =
        m.boundary[static_cast<std::size_t>(c.springs(0, s))] && m.boundary[static_cast<std::size_t>(c.springs(1, s))];
    ++(both ? out.along : out.inward);
  }
  return out;
}

}  // namespace clothbench
