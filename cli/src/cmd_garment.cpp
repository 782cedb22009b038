// clothbench garment: what a pattern file meshes into (counts, sizes, seams), as text, JSON or PNG; with --on BODY,
// how it is placed on that body before sewing (inside, crossings, touching, attached far), and a picture of it there
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "clothbench/bench/oracle.hpp"
#include "clothbench/io/body_loader.hpp"
#include "clothbench/io/errors.hpp"
#include "clothbench/io/pattern_file.hpp"
#include "clothbench/io/pattern_loader.hpp"
#include "clothbench/render/pattern_picture.hpp"
#include "clothbench/render/picture.hpp"
#include "commands.hpp"

namespace clothbench::cli {

namespace {

struct GarmentOptions {
  std::string file;
  int vertices = 0;         // target vertex count; 0 = use the spacing
  double spacing_cm = 2.0;  // grid spacing when no target is given [cm]
  bool on_grid = false;     // Durupinar's construction (MeshingOptions::on_grid)
  bool smooth = false;      // and its step 7 (MeshingOptions::smooth)
  bool json = false;
  std::string png;
  std::string on;  // a body file: place the garment on its rest pose and report the placement
};

// Where a placed garment starts, against the exact body: what the run's sewing begins from.
struct Placement {
  Accuracy accuracy;      // inside, depth, crossings of the structural springs
  long touching = 0;      // vertices outside the body within kTouching of it
  long attached = 0;      // attached vertices
  long attached_far = 0;  // of those, farther than kAttachedFar from the body
  double attached_farthest_mm = 0;
};
constexpr Real kTouching = 0.005f;    // [m]: within the accuracy limit's depth of the surface
constexpr Real kAttachedFar = 0.01f;  // [m]: as the runner's warning: a waistband rests within millimetres

Placement measure_placement(const BodyFrame& body, const ClothMesh& cloth) {
  const Oracle oracle(body);
  std::vector<Real> d;
  oracle.signed_distance(PointsView(cloth.positions), d);
  Placement p;
  p.accuracy = Oracle::penetration(d);
  oracle.measure_crossings(PointsView(cloth.positions), structural_springs(cloth), p.accuracy);
  for (Real x : d) p.touching += x >= 0 && x < kTouching;
  for (int v : cloth.attached) {
    const Real x = d[static_cast<std::size_t>(v)];
    ++p.attached;
    p.attached_far += x > kAttachedFar;
    p.attached_farthest_mm = std::max(p.attached_farthest_mm, 1e3 * double(x));
  }
  return p;
}

nlohmann::json to_json(const Placement& p, const std::string& body) {
  return {{"body", body},
          {"inside", p.accuracy.inside},
          {"inside_pct", p.accuracy.inside_pct},
          {"depth_max_mm", p.accuracy.depth_max_mm},
          {"crossings", p.accuracy.crossings},
          {"crossings_pct", p.accuracy.crossings_pct},
          {"touching", p.touching},
          {"touching_mm", 1e3 * double(kTouching)},
          {"attached", p.attached},
          {"attached_far", p.attached_far},
          {"attached_far_mm", 1e3 * double(kAttachedFar)},
          {"attached_farthest_mm", p.attached_farthest_mm}};
}

void print_placement(const Placement& p, const std::string& body) {
  const Accuracy& a = p.accuracy;
  std::printf("  placed on      %s (rest pose), against the exact body:\n", body.c_str());
  std::printf("    inside       %zu of %zu vertices (%.2f %%), the deepest %.1f mm\n", a.inside, a.points, a.inside_pct,
              a.depth_max_mm);
  std::printf("    crossings    %zu of %zu structural springs (%.2f %%)\n", a.crossings, a.segments, a.crossings_pct);
  std::printf("    touching     %ld vertices outside within %.0f mm of the body\n", p.touching,
              1e3 * double(kTouching));
  std::printf("    attached     %ld vertices, %ld of them farther than %.0f mm from the body (the farthest %.1f mm)\n",
              p.attached, p.attached_far, 1e3 * double(kAttachedFar), p.attached_farthest_mm);
  if (a.inside_pct > 1.0)
    std::fprintf(stderr,
                 "clothbench garment: warning: %.1f %% of the vertices start inside the body: sewing starts from a "
                 "tangle (move the pattern's panels out, or check the body's size and facing)\n",
                 a.inside_pct);
}

// front, side and back of the placed garment on the body
void draw_placement(const BodyFrame& body, const ClothMesh& cloth, const std::string& png) {
  const std::unique_ptr<PictureRenderer> pictures = make_picture_renderer();
  std::vector<Image> views;
  for (View v : {View::kFront, View::kSide, View::kBack}) views.push_back(pictures->render(body, cloth, 480, v));
  side_by_side(views).write_png(png);
  std::printf("  picture %s (the placement: front, side, back) drawn by %s\n", png.c_str(), pictures->name().c_str());
}

// One panel's summary: its vertices and its outline's extent and area.
struct PanelInfo {
  std::string name;
  int vertices = 0, edges = 0;
  Vec2d lo, hi;
  double area_cm2 = 0;
};

std::vector<PanelInfo> panel_infos(const Pattern& pat, const MeshedPattern& m) {
  std::vector<PanelInfo> out;
  for (const auto& p : pat.panels) {
    PanelInfo info;
    info.name = p.name;
    info.edges = p.edge_count();
    info.lo = info.hi = p.outline[0];
    // shoelace area and bounding box of the outline
    for (std::size_t i = 0; i < p.outline.size(); ++i) {
      const Vec2d a = p.outline[i], b = p.outline[(i + 1) % p.outline.size()];
      info.lo = info.lo.cwiseMin(a);
      info.hi = info.hi.cwiseMax(a);
      info.area_cm2 += 0.5 * (a.x() * b.y() - a.y() * b.x());
    }
    info.area_cm2 = std::abs(info.area_cm2);
    out.push_back(info);
  }
  for (int panel : m.mesh.panel) ++out[static_cast<std::size_t>(panel)].vertices;
  return out;
}

// per seam: the largest distance along the seam between the pattern positions of two partners [cm]
std::vector<double> seam_offsets(const MeshedPattern& m) {
  std::vector<double> out;
  std::size_t pair = 0;
  for (int n : m.seam_pair_count) {
    double worst = 0;
    for (int k = 0; k < n; ++k, ++pair) worst = std::max(worst, m.seam_offset_cm[pair]);
    out.push_back(worst);
  }
  return out;
}

// per seam: its two edges as the file names them
std::vector<std::string> seam_edges(const Pattern& pat) {
  std::vector<std::string> out;
  for (const Seam& s : pat.seams)
    out.push_back(edge_label(pat, s.panel_a, s.edge_a) + " <-> " + edge_label(pat, s.panel_b, s.edge_b));
  return out;
}

nlohmann::json to_json(const GarmentOptions& o, const Pattern& pat, const MeshedPattern& m,
                       const std::vector<PanelInfo>& infos) {
  const Slivers short_ones = slivers(m);
  nlohmann::json panels = nlohmann::json::array();
  for (const auto& p : infos)
    panels.push_back({{"name", p.name},
                      {"vertices", p.vertices},
                      {"edges", p.edges},
                      {"width_cm", p.hi.x() - p.lo.x()},
                      {"height_cm", p.hi.y() - p.lo.y()},
                      {"area_cm2", p.area_cm2}});
  return {{"file", o.file},
          {"garment", pat.name},
          {"spacing_cm", m.spacing_cm},
          {"panels", static_cast<int>(pat.panels.size())},
          {"panel_details", panels},
          {"vertices", m.mesh.vertex_count()},
          {"springs",
           {{"structural", m.mesh.count(SpringKind::kStructural)},
            {"shear", m.mesh.count(SpringKind::kShear)},
            {"flexion", m.mesh.count(SpringKind::kFlexion)}}},
          {"shortest_structural_cm", 100 * double(m.mesh.shortest(SpringKind::kStructural))},
          {"structural_under_half_spacing", {{"along_outline", short_ones.along}, {"inward", short_ones.inward}}},
          {"seams", static_cast<int>(pat.seams.size())},
          {"seam_pairs", static_cast<int>(m.mesh.seam_pairs.cols())},
          {"seam_offset_max_cm", seam_offsets(m)},
          {"seam_unpaired", m.seam_loose_count},
          {"seam_edges", seam_edges(pat)},
          {"seam_warnings", seam_length_warnings(pat)},
          {"quads", static_cast<int>(m.mesh.quads.cols())},
          {"attached", static_cast<int>(m.mesh.attached.size())}};
}

void print_text(const GarmentOptions& o, const Pattern& pat, const MeshedPattern& m,
                const std::vector<PanelInfo>& infos) {
  std::printf("garment %s (%s)\n", pat.name.c_str(), o.file.c_str());
  std::printf("  grid spacing   %.3f cm\n", m.spacing_cm);
  std::printf("  panels         %zu\n", pat.panels.size());
  for (const auto& p : infos)
    std::printf("    %-16s %6d vertices  %6.1f x %6.1f cm  %8.1f cm^2  %d edges\n", p.name.c_str(), p.vertices,
                p.hi.x() - p.lo.x(), p.hi.y() - p.lo.y(), p.area_cm2, p.edges);
  std::printf("  vertices       %d\n", m.mesh.vertex_count());
  std::printf("  springs        %d structural, %d shear, %d flexion\n", m.mesh.count(SpringKind::kStructural),
              m.mesh.count(SpringKind::kShear), m.mesh.count(SpringKind::kFlexion));
  const double shortest_cm = 100 * double(m.mesh.shortest(SpringKind::kStructural));
  std::printf("  shortest structural spring %.2f cm (%.2f of the spacing)\n", shortest_cm, shortest_cm / m.spacing_cm);
  const Slivers short_ones = slivers(m);
  std::printf("  structural springs under half the spacing: %d (%d between two outline vertices, %d from the outline "
              "inward)\n",
              short_ones.total(), short_ones.along, short_ones.inward);
  const auto& q = m.mesh.quads;
  const auto triangles = static_cast<int>((q.row(3).array() == q.row(2).array()).count());
  std::printf("  quads          %d (%d of them triangles, on the outline)\n", static_cast<int>(q.cols()), triangles);
  std::printf("  seams          %zu, %d seam pairs\n", pat.seams.size(), static_cast<int>(m.mesh.seam_pairs.cols()));
  const auto offsets = seam_offsets(m);
  for (std::size_t s = 0; s < pat.seams.size(); ++s) {
    const Seam& seam = pat.seams[s];
    const Panel& a = pat.panels[static_cast<std::size_t>(seam.panel_a)];
    const Panel& b = pat.panels[static_cast<std::size_t>(seam.panel_b)];
    std::printf("    %s (%.1f cm) <-> %s (%.1f cm)  %s, %d pairs, %d without a partner, partners up to %.2f cm apart "
                "along the seam\n",
                edge_label(pat, seam.panel_a, seam.edge_a).c_str(), edge_length_cm(a, seam.edge_a),
                edge_label(pat, seam.panel_b, seam.edge_b).c_str(), edge_length_cm(b, seam.edge_b),
                seam.reversed ? "reversed" : "aligned", m.seam_pair_count[s], m.seam_loose_count[s], offsets[s]);
  }
  for (const std::string& w : seam_length_warnings(pat)) std::fprintf(stderr, "clothbench garment: warning: %s\n", w.c_str());
  std::printf("  attached       %zu vertices\n", m.mesh.attached.size());
}

int run_garment(const GarmentOptions& o) {
  if (o.vertices < 0) throw InputError("--vertices must be > 0");
  if (o.vertices == 0 && !(o.spacing_cm > 0)) throw InputError("--spacing must be > 0 cm");
  const Pattern pat = load_pattern(o.file);
  MeshingOptions mo;
  mo.on_grid = o.on_grid;
  mo.smooth = o.smooth;
  if (o.vertices > 0)
    mo.target_vertices = o.vertices;
  else
    mo.spacing_cm = o.spacing_cm;
  MeshedPattern m;
  try {
    m = mesh_pattern(pat, mo);
  } catch (const std::invalid_argument& e) {
    throw InputError(located(o.file, 0, e.what()));
  }
  const auto infos = panel_infos(pat, m);
  if (o.on.empty()) {
    if (o.json)
      std::cout << to_json(o, pat, m, infos).dump(2) << "\n";
    else
      print_text(o, pat, m, infos);
    if (!o.png.empty()) draw_pattern(pat, m).write_png(o.png);
    return 0;
  }
  const BodyFrame body = load_body(o.on).rest();
  ClothMesh cloth;
  try {
    cloth = place_garment(m, pat, body);
  } catch (const std::invalid_argument& e) {
    throw InputError(located(o.file, 0, e.what()));
  }
  const Placement p = measure_placement(body, cloth);
  if (o.json) {
    nlohmann::json j = to_json(o, pat, m, infos);
    j["placement"] = to_json(p, o.on);
    std::cout << j.dump(2) << "\n";
  } else {
    print_text(o, pat, m, infos);
    print_placement(p, o.on);
  }
  if (!o.png.empty()) draw_placement(body, cloth, o.png);
  return 0;
}

}  // namespace

void add_garment_command(CLI::App& app, Action& action) {
  auto opts = std::make_shared<GarmentOptions>();
  auto* cmd =
      app.add_subcommand("garment", "Mesh a pattern file (.pattern or GarmentCode .json) and print what it holds");
  cmd->add_option("file", opts->file, "Pattern file")->required();
  cmd->add_option("--vertices", opts->vertices, "Target vertex count of the whole garment (within a few per cent)");
  cmd->add_option("--spacing", opts->spacing_cm, "Grid spacing [cm], used when --vertices is not given")
      ->capture_default_str();
  cmd->add_flag("--on-grid", opts->on_grid,
                "Durupinar's construction: the outline drawn on the grid (Bresenham lines, a 4-neighbour fill), every "
                "vertex a grid node");
  cmd->add_flag("--smooth", opts->smooth,
                "With --on-grid: Durupinar's step 7, the outline's vertices moved onto the outline, the seams' vertices "
                "aligned and every structural spring kept at least half a spacing long");
  cmd->add_flag("--json", opts->json, "Print JSON (keys panels, vertices, springs, seams, seam_pairs, quads)");
  cmd->add_option("--png", opts->png,
                  "Draw the meshed panels and seams into this PNG file (with --on: the garment placed on the body)");
  cmd->add_option("--on", opts->on,
                  "A body file (any format `clothbench body` reads, or debian:human, data:REL): place the garment on "
                  "its rest pose as a run "
                  "would, and report how it starts (vertices inside, springs crossing, touching, attached far)");
  cmd->callback([opts, &action] { action = [opts] { return run_garment(*opts); }; });
}

}  // namespace clothbench::cli
