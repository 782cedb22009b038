// made-to-measure: garments drafted from each body's own measurements (Durupinar section 2) in sizes S to XL, sewn
// and draped on the body they were drafted from: whether they dress it within every limit, and how loose they sit.
#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "clothbench/bench/oracle.hpp"
#include "clothbench/bench/report.hpp"
#include "clothbench/experiments/experiment.hpp"
#include "clothbench/sim/body_measure.hpp"
#include "clothbench/sim/garment_draft.hpp"
#include "experiment_list.hpp"

namespace clothbench {

namespace {

struct Body {
  const char* label;
  const char* file;
  const char* scale;  // body.scale, or "" for the body as it is
};
// the bodies this project ships, each in its rest pose: two MakeHuman shapes (the walking body and a taller one), a
// broader body from another source, and a slimmer one made by scaling
const Body kBodies[] = {
    {"Debian's human", "debian:human", ""},
    {"walking body (MakeHuman)", "data:body/mh_female_walk.glb", ""},
    {"tall MakeHuman body", "data:body/mh_female_tall.obj", ""},
    {"GarmentCode's mean female", "data:garments/garmentcode/mean_female.obj", ""},
    {"walking body, 0.9 across", "data:body/mh_female_walk.glb", "[0.9, 1, 0.9]"},
};
// the landmarks the fit is measured at
const char* const kLandmarks[] = {"bust girth", "waist girth", "hip girth"};
// a landmark's first word: "hip" for "hip girth"
std::string landmark_word(const char* landmark) {
  const std::string l(landmark);
  return l.substr(0, l.find(' '));
}
// a garment type: the dressing scene it is run in (scenes/dressing), its vertex count (the scene's; the shirt's raised
// to the skirt's, with sleeves to the dress's), and the landmark where its size's ease tells, at which the fit is
// judged (the shirt ends above the hip)
struct Type {
  const char* name;
  const char* scene;
  int vertices;
  int judged_at;  // index into kLandmarks
};
const Type kTypes[] = {{"skirt", "skirt", 600, 2},
                       {"shirt", "shirt", 600, 0},
                       {"shirt_sleeves", "shirt", 800, 0},
                       {"dress", "dress", 800, 2},
                       {"trousers", "trousers", 800, 2}};

// how far the cloth sits off the body round one landmark, as a tape round the garment there would show it: the
// points where the cloth's structural springs cross the landmark's height, their mean and largest distance outside
// the body [mm] (points inside count 0: the oracle judges those)
struct Gap {
  double mean_mm = 0, max_mm = 0;
  int points = 0;
};
Gap gap_at(const Oracle& oracle, const ClothMesh& cloth, double height_m) {
  const Points3& x = cloth.positions;
  std::vector<Vec3> section;
  for (Eigen::Index s = 0; s < cloth.springs.cols(); ++s) {
    if (cloth.kind[static_cast<std::size_t>(s)] != SpringKind::kStructural) continue;
    const Vec3 a = x.col(cloth.springs(0, s)), b = x.col(cloth.springs(1, s));
    if ((a.y() - height_m) * (b.y() - height_m) > 0 || a.y() == b.y()) continue;
    section.push_back(a + Real((height_m - a.y()) / (b.y() - a.y())) * (b - a));
  }
  Points3 points(3, static_cast<Eigen::Index>(section.size()));
  for (std::size_t k = 0; k < section.size(); ++k) points.col(static_cast<Eigen::Index>(k)) = section[k];
  std::vector<Real> d;
  oracle.signed_distance(points, d);
  Gap g;
  for (const Real r : d) {
    const double mm = 1e3 * std::max(0.0, double(r));
    g.mean_mm += mm / double(d.size()), g.max_mm = std::max(g.max_mm, mm);
  }
  g.points = static_cast<int>(d.size());
  return g;
}

// the three meshers: the ring of grid nodes snapped onto the outline; Durupinar's construction (garment.on_grid); and
// that with her step 7, the outline made smooth (garment.smooth)
struct Mesher {
  const char* label;
  const char* suffix;  // of its pictures' file names
  bool on_grid, smooth;
  const char* style;  // its curves' in the charts
};
const Mesher kMeshers[] = {{"ring", "", false, false, "o-"},
                           {"on the grid", "-grid", true, false, "x--"},
                           {"on the grid, smoothed", "-smooth", true, true, "s:"}};

// one row: a body, a garment type, a mesher and a size
struct Row {
  std::string body;
  const Type* type;
  const Mesher* mesher;
  std::string size;
  bool meets = false;
  std::vector<Gap> gaps;  // one per landmark
  Slivers slivers;
  double spacing_cm = 0;  // the grid's
};

// whether a body is dressed: every one, or at quick sizes one of each kind (a mesh alone, a rig, a scaled body)
bool measured(const ExperimentContext& ctx, const Body& b) {
  return !ctx.quick() || &b == &kBodies[0] || &b == &kBodies[1] || *b.scale;
}

// the row's vertex count: the type's, or a few at quick sizes
int vertices(const ExperimentContext& ctx, const Type& type) { return ctx.quick() ? 150 : type.vertices; }

// the sizes drafted: every one, or M and the largest at quick sizes (the same code paths at half the runs)
std::vector<std::string> drafted_sizes(const ExperimentContext& ctx) {
  const std::vector<std::string> all = draft_sizes();
  return ctx.quick() ? std::vector<std::string>{"M", all.back()} : all;
}

std::vector<std::string> overrides(const ExperimentContext& ctx, const Body& b, const Type& type, const Mesher& mesher,
                                   const std::string& size) {
  std::vector<std::string> sets{"body.file=" + std::string(b.file),
                                "garment.file=",
                                "garment.fit=" + std::string(type.name),
                                "garment.size=" + size,
                                "garment.vertices=" + std::to_string(vertices(ctx, type)),
                                "garment.on_grid=" + std::string(mesher.on_grid ? "true" : "false"),
                                "solver.face_queries=true"};
  if (*b.scale) sets.push_back("body.scale=" + std::string(b.scale));
  if (mesher.smooth) sets.push_back("garment.smooth=true");
  if (ctx.quick()) sets.push_back("stop.max_iterations=40");
  return sets;
}

MarkdownTable table() {
  std::vector<std::string> head{"body",
                                "garment",
                                "mesh",
                                "size",
                                "ease [cm]",
                                "stature; bust / waist / hip girth [cm]",
                                "vertices",
                                "springs under half a spacing",
                                "sewn",
                                "settled",
                                "iterations (sew + drape)",
                                "wall to dressed [s] (set-up incl.)"};
  for (const char* l : kLandmarks) head.push_back("gap at the " + landmark_word(l) + ": mean / max [mm] (points)");
  for (const char* h :
       {"inside [%]", "depth max [mm]", "crossings [%]", "seam gap [mm]", "strain max [%]", "meets the limits"})
    head.push_back(h);
  return MarkdownTable(head);
}

// the garment the run drafted and meshed, again (the same body, pattern and target vertex count give the same mesh)
MeshedPattern drafted(const RunResult& r, const BodyMeasurements& m, const Type& type, const std::string& size,
                      int vertices, const Mesher& mesher) {
  return mesh_pattern(draft_garment(type.name, r.final_body, m, size_ease_cm(size)),
                      MeshingOptions{0, vertices, true, mesher.on_grid, mesher.smooth});
}

// the row's cells, and what the summary gathers from it
std::vector<std::string> cells(const Body& b, const RunResult& r, const BodyMeasurements& m, Row& row) {
  std::string girths = num(100 * m["stature"].value_m, 0) + "; ";
  for (const char* l : kLandmarks) girths += (l == kLandmarks[0] ? "" : " / ") + num(100 * m[l].value_m, 1);
  std::vector<std::string> c{b.label,
                             row.type->name,
                             row.mesher->label,
                             row.size,
                             num(size_ease_cm(row.size), 0),
                             girths,
                             std::to_string(r.vertices),
                             std::to_string(row.slivers.total())};
  if (r.divergence) {
    c.push_back("diverged at iteration " + std::to_string(r.divergence->iteration));
    c.resize(table().columns(), "-");  // settled to strain: the columns up to the verdict
    c.back() = "no: diverged";
    return c;
  }
  const Oracle oracle(r.final_body);
  c.insert(c.end(),
           {r.sew.reached ? "yes" : "no", r.drape.reached ? "yes" : "no",
            std::to_string(r.sew.iterations) + " + " + std::to_string(r.drape.iterations), num(r.dressed_wall_s(), 3)});
  for (const char* l : kLandmarks) {
    row.gaps.push_back(gap_at(oracle, r.mesh, m[l].height_m));
    const Gap& g = row.gaps.back();
    c.push_back(g.points == 0 ? "- (0)"
                              : num(g.mean_mm, 1) + " / " + num(g.max_mm, 1) + " (" + std::to_string(g.points) + ")");
  }
  c.insert(c.end(), {num(r.accuracy.inside_pct, 2), num(r.accuracy.depth_max_mm, 1), num(r.accuracy.crossings_pct, 2),
                     num(r.seam_gap_max_mm, 1), num(100 * r.strain_max, 1), limits_cell(r)});
  row.meets = limit_misses(r).empty();
  return c;
}

// what the summary says of one mesher's rows
struct Tally {
  int pairs = 0, m_meets = 0, grows = 0, rows = 0, meet = 0, clean = 0, springs = 0;
  double spacing_lo = 1e300, spacing_hi = 0;  // the grids' [cm]
  std::string m_misses, flat;
};
Tally tally(const std::vector<Row>& rows, const Mesher& mesher) {
  std::map<std::string, std::vector<const Row*>> by;  // garment and body: its sizes in order
  for (const Row& r : rows)
    if (r.mesher == &mesher) by[std::string(r.type->name) + " on " + r.body].push_back(&r);
  Tally t;
  for (const auto& [what, sizes] : by) {
    std::vector<double> gap;  // the mean gap at the judged landmark of each size that did not diverge, S to XL
    for (const Row* r : sizes) {
      if (r->size == "M") ++(r->meets ? t.m_meets : t.pairs), t.m_misses += r->meets ? "" : "; " + what;
      if (!r->gaps.empty()) gap.push_back(r->gaps[static_cast<std::size_t>(r->type->judged_at)].mean_mm);
      ++t.rows, t.meet += r->meets ? 1 : 0, t.clean += r->slivers.total() == 0 ? 1 : 0;
      t.springs += r->slivers.total();
      t.spacing_lo = std::min(t.spacing_lo, r->spacing_cm), t.spacing_hi = std::max(t.spacing_hi, r->spacing_cm);
    }
    bool up = gap.size() == sizes.size();  // every size drafted dressed
    std::string series;
    for (std::size_t k = 0; k < gap.size(); ++k) {
      up = up && (k == 0 || gap[k] > gap[k - 1]);
      series += std::string(k ? ", " : "") + num(gap[k], 1);
    }
    t.grows += up ? 1 : 0;
    if (!up) t.flat += "; " + what + " " + series + " mm";
  }
  t.pairs += t.m_meets;
  return t;
}

// "; a; b" as " (not: a; b)", "" as ""
std::string except(const std::string& list) { return list.empty() ? "" : " (not: " + list.substr(2) + ")"; }

// the page's opening lines: what the paper gives; per mesher, size M within the limits, the gap from S to XL where
// each type is judged, the slivers; the verdict
std::vector<std::string> summary(const std::vector<Row>& rows) {
  const auto line = [&](const Tally& t, const std::string& how) {
    return how + ": size M dresses its body within every limit in " + std::to_string(t.m_meets) + " of " +
           std::to_string(t.pairs) + " garment and body pairs" + except(t.m_misses) +
           "; the mean gap grows from S to XL (at the hip; the shirts' at the bust) in " + std::to_string(t.grows) +
           " of " + std::to_string(t.pairs) + except(t.flat) + "; " + std::to_string(t.meet) + " of " +
           std::to_string(t.rows) + " rows within every limit; " + std::to_string(t.clean) + " of " +
           std::to_string(t.rows) + " garments without a structural spring under half a spacing (" +
           std::to_string(t.springs) + " such springs in all).";
  };
  std::vector<Tally> t;
  for (const Mesher& m : kMeshers) t.push_back(tally(rows, m));
  std::set<std::string> dressed;
  for (const Row& r : rows) dressed.insert(r.body);
  const std::size_t bodies = dressed.size();
  const Tally& grid = t[1];
  // "yes (ring), no (on the grid), ..." of one criterion
  const auto verdict = [&](const std::function<bool(const Tally&)>& met) {
    std::string s;
    for (std::size_t k = 0; k < t.size(); ++k)
      s += std::string(k ? ", " : "") + (met(t[k]) ? "yes" : "no") + " (" + kMeshers[k].label + ")";
    return s;
  };
  return {
      "The paper (Durupinar section 2): each panel's corners from the body's measurements, joined and filled on the "
      "cloth grid; it gives no measure of the fit nor a time for it.",
      line(t[0], "Ours, one run each, " + std::to_string(std::size(kTypes)) + " garment types on " +
                     std::to_string(bodies) + " bodies, meshed with the ring snapped onto the outline"),
      line(grid, "Drawn on the grid (Durupinar's construction)") +
          " Every corner moves to a grid node up to a column outward and half a row off; the columns are " +
          num(grid.spacing_lo, 1) + " to " + num(grid.spacing_hi, 1) + " cm wide here, each side of a panel gains " +
          num((size_ease_cm(draft_sizes()[1]) - size_ease_cm(draft_sizes()[0])) / 4, 1) +
          " cm from one size to the next.",
      line(t[2], "Drawn on the grid and smoothed (her step 7: the outline's vertices moved onto the outline, then the "
                 "seams' vertices aligned as the ring mesher aligns them and every spring kept at least half a spacing "
                 "long)"),
      "Verdict: every drafted garment type dresses every body at size M within every limit: " +
          verdict([](const Tally& x) { return x.m_meets == x.pairs; }) + "; the gap grows from S to XL: " +
          verdict([](const Tally& x) { return x.grows == x.pairs; }) +
          "; the generated panels have no spring under half a spacing: " +
          verdict([](const Tally& x) { return x.clean == x.rows; }) + ".",
  };
}

const char* const kDescription =
    "Each garment type `clothbench measure --draft` knows (skirt, sleeveless shirt, shirt with short sleeves, "
    "sleeveless dress, knee-length trousers) is drafted "
    "from each body's own measurements (Durupinar section 2; `[[garment]] fit`, scenes/README.md, says how the "
    "panels are cut) in sizes S, M, L and XL, meshed in three ways: the ring of grid nodes snapped "
    "onto the outline (the default), Durupinar's construction (`garment.on_grid`: the outline's points moved to grid "
    "nodes, joined by Bresenham lines and filled, every vertex a grid node), and that with her step 7 "
    "(`garment.smooth`: the outline made smooth, the seams' vertices aligned, no spring under half a spacing); then sewn and draped on that body standing still, with "
    "the settings of its scene in scenes/dressing (is-cpu, the stable regime) and face "
    "queries (quad midpoints too, as skirt.toml has them; the shirt with sleeves in shirt.toml's), at 600 vertices "
    "(the shirt with sleeves, the dress and the trousers 800). The "
    "bodies, in their rest "
    "pose: Debian's human; the "
    "walking body; a taller MakeHuman body (scenes/data/body/mh_female_tall.obj, made by tools/make_body.py from the "
    "same sources with a larger height target); GarmentCode's mean female, broader; and the walking body scaled to "
    "0.9 across (`body.scale`). The fit: how far the cloth sits outside the body round the bust, the waist and the "
    "hip, as a tape round the garment would show it: the points where its structural springs cross each landmark's "
    "height (as `clothbench measure` finds it), their mean and largest signed distance to the body (the exact "
    "oracle's, points inside counting 0), with the count of points beside each (a skirt's top edge sits at the "
    "waist or just below it, so few springs cross there; a skirt has none at the bust, a shirt none at the hip). "
    "The slivers: the meshed garment's structural springs shorter than half the grid spacing. One run each; wall "
    "time one thread, set-up included.\n\n";

// a picture's or a chart's file name
std::string figure(const Type& type, const Mesher& mesher) {
  return "made-to-measure-" + std::string(type.name) + mesher.suffix;
}

void made_to_measure(ExperimentContext& ctx) {
  MarkdownTable t = table();
  std::vector<Row> rows;
  std::map<std::string, nlohmann::json> series;        // per type: one curve per body and mesher
  std::map<std::string, std::vector<Image>> pictures;  // per figure: each body in size M
  for (const Body& b : kBodies) {
    if (!measured(ctx, b)) continue;
    std::optional<BodyMeasurements> m;  // the body's, once (its rest pose is every row's final body)
    for (const Type& type : kTypes)
      for (const Mesher& mesher : kMeshers) {
        std::vector<double> x, y;
        for (const std::string& size : drafted_sizes(ctx)) {
          const RunResult& r =
              ctx.run("dressing/" + std::string(type.scene) + ".toml", "is-cpu", overrides(ctx, b, type, mesher, size));
          ctx.add_run(r, "made-to-measure/" + std::string(b.label) + "/" + type.name + "/" + mesher.label + "/" + size);
          if (!m) m = measure_body(r.final_body);
          rows.push_back({b.label, &type, &mesher, size});
          Row& row = rows.back();
          const MeshedPattern mesh = drafted(r, *m, type, size, vertices(ctx, type), mesher);
          row.slivers = slivers(mesh);
          row.spacing_cm = mesh.spacing_cm;
          t.row(cells(b, r, *m, row));
          if (!row.gaps.empty())
            x.push_back(size_ease_cm(size)), y.push_back(row.gaps[static_cast<std::size_t>(type.judged_at)].mean_mm);
          if (size == "M" && !r.divergence)
            pictures[figure(type, mesher)].push_back(ctx.pictures().render(r.final_body, r.mesh, 360, View::kFront));
        }
        series[type.name].push_back(
            {{"label", std::string(b.label) + (mesher.on_grid ? ", " + std::string(mesher.label) : "")},
             {"x", x},
             {"y", y},
             {"style", mesher.style}});
      }
  }
  std::string figures;
  for (const Type& type : kTypes) {
    const std::string at = landmark_word(kLandmarks[type.judged_at]);
    ctx.chart(figure(type, kMeshers[0]),
              {{"title", "Drafted " + std::string(type.name) + "s: the gap at the " + at + " against the size's ease"},
               {"xlabel", "ease [cm] (S, M, L, XL)"},
               {"ylabel", "mean gap at the " + at + " [mm]"},
               {"series", series[type.name]}});
    figures += "![" + std::string(type.name) + " chart](" + figure(type, kMeshers[0]) + ".png)\n\n";
    for (const Mesher& mesher : kMeshers) {
      side_by_side(pictures[figure(type, mesher)]).write_png(ctx.path("pictures/" + figure(type, mesher) + ".png"));
      figures += "![each body in its size M " + std::string(type.name) + ", " + mesher.label + "](pictures/" +
                 figure(type, mesher) + ".png)\n\n";
    }
  }
  ctx.write("made-to-measure", "Made-to-measure garments on each body",
            kDescription + t.str() + "\n" + figures + "Pictures drawn by " + ctx.pictures().name() +
                ", the bodies in the order of the table: each type with the ring mesher, then on the grid, then on the grid and "
                "smoothed.\n",
            summary(rows));
}

}  // namespace

void add_made_to_measure_experiments(std::vector<Experiment>& out) {
  out.push_back({"made-to-measure", "Made-to-measure garments on each body", made_to_measure});
}

}  // namespace clothbench
