#pragma once
// What the tables of the dressing paper (dressing-t1, walking-t1, dressing-t2, dressing-f8) share: the
// colliders they compare, --quick budgets, accuracy cells, the Table 1 garments and budget, image space with
// the papers' test or ours (Variant), pictures of the is-cpu runs and the line naming their renderer.
#include <cmath>
#include <optional>
#include <sstream>

#include "clothbench/bench/report.hpp"
#include "clothbench/experiments/experiment.hpp"
#include "clothbench/experiments/paper_figures.hpp"
#include "clothbench/experiments/statistics.hpp"
#include "clothbench/render/picture.hpp"

namespace clothbench::paper_tables {

// whether a collider is of the image-space family (ColliderInfo::family)
inline bool image_space(const std::string& collider) {
  const std::optional<ColliderInfo> c = collider_info(collider);
  return c && c->family == Family::kImageSpace;
}

// overrides every run of an experiment gets in --quick mode: same code paths, fewer iterations
inline std::vector<std::string> with_quick(const ExperimentContext& ctx, std::vector<std::string> sets,
                                           long iterations = 60) {
  if (ctx.quick()) sets.push_back("stop.max_iterations=" + std::to_string(iterations));
  return sets;
}

// inside [%] | depth max [mm] | crossings (% of structural springs) | seam gap [mm] | strain max [%]
inline std::string accuracy_cells(const RunResult& r) {
  if (r.divergence) return "diverged (it " + std::to_string(r.divergence->iteration) + ") | - | - | - | -";
  return num(r.accuracy.inside_pct, 2) + " | " + num(r.accuracy.depth_max_mm, 1) + " | " +
         std::to_string(r.accuracy.crossings) + " (" + num(r.accuracy.crossings_pct, 2) + " %) | " +
         num(r.seam_gap_max_mm, 1) + " | " + num(100 * r.strain_max, 1);
}

// a table's own columns, then those accuracy_cells fills, whether the run converged and the limits' verdict
inline std::vector<std::string> with_accuracy_columns(std::vector<std::string> head) {
  for (const char* c : {"inside [%]", "depth max [mm]", "crossings (%)", "seam gap [mm]", "strain max [%]", "converged",
                        "meets the limits"})
    head.push_back(c);
  return head;
}

// pictures/NAME.png: front, side and back of a run's end state; returns a markdown link to it
inline std::string picture(ExperimentContext& ctx, const RunResult& r, const std::string& name,
                           const std::string& label) {
  std::vector<Image> views;
  for (View v : {View::kFront, View::kSide, View::kBack})
    views.push_back(ctx.pictures().render(r.final_body, r.mesh, 360, v));
  side_by_side(views).write_png(ctx.path("pictures/" + name + ".png"));
  return "[" + label + "](pictures/" + name + ".png)";
}

// the line under a table that lists its pictures and names the renderer that drew them (empty without pictures)
inline std::string pictures_line(ExperimentContext& ctx, const std::vector<std::string>& links,
                                 const std::string& extra = "") {
  if (links.empty()) return "";
  std::string line =
      "\nPictures of the is-cpu runs' end states (front, side, back), drawn by " + ctx.pictures().name() + ": ";
  for (std::size_t i = 0; i < links.size(); ++i) line += (i ? ", " : "") + links[i];
  return line + extra + ".\n";
}

struct T1Garment {
  const char* product;
  const char* scene;
  int vertices;
};
inline const T1Garment kT1[] = {{"shirt", "dressing/shirt.toml", 1800}, {"dress", "dressing/dress.toml", 3840}};

// the reproduce budget (20 minutes on 2 cores) allows 1 s of simulated time per Table 1 run in the stable
// regime; the papers' regime takes 24-42 times fewer iterations, so its runs get 1 s to sew and 2 s to settle
inline std::vector<std::string> t1_budget(const std::string& regime) {
  if (regime == "papers") return {"stop.sew_max_s=1", "stop.drape_max_s=2"};
  return {"stop.sew_max_s=0.6", "stop.drape_max_s=0.4"};
}

// a paper table's collider entry: with the papers' detection (papers_detection), or with ours
struct Variant {
  std::string collider;
  bool ours = false;
  std::string label() const { return collider + (ours ? " (ours)" : ""); }
  // `sets` with what the entry adds to the scene
  std::vector<std::string> with(std::vector<std::string> sets) const {
    if (!ours)
      for (const auto& o : papers_detection(collider)) sets.push_back(o);
    return sets;
  }
};

// what one Table 1 run asks for: a garment, an entry, a regime
inline ExperimentContext::Request t1_request(const ExperimentContext& ctx, const T1Garment& g, const Variant& v,
                                             const std::string& regime = "stable") {
  std::vector<std::string> sets = t1_budget(regime);
  sets.push_back("garment.vertices=" + std::to_string(g.vertices));
  sets.push_back("solver.regime=" + regime);
  return {g.scene, v.collider, with_quick(ctx, v.with(sets))};
}

// `at_least`: runs of it (ExperimentContext::run)
inline const RunResult& t1_run(ExperimentContext& ctx, const T1Garment& g, const Variant& v,
                               const std::string& regime = "stable", int at_least = 1) {
  const ExperimentContext::Request q = t1_request(ctx, g, v, regime);
  return ctx.run(q.scene, q.collider, q.sets, {}, at_least);
}

// every collider, and once more with our defaults ("ours") those whose default departs from the papers' (image
// space; the object-space collider the verdicts lean on, kLeadObjectSpace, for its normals)
inline std::vector<Variant> with_ours(const std::vector<std::string>& colliders) {
  std::vector<Variant> v;
  for (const auto& c : colliders) v.push_back({c, false});
  for (const auto& c : colliders)
    if (image_space(c) || c == kLeadObjectSpace) v.push_back({c, true});
  return v;
}

// Table 1's entries (dressing-t1, walking-t1): every collider of the tables, then ours where it departs
inline std::vector<Variant> t1_variants(const ExperimentContext& ctx) { return with_ours(ctx.colliders(in_tables())); }

// the runs of dressing-t1 and walking-t1, in their tables' order: per garment, regime and entry (their summaries
// and dressing-t1's ratios take theirs from these)
inline std::vector<ExperimentContext::Request> t1_runs(const ExperimentContext& ctx) {
  std::vector<ExperimentContext::Request> runs;
  for (const auto& g : kT1)
    for (const std::string regime : kRegimes)
      for (const Variant& v : t1_variants(ctx)) runs.push_back(t1_request(ctx, g, v, regime));
  return runs;
}

inline const std::string kImageSpaceNote =
    " Image space (is-gl, is-cpu) runs the papers' own test by default: the z comparison along the view axis "
    "(dressing Eq. 9) on 8-bit colour maps (dressing Eqs. 6-7); rows marked (ours) run our default, the "
    "tangent-plane refinement on float maps (results/deviations.md). Object space responds with face normals as the "
    "dressing paper's bounding-box method did (section 7; fcl and embree, `collider.face_normals`); embree (ours) "
    "with our interpolated vertex normals.";

// the is-cpu run's picture, named and labelled by garment and regime
inline std::string regime_picture(ExperimentContext& ctx, const RunResult& r, const std::string& table,
                                  const std::string& product, const std::string& regime) {
  return picture(ctx, r, table + "-" + product + regime_suffix(regime, "-"),
                 product + (regime == "stable" ? "" : " (" + regime + ")"));
}

// the sewing phase's iterations and their ratio to the paper's count ("to sew", dressing section 7)
inline std::string sew_cell(const RunResult& r, int paper_iterations) {
  if (!r.sew.reached) return "not sewn (" + std::to_string(r.sew.iterations) + ")";
  return std::to_string(r.sew.iterations) + " (" + num(double(r.sew.iterations) / paper_iterations, 2) + "x)";
}

// our wall time to sew (the sew phase alone), what the dressing paper's totals measure (Table 1: "to sew")
inline std::string sew_time_cell(const RunResult& r) {
  return r.sew.reached ? num(r.sew.wall_ms / 1e3, 2) : "not sewn (" + num(r.sew.wall_ms / 1e3, 2) + ")";
}

// "N at dt ms": an iteration count with the step it was taken at
inline std::string iterations_cell(const RunResult& r) {
  return std::to_string(r.iterations()) + " at " + num(1e3 * r.dt_s, 3) + " ms";
}

// a summary's account of one run: "N iterations to sew (T s), meets every limit" or what it misses
inline std::string summary_run(const RunResult& r) {
  if (r.divergence) return "diverged at iteration " + std::to_string(r.divergence->iteration);
  const std::string sew =
      r.sew.reached ? std::to_string(r.sew.iterations) + " iterations to sew (" + num(r.sew.wall_ms / 1e3, 2) + " s)"
                    : "not sewn in " + std::to_string(r.sew.iterations) + " iterations";
  const auto misses = limit_misses(r);
  std::string verdict = misses.empty() ? "meets every limit" : "misses ";
  for (std::size_t i = 0; i < misses.size(); ++i) verdict += (i ? ", " : "") + misses[i];
  return sew + ", " + verdict;
}

// whether a summary's two rows are a verdict's evidence: a row that misses any limit, strain included, is not
inline bool both_meet_the_limits(const RunResult& a, const RunResult& b) {
  return limit_misses(a).empty() && limit_misses(b).empty();
}

// "; the shirt and the dress left out (a row misses a limit)" for the garments a verdict cannot count, else ""
inline std::string left_out(const std::vector<std::string>& garments) {
  if (garments.empty()) return "";
  std::string s = "; left out, a row misses a limit: the ";
  for (std::size_t i = 0; i < garments.size(); ++i)
    s += (i ? (i + 1 == garments.size() ? " and the " : ", the ") : "") + garments[i];
  return s;
}

// the colliders a summary sets against each other: the lead image-space and object-space ones, else the first built
// of each family in the tables
struct SummaryPair {
  std::string is, os;
  bool ok() const { return !is.empty() && !os.empty(); }
};
inline SummaryPair summary_pair(const ExperimentContext& ctx) {
  const auto is = lead_first(kLeadImageSpace, ctx.colliders(in_tables(Family::kImageSpace)));
  const auto os = lead_first(kLeadObjectSpace, ctx.colliders(in_tables(Family::kObjectSpace)));
  return {is.empty() ? "" : is.front(), os.empty() ? "" : os.front()};
}

// the runs of each of the summary pair's rows at the papers' clock: their timing verdicts rest on five at least
// the summary pair's rows of every garment at the papers' clock, run kVerdictRuns times (once in --quick); before
// the table, so that its rows and the JSON's hold every run
inline void run_verdict_rows(ExperimentContext& ctx) {
  const SummaryPair c = summary_pair(ctx);
  if (!c.ok()) return;
  for (const auto& g : kT1)
    for (const auto& collider : {c.is, c.os}) t1_run(ctx, g, {collider}, "papers", ctx.quick() ? 1 : kVerdictRuns);
}

// a run's collision time per iteration [ms] over every run of its configuration
inline Spread cdr_spread(const ExperimentContext& ctx, const RunResult& r) {
  std::vector<double> ms;
  for (const RunResult* each : ctx.repetitions_of(r)) ms.push_back(each->cdr_ms_per_iteration());
  return spread(ms);
}
// "0.18 ms (0.17-0.19, 5 runs)" or "0.18 ms (one run)"
inline std::string spread_text(const Spread& s, int digits) {
  return num(s.median, digits) + " ms (" +
         (s.runs > 1 ? num(s.lo, digits) + "-" + num(s.hi, digits) + ", " + std::to_string(s.runs) + " runs"
                     : std::string("one run")) +
         ")";
}

}  // namespace clothbench::paper_tables
