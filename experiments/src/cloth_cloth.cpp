// cloth-cloth: the cloth against itself and against the garment under it, on the static body and on the walk: how
// many of the structural springs pass through a triangle of the cloth (the worst frame) with each method and with
// none, beside the body's limits and the time per step.
#include <string>
#include <vector>

#include "clothbench/bench/report.hpp"
#include "clothbench/experiments/experiment.hpp"
#include "experiment_list.hpp"

namespace clothbench {

namespace {

// the limit of the cloth through itself, as the body's crossings limit [%]
constexpr double kClothCrossingsLimitPct = 1.0;

// one way of answering the cloth against itself (scene keys)
struct Method {
  std::string label;
  std::vector<std::string> sets;
  bool image = false;     // image space: answers a layer against the cloth under it, run on layered cases only
  bool standing = false;  // image space with the papers' two cameras: run standing only (the walking outfit's body
                          // needs its six)
};
// the cloth's thickness where it is answered [mm]: the scenes' (outfit.toml)
const std::string kThicknessMm = "5";
// image space: the cloth under answered this much thicker [mm] (collider.cloth_skin_mm)
const std::string kClothSkinMm = "3";
// none; object space (a spatial hash of the cloth's triangles, Bridson, Fedkiw and Anderson 2002 section 7.1) answered
// once a step, after the body's response; and answered again after the strain limit's second pass. Image space:
// the layer under as a body, its maps drawn by the CPU rasteriser, seen by two cameras or six (the body too)
std::vector<Method> methods() {
  const std::string mm = " (" + kThicknessMm + " mm)", thickness = "solver.self_contact_mm=" + kThicknessMm;
  const std::vector<std::string> none{"solver.self_contact_mm=0", "solver.self_contact_last=false"};
  auto image = none;
  image.insert(image.end(), {"collider.cloth_under=is-cpu", "collider.cloth_skin_mm=" + kClothSkinMm});
  auto two = image, six = image;
  two.push_back("collider.views=2");
  six.push_back("collider.views=6");
  auto both = six;
  both.insert(both.end(), {thickness, "solver.self_contact_last=true"});
  return {{"none", none},
          {"object space, once a step" + mm, {thickness, "solver.self_contact_last=false"}},
          {"object space, again after the limit" + mm, {thickness, "solver.self_contact_last=true"}},
          {"image space, the layer under, 2 views", two, true, true},
          {"image space, the layer under, 6 views", six, true},
          {"image space, 6 views, and object space again after the limit" + mm, both, true}};
}

// one scene of the page: its file, the motion it is run on ("" standing still) and how its garments are dressed
struct Case {
  std::string label, scene, clip;
  std::vector<std::string> sets;
  bool layered;  // an outer layer is placed over the dressed inner one
};
// whether a method is run on a case
// (quick runs: image space standing only, the same code path; the walking outfit is dressed in full at quick sizes
// and the maps of its moving shirt are drawn every few steps. The outfits, dressed in full, run object space in none
// of their rows: the cases of one layer run its code paths at a few iterations)
bool runs(const Method& m, const Case& c, bool quick) {
  if (quick && c.layered && !m.image) return m.label == "none";
  return !m.image || (c.layered && (!(m.standing || quick) || c.clip.empty()));
}

std::vector<Case> cases() {
  return {{"outfit (a dress over a shirt with sleeves)", "dressing/outfit.toml", "", {}, true},
          {"outfit, dressed together", "dressing/outfit.toml", "", {"garment.layer=0"}, false},
          {"dress with sleeves", "walking/dress_sleeves.toml", "walk_07_01", {}, false},
          {"dress with sleeves", "walking/dress_sleeves.toml", "walk_08_02", {"body.animation=walk_08_02"}, false},
          {"outfit (a dress over a shirt with sleeves)", "walking/outfit.toml", "walk_07_01", {}, true}};
}

// quick runs: a few iterations a phase and a short walk, but a layered outfit dressed in full (an outer layer over an
// inner one that was not dressed starts far outside it, stretched, and diverges)
std::vector<std::string> quick_sets(const Case& c) {
  std::vector<std::string> sets;
  if (!c.layered) sets.push_back("stop.max_iterations=40");
  if (!c.clip.empty()) sets.push_back("body.end_s=1.05");
  return sets;
}

// the cloth through itself [%]: at the worst measured frame of a walk, at the end standing still
double cloth_through(const RunResult& r) {
  return r.frame_samples.empty() ? r.accuracy.cloth_crossings_pct : r.frame_max(&FrameSample::cloth_crossings_pct);
}

// what a row of the summary needs
struct Row {
  const Case* c;
  const Method* m;
  double through_pct;
  bool body_ok;  // every body limit, at every frame of a walk
  double ms_per_step;
};

MarkdownTable table() {
  return MarkdownTable({"garments", "body", "cloth against cloth", "vertices", "sewn", "iterations (sew + drape)",
                        "ms per step (all phases; of which cloth against cloth)", "s per frame (walk)",
                        "cloth through itself [%] (worst / mean frame on a walk)",
                        "body limits (every frame on a walk)"});
}

std::vector<std::string> cells(const Case& c, const Method& m, const RunResult& r) {
  std::vector<std::string> row{c.label, c.clip.empty() ? "standing" : c.clip, m.label, std::to_string(r.vertices)};
  if (r.divergence) {  // the columns from "sewn" to the cloth through itself say where, the last what
    row.push_back("diverged (" + std::string(to_string(r.divergence->phase)) + ", iteration " +
                  std::to_string(r.divergence->iteration) + ")");
    row.resize(table().columns() - 1, "-");
    row.push_back("no: diverged");
    return row;
  }
  const bool walks = !r.frame_samples.empty();
  row.insert(row.end(),
             {r.sew.reached || (walks && r.window_seam_gap_mm <= kAccuracyLimits.seam_gap_mm) ? "yes" : "no",
              std::to_string(r.sew.iterations) + " + " + std::to_string(r.drape.iterations),
              num(r.ms_per_iteration(), 3) + " (" + num(r.cloth_ms_per_iteration(), 3) + ")",
              walks && r.frames ? num(r.animate.wall_ms / 1e3 / double(r.frames), 3) : "-",
              num(cloth_through(r), 2) + (walks ? " / " + num(r.frame_mean(&FrameSample::cloth_crossings_pct), 2) : ""),
              limits_cell(r)});
  return row;
}

// whether every row of method `m` keeps at most the limit of its springs out of the cloth with every body limit met
bool holds(const std::vector<Row>& rows, const Method& m) {
  bool all = true;
  for (const Row& r : rows)
    if (r.m == &m) all = all && r.through_pct <= kClothCrossingsLimitPct && r.body_ok;
  return all;
}

// the page's opening lines: per scene, the cloth through itself with each method; a verdict on the object-space
// method answered twice, on the image-space one with six views and on both
std::vector<std::string> summary(const std::vector<Row>& rows, const std::vector<Case>& all_cases,
                                 const std::vector<Method>& methods) {
  const Method &object = methods[2], &image = methods[4], &both = methods[5];
  std::vector<std::string> out{
      "The papers answer the cloth against the body only; the dressing paper proposes the cloth's own maps for "
      "cloth against cloth as future work (section 8). Image space here answers a layer of garments against the "
      "dressed cloth under it, as against the body; object space answers the cloth against all of itself."};
  for (const bool walks : {false, true}) {  // a line standing, a line walking
    std::string line = walks ? "Walking, the worst frame:" : "Standing:";
    const char* sep = " ";
    for (const Case& c : all_cases) {
      if (c.clip.empty() == walks) continue;
      line += sep + c.label + (walks ? " (" + c.clip + ")" : "") + " through itself";
      const char* inner = " ";
      for (const Row& r : rows) {
        if (r.c != &c) continue;
        line += inner + num(r.through_pct, 2) + " % " + r.m->label + (r.body_ok ? "" : " (misses a body limit)") +
                ", " + num(r.ms_per_step, 3) + " ms per step";
        inner = ", ";
      }
      sep = "; ";
    }
    out.push_back(line + ".");
  }
  const std::string limit = num(kClothCrossingsLimitPct, 0) + " % of its springs out of the cloth";
  out.push_back("Verdict: " + object.label + ", every scene keeps at most " + limit +
                " with every body limit met: " + (holds(rows, object) ? "yes" : "no") +
                ". Every outfit dressed in layers, " + image.label + ": " + (holds(rows, image) ? "yes" : "no") + "; " +
                both.label + ": " + (holds(rows, both) ? "yes" : "no") + ".");
  return out;
}

// the page's description, around the skin of the image-space rows
const char* const kDescriptionHead =
    "Cloth against cloth: a garment's springs through its own triangles (a fold, a sleeve against the torso) or "
    "through another garment's. The figure is the oracle's (cloth_crossings.hpp): structural springs through a "
    "triangle of the cloth with no corner at either end, sewn points counted as one, at the end of a standing run and "
    "at the worst of every frame of a walk. The methods (scenes/README.md, `solver.self_contact_mm`, "
    "`self_contact_last`): none; a point nearer than the thickness to a triangle of the cloth and moving towards it "
    "stopped by an impulse shared with the triangle's corners (Bridson, Fedkiw and Anderson 2002, section 7.1; the "
    "candidates from a spatial hash of the triangles, Teschner et al. 2003), once a step after the body's response; "
    "and the same again after the strain limit's second pass, which moves points along their springs and can carry one "
    "through the cloth, followed by the body's non-penetration. Image space (`collider.cloth_under`, `cloth_skin_mm`; "
    "rows of the outfits dressed in layers only): the dressing paper's future work, the cloth rendered and its "
    "collisions read from the maps. The dressed layer under is given to an image-space collider as a moving body (its "
    "cells as triangles facing away from its middle, its velocities as the body's), drawn again once a point of it has "
    "moved half the hit distance (`collider.tol`), answered ";
const char* const kDescriptionTail =
    " mm thicker; the outer layer's points and quad midpoints are answered against it as against the body (dressing "
    "Eq. 12, pushed out, held out after the limit's second pass). One way: the layer under is not answered against the "
    "one over it, nor a garment against itself. With the papers' two cameras a point that neither sees behind the "
    "cloth under (the armpit, a shoulder's top) is not answered, or answered along a side's normal; the six-view rows "
    "answer the body with the same six cameras. The outfit (scenes/dressing/outfit.toml, scenes/walking/outfit.toml) "
    "is a sleeveless dress drafted in size XL over a shirt with sleeves in size M, dressed inner first (`[[garment]] "
    "layer`: the dress placed clear of the dressed shirt) or, in one row, both together. The dress with sleeves is "
    "walking-t2's (2,300 vertices). One run each, one thread, is-cpu.\n\n";

void cloth_cloth(ExperimentContext& ctx) {
  MarkdownTable t = table();
  const std::vector<Case> all_cases = cases();
  const std::vector<Method> all_methods = methods();
  std::vector<Row> rows;
  RunOptions frames;
  frames.measure_frames = true;
  for (const Case& c : all_cases)
    for (const Method& m : all_methods) {
      if (!runs(m, c, ctx.quick())) continue;
      std::vector<std::string> sets = c.sets;
      sets.insert(sets.end(), m.sets.begin(), m.sets.end());
      if (ctx.quick())
        for (const std::string& q : quick_sets(c)) sets.push_back(q);
      const RunResult& r = ctx.run(c.scene, "is-cpu", sets, c.clip.empty() ? RunOptions{} : frames);
      ctx.add_run(r, "cloth-cloth/" + c.label + "/" + (c.clip.empty() ? "standing" : c.clip) + "/" + m.label);
      t.row(cells(c, m, r));
      rows.push_back({&c, &m, cloth_through(r), !r.divergence && limit_misses(r).empty(), r.ms_per_iteration()});
    }
  ctx.write("cloth-cloth", "Cloth against cloth", kDescriptionHead + kClothSkinMm + kDescriptionTail + t.str(),
            summary(rows, all_cases, all_methods));
}

}  // namespace

void add_cloth_cloth_experiments(std::vector<Experiment>& out) {
  out.push_back({"cloth-cloth", "Cloth against cloth", cloth_cloth});
}

}  // namespace clothbench
