// integrators: the shirt, dress and skirt dressed on the static body with each integrator (Durupinar
// section 3: explicit Euler, implicit Euler, adaptive Runge-Kutta) and the papers' regime, image space
// against object space: dt, iterations, wall time to dressed-and-settled, accuracy (issue: the papers' clock).
#include <string>
#include <vector>

#include "clothbench/bench/report.hpp"
#include "clothbench/experiments/experiment.hpp"
#include "clothbench/experiments/paper_figures.hpp"
#include "clothbench/experiments/statistics.hpp"
#include "experiment_list.hpp"

namespace clothbench {

namespace {

struct Garment {
  const char* product;
  const char* scene;
  int vertices;
  int paper_iterations;  // the papers' image-space count (dressing Table 1, skirt: Table 2)
};

struct Solver {
  const char* integrator;
  const char* regime;
  bool papers_limit = false;   // the papers' regime's velocity modification on the regime's springs
  int limit_passes = 0;        // the regime's passes of its limit unless set
  const char* skin = nullptr;  // body.skin_mm, when set
};

// the papers' regime's limit settings (apply_regime): at a step of milliseconds one pass of the
// regime's velocity limit leaves the shoulders 50 % stretched (implicit Euler, shirt)
const char* const kPapersLimit[] = {"solver.limit=directional", "solver.limit_passes=32",
                                    "solver.limit_after_response=true"};

std::string regime_label(const Solver& s) {
  return std::string(s.regime) + (s.papers_limit ? " + papers' limit" : "") +
         (s.limit_passes ? ", " + std::to_string(s.limit_passes) + " limit passes" : "") +
         (s.skin ? ", " + std::string(s.skin) + " mm skin" : "");
}

// the rows' overrides: garment size, solver, and the quick run's cap
std::vector<std::string> overrides(const ExperimentContext& ctx, const Garment& g, const Solver& s) {
  std::vector<std::string> sets{"garment.vertices=" + std::to_string(ctx.quick() ? 150 : g.vertices),
                                "stop.drape_max_s=2", std::string("solver.regime=") + s.regime,
                                std::string("solver.integrator=") + s.integrator};
  if (s.papers_limit) sets.insert(sets.end(), std::begin(kPapersLimit), std::end(kPapersLimit));
  if (s.limit_passes) sets.push_back("solver.limit_passes=" + std::to_string(s.limit_passes));
  if (s.skin) sets.push_back(std::string("body.skin_mm=") + s.skin);
  if (ctx.quick()) sets.push_back("stop.max_iterations=40");
  return sets;
}

// one row's outcome: diverged (when, where, why), or its iterations and the limits' verdict
std::string outcome(const RunResult& r) {
  if (r.divergence)
    return "diverged at iteration " + std::to_string(r.divergence->iteration) + " (" + to_string(r.divergence->phase) +
           ", vertex " + std::to_string(r.divergence->vertex) + ": " + r.divergence->reason + ")";
  return std::to_string(r.sew.iterations) + " + " + std::to_string(r.drape.iterations) + " iterations, " +
         (r.sew.reached ? "sewn" : "not sewn") + ", " + (r.drape.reached ? "settled" : "not settled") +
         "; strain max " + num(100 * r.strain_max, 1) + " %; " + limits_cell(r);
}

// where explicit Euler stops: the papers' regime's springs (as soft as Eq. 4 and Gershgorin need at 5 ms)
// kept while dt grows past their bounds, beside implicit Euler with the stable regime's 60 N/m springs
std::string step_sweep(ExperimentContext& ctx, const Garment& g, const std::vector<std::string>& colliders) {
  const std::string collider = colliders.front();
  const auto base = [&](const char* integrator, const char* regime) {
    return overrides(ctx, g, {integrator, regime, std::string(integrator) == "implicit-euler"});
  };
  const RunResult& papers = ctx.run(g.scene, collider, base("explicit-euler", "papers"));
  const double k = papers.k_structural;
  MarkdownTable t({"dt [ms]", "dt / Eq. 4 bound", "dt / Gershgorin bound",
                   "explicit Euler, papers' regime springs (" + num(k, 3) + " N/m structural)",
                   "implicit Euler, 60 N/m (stable regime's springs and masses, papers' limit)"});
  for (const double dt_ms : {5.0, 6.0, 7.0, 8.0, 10.0, 15.0, 20.0}) {
    const std::string dt = "solver.dt=" + num(dt_ms / 1e3, 4);
    std::vector<std::string> ex = base("explicit-euler", "papers");
    for (const std::string& o : {dt, std::string("solver.allow_unstable_dt=true"), "material.k_structural=" + num(k, 6),
                                 "material.k_shear=" + num(k / 3, 6), "material.k_flexion=" + num(k / 6, 6)})
      ex.push_back(o);
    std::vector<std::string> im = base("implicit-euler", "stable");
    im.push_back(dt);
    const RunResult& e = ctx.run(g.scene, collider, ex);
    const RunResult& i = ctx.run(g.scene, collider, im);
    ctx.add_run(e, "integrators-dt/" + std::string(g.product) + "/explicit-euler/papers/" + num(dt_ms, 0));
    ctx.add_run(i, "integrators-dt/" + std::string(g.product) + "/implicit-euler/stable+papers-limit/" + num(dt_ms, 0));
    t.row({num(dt_ms, 1), num(e.dt_s / e.dt_bound_s, 2), num(e.dt_s / e.dt_spectral_s, 2), outcome(e), outcome(i)});
  }
  return "### Where explicit Euler diverges (" + std::string(g.product) + ", " + std::to_string(papers.vertices) +
         " vertices, " + collider +
         ")\n\nThe papers' regime's springs are made for 5 ms (equal point masses, as soft as Eq. 4 and Gershgorin "
         "need at dt / 0.9); here they are kept while dt grows, with `allow_unstable_dt` (Eq. 4 would refuse the "
         "larger "
         "steps). Implicit Euler runs the stable regime's 60/20/10 N/m springs (its point masses equal too) at the "
         "same steps. Bounds are those of the explicit row's springs and masses.\n\n" +
         t.str();
}

// what sets our sewing count in the papers' regime: partners of a seam approach each other at seam_speed at
// most (cap_seam_speeds), so the count is about the widest gap over seam_speed dt; the paper gives neither
std::string sew_speed_sweep(ExperimentContext& ctx, const std::vector<Garment>& garments, const std::string& collider) {
  const double speeds[] = {0.5, 1.0, 2.0};
  std::vector<std::string> head{"garment", "vertices", "paper iterations (IS)"};
  for (const double v : speeds) head.push_back("to sew at seam_speed " + num(v, 1) + " m/s (ours/paper)");
  MarkdownTable t(head);
  for (const Garment& g : garments) {
    std::vector<std::string> row{g.product, std::to_string(ctx.quick() ? 150 : g.vertices),
                                 std::to_string(g.paper_iterations)};
    for (const double v : speeds) {
      std::vector<std::string> sets = overrides(ctx, g, {"explicit-euler", "papers"});
      sets.push_back("solver.seam_speed=" + num(v, 2));
      sets.push_back("stop.drape_max_s=0");
      const RunResult& r = ctx.run(g.scene, collider, sets);
      ctx.add_run(r, "integrators-sew/" + std::string(g.product) + "/seam_speed-" + num(v, 1));
      row.push_back(r.sew.reached ? std::to_string(r.sew.iterations) + " (" +
                                        num(double(r.sew.iterations) / g.paper_iterations, 2) + "x)"
                                  : "not sewn (" + std::to_string(r.sew.iterations) + ")");
    }
    t.row(row);
  }
  return "### What sets the sewing count (papers' regime, " + collider +
         ", sewing only)\n\nOur sewing phase in the papers' regime takes fewer iterations than the papers' counts "
         "(above). Partners of a seam approach each other no faster than `solver.seam_speed` (2 m/s by default, 1 cm "
         "per 5 ms step), so "
         "the count is about the widest placement gap over seam_speed x dt; the paper states neither its dt, its "
         "seam force nor its placement distances. The same runs at half and a quarter of that speed:\n\n" +
         t.str();
}

// the wall times to dressed of every run of the request that returned r
Spread wall_spread(const ExperimentContext& ctx, const RunResult& r) {
  std::vector<double> s;
  for (const RunResult* each : ctx.repetitions_of(r)) s.push_back(each->dressed_wall_s());
  return spread(s);
}

// "0.340" or "0.340 (median of 5 runs, 0.312-0.371)"
std::string wall_text(const Spread& s) { return num(s.median, 3) + (s.runs > 1 ? " (" + runs_text(s, 3) + ")" : ""); }

// per garment: the quickest row to dressed within every limit (by its runs' median), and the quickest of all with
// what it misses
struct Quickest {
  std::string within, any;
  Spread within_s, any_s;
  void offer(const std::string& label, const Spread& wall, const RunResult& r) {
    if (r.divergence) return;
    if (limit_misses(r).empty() && (within.empty() || wall.median < within_s.median)) within = label, within_s = wall;
    if (any.empty() || wall.median < any_s.median) any = label + ", " + limits_cell(r), any_s = wall;
  }
};

// the rows within every limit whose one run took at most 1 / kContender of the quickest such row's wall time (per
// garment) run kVerdictRuns times: the summary's quickest and the targets' verdict are chosen by their median
// (--quick: no repetitions)
constexpr double kContender = 0.75;

// the page's opening lines: the papers' counts, our quickest dressing within every limit, the verdict
std::vector<std::string> summary(const std::vector<Garment>& garments, const std::vector<Quickest>& quickest) {
  std::vector<std::string> lines{
      "The papers: explicit Euler at a fixed step, the stretch held by velocity "
      "modification; image space sews the shirt in " +
      std::to_string(garments[0].paper_iterations) + " iterations and the dress in " +
      std::to_string(garments[1].paper_iterations) + " (dressing Table 1)."};
  std::string
      within =
          "Ours, the quickest to dressed within every limit, strain included (set-up included; the rows near the "
          "quickest run " +
          std::to_string(kVerdictRuns) + " times, the others once):",
      any = "The quickest of all rows and what it misses:";
  for (std::size_t i = 0; i < garments.size(); ++i) {
    const Quickest& q = quickest[i];
    within +=
        std::string(i ? ";" : "") + " " + garments[i].product + " " +
        (q.within.empty() ? std::string("none")
                          : num(q.within_s.median, 3) + " s (" + q.within + "; " + runs_text(q.within_s, 3) + ")");
    any += std::string(i ? ";" : "") + " " + garments[i].product + " " + num(q.any_s.median, 3) + " s (" + q.any +
           "; " + runs_text(q.any_s, 3) + ")";
  }
  lines.push_back(within + ".");
  lines.push_back(any + ".");
  const auto target = [&](std::size_t i, double s) {
    const Quickest& q = quickest[i];
    return std::string(garments[i].product) + " " +
           (q.within.empty() ? "none within the limits" : num(q.within_s.median, 3) + " s") + " against " + num(s, 1) +
           " s: " + (!q.within.empty() && q.within_s.median <= s ? "met" : "not met");
  };
  lines.push_back("Verdict, the targets for dressing within every limit on one thread: " + target(0, 0.1) + "; " +
                  target(1, 0.3) + ".");
  return lines;
}

// the table's columns: what ran, then its outcome
MarkdownTable integrators_table() {
  return MarkdownTable({"garment",
                        "integrator",
                        "regime",
                        "collider",
                        "vertices",
                        "dt [ms]",
                        "iterations (sew + drape)",
                        "paper iterations (IS)",
                        "ours/paper (sew; all)",
                        "sewn",
                        "settled",
                        "wall to dressed [s] (set-up incl.)",
                        "ms/iteration (CD&R + CS; of CS the limits)",
                        "inside [%]",
                        "depth max [mm]",
                        "crossings [%]",
                        "seam gap [mm]",
                        "strain max / p99 [%]",
                        "springs over the strain limit [%]",
                        "largest strain at",
                        "meets the limits"});
}

// one row of the table: what ran, then its outcome (a diverged run has no accuracy)
std::vector<std::string> row_cells(const Garment& g, const Solver& s, const std::string& collider, const RunResult& r,
                                   const Spread& wall) {
  const long its = r.sew.iterations + r.drape.iterations;
  std::vector<std::string> cells{
      g.product, s.integrator, regime_label(s), collider, std::to_string(r.vertices), num(1e3 * r.dt_s, 3)};
  const auto add = [&](std::initializer_list<std::string> more) { cells.insert(cells.end(), more); };
  if (r.divergence) {
    add({"diverged at " + std::to_string(r.divergence->iteration), std::to_string(g.paper_iterations), "-", "-", "-",
         wall_text(wall), num(r.ms_per_iteration(), 3)});
    cells.resize(cells.size() + 7, "-");  // inside, depth, crossings, seam gap, strain, over, where
    add({"no: diverged"});
    return cells;
  }
  add({std::to_string(r.sew.iterations) + " + " + std::to_string(r.drape.iterations),
       std::to_string(g.paper_iterations),
       num(double(r.sew.iterations) / g.paper_iterations, 1) + "; " + num(double(its) / g.paper_iterations, 1),
       r.sew.reached ? "yes" : "no", r.drape.reached ? "yes" : "no", wall_text(wall),
       num(r.ms_per_iteration(), 3) + " (" + num(r.cdr_ms_per_iteration(), 3) + " + " +
           num(r.cs_ms_per_iteration(), 3) + "; " + num(r.limit_ms_per_iteration(), 3) + ")",
       num(r.accuracy.inside_pct, 2), num(r.accuracy.depth_max_mm, 1), num(r.accuracy.crossings_pct, 2),
       num(r.seam_gap_max_mm, 1), num(100 * r.strain_max, 1) + " / " + num(100 * r.strain_p99, 1),
       num(100 * r.strain_over, 2), r.strain_max_where, limits_cell(r)});
  return cells;
}

// the page's text above the table
std::string description() {
  return "Each garment sewn and draped on the static body (scenes/dressing/*.toml, their other settings as "
         "committed: limit threshold 10 %, the skirt with face queries) at the papers' sizes, with each "
         "integrator (`solver.integrator`) in the stable regime (automatic dt: explicit Euler and rk45 at 0.9 x "
         "min(Eq. 4, Gershgorin) over the actual point masses, implicit Euler 10 ms with the papers' limit settings: "
         "directional, 32 passes, again after the response; the projective solve, Liu et al. 2013 beyond the papers, "
         "5 ms, 2 local/global iterations, the body answered 1 mm thicker, `body.skin_mm`: at steps of milliseconds a "
         "step slides resting cloth a fraction of a millimetre into a curved surface) and explicit Euler in the "
         "papers' regime (`solver.regime = \"papers\"`: equal point masses, dt 5 ms, springs as soft as Eq. 4 "
         "and Gershgorin need at that dt, the stretch held by the directional velocity limit, 32 passes). The "
         "stable regime's limit is `impulses` (walking Eq. 5 as accumulated impulses warm-started from the last step, "
         "after "
         "Catto 2005), 1 pass, run again after the collision response. "
         "Wall time is one thread, collider set-up included, until sewn and settled or the phase budgets (1 s + 2 s "
         "simulated) run out. A row within every limit whose one run came within a factor " +
         num(1 / kContender, 2) + " of the quickest such row of its garment runs " + std::to_string(kVerdictRuns) +
         " times: its wall time is the median of the runs with their range (the summary and the targets' verdict "
         "judge the median), its other timings the run with the median ms/iteration; every other row is one run. "
         "Runs are deterministic, so the repetitions differ in their times only. The papers' iteration counts are "
         "their "
         "image-space rows (dressing Table 1 for shirt and dress, Table 2 for the skirt at 336 vertices and the "
         "trousers at 560, here 600, which does not state dt); Table 1's are counts \"to sew a shirt and a dress\" "
         "(dressing section 7), so ours/paper gives the sewing phase's ratio first and the whole run's (sew and drape "
         "to settled) second. A row \"4 limit passes\" runs the papers' regime with four limit passes instead of 32: "
         "the strain left when the limit's Gauss-Seidel sweep is not given the passes to converge, and what the "
         "passes cost; a row \"stable, 2 limit passes\" the stable regime with two passes of its limit instead of "
         "one. The table gives each integrator's wall time to dressed as ms/iteration times iterations (CD&R = "
         "collider query and response, CS = forces, integration, limits and "
         "seaming, and of CS the velocity limits' passes alone). \"Largest strain at\" names the most stretched "
         "structural spring at the end: how high it is, "
         "and how many of its ends the body holds (in contact) or a seam joins, the measured reason a row misses "
         "the strain limit.\n\n";
}

// one row of the table: a garment (index into the page's list), a solver and a collider
struct Row {
  std::size_t garment;
  const Solver* solver;
  std::string collider;
};

// the rows within every limit near the quickest such row of their garment run kVerdictRuns times (kContender)
void repeat_contenders(ExperimentContext& ctx, const std::vector<Garment>& garments, const std::vector<Row>& rows) {
  if (ctx.quick()) return;
  const auto wall_within = [&](const Row& w) {
    const RunResult& r = ctx.run(garments[w.garment].scene, w.collider, overrides(ctx, garments[w.garment], *w.solver));
    return !r.divergence && limit_misses(r).empty() ? r.dressed_wall_s() : -1.0;
  };
  std::vector<double> quickest(garments.size(), -1);
  for (const Row& w : rows) {
    const double s = wall_within(w);
    double& q = quickest[w.garment];
    if (s >= 0 && (q < 0 || s < q)) q = s;
  }
  for (const Row& w : rows) {
    const double s = wall_within(w);
    if (s >= 0 && kContender * s <= quickest[w.garment])
      ctx.run(garments[w.garment].scene, w.collider, overrides(ctx, garments[w.garment], *w.solver), {}, kVerdictRuns);
  }
}

void integrators(ExperimentContext& ctx) {
  const std::vector<Garment> garments = {{"shirt", "dressing/shirt.toml", 1800, paper::kDressingT1[0].iterations},
                                         {"dress", "dressing/dress.toml", 3840, paper::kDressingT1[2].iterations},
                                         {"skirt", "dressing/skirt.toml", 336, paper::kDressingT2[0].iterations},
                                         {"trousers", "dressing/trousers.toml", 600, paper::kDressingT2[1].iterations}};
  // the papers' regime again with four limit passes instead of 32: the strain left when the Gauss-Seidel
  // sweep is not given the passes to converge; the stable regime with two passes of its limit, not one: what a
  // second pass holds (the dress's shoulders) and costs
  const Solver solvers[] = {{"explicit-euler", "stable"},       {"explicit-euler", "stable", false, 2},
                            {"explicit-euler", "papers"},       {"explicit-euler", "papers", false, 4},
                            {"implicit-euler", "stable", true}, {"rk45", "stable"},
                            {"projective", "stable", false, 0, "1"}};
  std::vector<Row> rows;
  for (const Solver& s : solvers)
    // one collider of each family, the lead ones: the solvers are compared, not the colliders
    for (const std::string& collider : ctx.colliders({"is-cpu", "embree"}))
      for (std::size_t gi = 0; gi < garments.size(); ++gi) rows.push_back({gi, &s, collider});
  repeat_contenders(ctx, garments, rows);
  MarkdownTable t = integrators_table();
  nlohmann::json series = nlohmann::json::array();
  std::vector<Quickest> quickest(garments.size());
  std::vector<double> x, y;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const Row& w = rows[i];
    const Garment& g = garments[w.garment];
    const Solver& s = *w.solver;
    const RunResult& r = ctx.run(g.scene, w.collider, overrides(ctx, g, s));
    const std::string label = std::string(s.integrator) + " / " + regime_label(s) + " / " + w.collider;
    ctx.add_run(r, "integrators/" + std::string(g.product) + "/" + label);
    const Spread wall = wall_spread(ctx, r);
    quickest[w.garment].offer(label, wall, r);
    t.row(row_cells(g, s, w.collider, r, wall));
    if (!r.divergence) x.push_back(wall.median), y.push_back(100 * r.strain_p99);
    // a series per solver and collider: the garments' rows
    if (w.garment + 1 == garments.size()) {
      series.push_back({{"label", std::string(s.integrator) + " " + regime_label(s) + " " + w.collider},
                        {"x", x},
                        {"y", y},
                        {"style", "o"}});
      x.clear(), y.clear();
    }
  }
  const std::string sweep = step_sweep(ctx, garments[0], ctx.colliders({"is-cpu", "embree"})) + "\n\n" +
                            sew_speed_sweep(ctx, garments, ctx.colliders({"is-cpu", "embree"}).front());
  ctx.chart("integrators",
            {{"title", "Dressing (shirt, dress, skirt, trousers): wall time against strain"},
             {"xlabel", "wall time to dressed and settled, set-up included (median run where repeated) [s]"},
             {"ylabel", "strain p99 at the end [%]"},
             {"logx", true},
             {"series", series}});
  ctx.write("integrators", "Integrators and the papers' clock",
            description() + t.str() + "\n![chart](integrators.png)\n\n" + sweep, summary(garments, quickest));
}

}  // namespace

void add_integrators_experiments(std::vector<Experiment>& out) {
  out.push_back({"integrators", "Integrators and the papers' clock", integrators});
}

}  // namespace clothbench
