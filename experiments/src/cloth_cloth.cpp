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
};
// the cloth's thickness where it is answered [mm]: the scenes' (outfit.toml)
const std::string kThicknessMm = "5";
// none; object space (a spatial hash of the cloth's triangles, Bridson, Fedkiw and Anderson 2002 section 7.1) answered
// once a step, after the body's response; and answered again after the strain limit's second pass
std::vector<Method> methods() {
  const std::string mm = " (" + kThicknessMm + " mm)", thickness = "solver.self_contact_mm=" + kThicknessMm;
  return {{"none", {"solver.self_contact_mm=0", "solver.self_contact_last=false"}},
          {"object space, once a step" + mm, {thickness, "solver.self_contact_last=false"}},
          {"object space, again after the limit" + mm, {thickness, "solver.self_contact_last=true"}}};
}

// one scene of the page: its file, the motion it is run on ("" standing still) and how its garments are dressed
struct Case {
  std::string label, scene, clip;
  std::vector<std::string> sets;
  bool layered;  // an outer layer is placed over the dressed inner one
};
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
                        "ms per step (all phases)", "s per frame (walk)",
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
  row.insert(
      row.end(),
      {r.sew.reached || (walks && r.window_seam_gap_mm <= kAccuracyLimits.seam_gap_mm) ? "yes" : "no",
       std::to_string(r.sew.iterations) + " + " + std::to_string(r.drape.iterations), num(r.ms_per_iteration(), 3),
       walks && r.frames ? num(r.animate.wall_ms / 1e3 / double(r.frames), 3) : "-",
       num(cloth_through(r), 2) + (walks ? " / " + num(r.frame_mean(&FrameSample::cloth_crossings_pct), 2) : ""),
       limits_cell(r)});
  return row;
}

// the page's opening lines: per scene, the cloth through itself with each method; the verdict on the last method
std::vector<std::string> summary(const std::vector<Row>& rows, const std::vector<Case>& all_cases, const Method& last) {
  std::vector<std::string> out{
      "The papers answer the cloth against the body only; the dressing paper proposes the cloth's own depth maps for "
      "cloth against cloth as future work. Not built here: an image-space method (the inner layer's depth and normal "
      "maps queried as the body's are), so every method below is in object space."};
  bool all = true;
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
        if (r.m == &last) all = all && r.through_pct <= kClothCrossingsLimitPct && r.body_ok;
      }
      sep = "; ";
    }
    out.push_back(line + ".");
  }
  out.push_back(std::string("Verdict: with the cloth answered again after the limit, every scene keeps at most ") +
                num(kClothCrossingsLimitPct, 0) +
                " % of its springs out of the cloth with every body limit met: " + (all ? "yes" : "no") + ".");
  return out;
}

const char* const kDescription =
    "Cloth against cloth: a garment's springs through its own triangles (a fold, a sleeve against the torso) or "
    "through another garment's. The figure is the oracle's (cloth_crossings.hpp): structural springs through a "
    "triangle of the cloth with no corner at either end, sewn points counted as one, at the end of a standing run and "
    "at the worst of every frame of a walk. The methods (scenes/README.md, `solver.self_contact_mm`, "
    "`self_contact_last`): none; a point nearer than the thickness to a triangle of the cloth and moving towards it "
    "stopped by an impulse shared with the triangle's corners (Bridson, Fedkiw and Anderson 2002, section 7.1; the "
    "candidates from a spatial hash of the triangles, Teschner et al. 2003), once a step after the body's response; "
    "and the same again after the strain limit's second pass, which moves points along their springs and can carry "
    "one through the cloth, followed by the body's non-penetration. The outfit (scenes/dressing/outfit.toml, "
    "scenes/walking/outfit.toml) is a sleeveless dress drafted in size XL over a shirt with sleeves in size M, "
    "dressed inner first (`[[garment]] layer`: the dress placed clear of the dressed shirt) or, in one row, both "
    "together. The dress with sleeves is walking-t2's (2,300 vertices). One run each, one thread, is-cpu.\n\n";

void cloth_cloth(ExperimentContext& ctx) {
  MarkdownTable t = table();
  const std::vector<Case> all_cases = cases();
  const std::vector<Method> all_methods = methods();
  std::vector<Row> rows;
  RunOptions frames;
  frames.measure_frames = true;
  for (const Case& c : all_cases)
    for (const Method& m : all_methods) {
      std::vector<std::string> sets = c.sets;
      sets.insert(sets.end(), m.sets.begin(), m.sets.end());
      if (ctx.quick())
        for (const std::string& q : quick_sets(c)) sets.push_back(q);
      const RunResult& r = ctx.run(c.scene, "is-cpu", sets, c.clip.empty() ? RunOptions{} : frames);
      ctx.add_run(r, "cloth-cloth/" + c.label + "/" + (c.clip.empty() ? "standing" : c.clip) + "/" + m.label);
      t.row(cells(c, m, r));
      rows.push_back({&c, &m, cloth_through(r), !r.divergence && limit_misses(r).empty(), r.ms_per_iteration()});
    }
  ctx.write("cloth-cloth", "Cloth against cloth", kDescription + t.str(), summary(rows, all_cases, all_methods.back()));
}

}  // namespace

void add_cloth_cloth_experiments(std::vector<Experiment>& out) {
  out.push_back({"cloth-cloth", "Cloth against cloth", cloth_cloth});
}

}  // namespace clothbench
