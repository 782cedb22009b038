// limiters: the strain-limiter family (sim/src/limiters/) against each other: each member at a few pass counts on
// the shirt and the dress dressed on the static body and on the skirt and the dress with sleeves walking, at the
// papers' clock (where the limiter alone holds the stretch) and in our stable regime: strain (worst frame when
// walking), the other accuracy limits, what the limiter costs a step and its share of the step.
#include <algorithm>
#include <string>
#include <vector>

#include "clothbench/bench/report.hpp"
#include "clothbench/experiments/experiment.hpp"
#include "experiment_list.hpp"

namespace clothbench {

namespace {

struct Case {
  const char* garment;
  const char* scene;
  int vertices;
  const char* clip;  // empty: the static body
};

// every limiter but none and stiff (whose figures are those of the cloth's own springs)
const char* const kLimits[] = {"velocity-zero", "velocity", "directional", "directional-literal",
                               "position",      "tethers",  "follow",      "projection",
                               "impulses"};

struct Setting {
  const char* regime;
  const char* limit;
  int passes;
  bool after = false;  // the stable regime's limit run again after the collision response (the papers' always is)
};

// --quick runs each limiter's code path once a case: a setting that differs from an earlier one of the case only in
// its pass count adds none
bool repeats_a_code_path(const std::vector<Setting>& settings, const Setting& s) {
  for (const Setting& earlier : settings) {
    if (&earlier == &s) return false;
    if (std::string(earlier.regime) == s.regime && std::string(earlier.limit) == s.limit && earlier.after == s.after)
      return true;
  }
  return false;
}

// the row's name: limiters/GARMENT/CLIP/REGIME/LIMIT/PASSES
std::string row_name(const Case& c, const Setting& s) {
  return std::string("limiters/") + c.garment + "/" + (*c.clip ? c.clip : "static") + "/" + s.regime + "/" + s.limit +
         "/" + std::to_string(s.passes) + (s.after ? "/after" : "");
}

std::vector<std::string> overrides(const ExperimentContext& ctx, const Case& c, const Setting& s) {
  std::vector<std::string> sets{"garment.vertices=" + std::to_string(ctx.quick() ? 150 : c.vertices),
                                std::string("solver.regime=") + s.regime, std::string("solver.limit=") + s.limit,
                                "solver.limit_passes=" + std::to_string(s.passes)};
  // explicit, as the walking scenes set it: the papers' regime runs the limit again after the response, the
  // stable one only where the setting asks
  const bool after = s.after || std::string(s.regime) == "papers";
  sets.push_back(std::string("solver.limit_after_response=") + (after ? "true" : "false"));
  if (*c.clip) sets.push_back(std::string("body.animation=") + c.clip);
  if (!*c.clip) sets.push_back("stop.drape_max_s=2");
  if (ctx.quick()) sets.push_back(*c.clip ? "body.end_s=1.1" : "stop.max_iterations=40");
  return sets;
}

// what one row measured, for the table, the chart and the summary
struct Measured {
  const Case* c;
  Setting s;
  bool ok = false;        // ran to its end without diverging
  bool meets = false;     // every accuracy limit (every frame when walking)
  double strain_pct = 0;  // the largest structural strain (at any frame when walking) [%]
  double limit_ms = 0;    // the limiter per step [ms]
  double share = 0;       // of the step (CD&R + CS)
  double step_ms = 0;
  double speed = 0;     // frames/s walking, else wall time to dressed [s]
  std::string verdict;  // limits_cell: "yes", or what it misses
};

// whether the stable regime runs the limiter again after the response, as words after its name
std::string after_words(const Setting& s) { return s.after ? ", again after the response" : ""; }

// the limiter's name, and whether the stable regime runs it again after the response
std::string limit_label(const Setting& s) { return std::string(s.limit) + after_words(s); }

std::vector<std::string> row_cells(const Measured& m, const RunResult& r) {
  const bool walking = *m.c->clip;
  std::vector<std::string> cells{m.c->garment,     walking ? m.c->clip : "static", m.s.regime,
                                 limit_label(m.s), std::to_string(m.s.passes),     std::to_string(r.vertices)};
  if (!m.ok) {
    const std::string why = r.divergence ? "diverged at iteration " + std::to_string(r.divergence->iteration) + " (" +
                                               to_string(r.divergence->phase) + ")"
                                         : "not dressed";
    cells.insert(cells.end(), {why, "-", "-", "-", "-", "-", "-", "-", "no: " + why});
    return cells;
  }
  const double p99 = walking ? r.frame_max(&FrameSample::strain_p99) : r.strain_p99;
  const double inside = walking ? r.frame_max(&FrameSample::inside_pct) : r.accuracy.inside_pct;
  const double depth = walking ? r.frame_max(&FrameSample::depth_max_mm) : r.accuracy.depth_max_mm;
  const double crossings = walking ? r.frame_max(&FrameSample::crossings_pct) : r.accuracy.crossings_pct;
  cells.insert(cells.end(), {num(m.strain_pct, 1) + " / " + num(100 * p99, 1), num(100 * r.strain_over, 2),
                             num(inside, 2) + " / " + num(depth, 1) + " / " + num(crossings, 2), num(m.limit_ms, 3),
                             num(100 * m.share, 0), num(m.step_ms, 3), walking ? num(m.speed, 1) : num(m.speed, 3),
                             std::to_string(r.iterations()), limits_cell(r)});
  return cells;
}

Measured measure(const Case& c, const Setting& s, const RunResult& r) {
  Measured m{&c, s};
  const bool walking = *c.clip;
  m.ok = !r.divergence && (!walking || r.frames > 0);
  if (!m.ok) return m;
  m.meets = limit_misses(r).empty();
  m.verdict = limits_cell(r);
  m.strain_pct = 100 * (walking ? r.animate_strain_max : r.strain_max);
  m.limit_ms = r.limit_ms_per_iteration();
  m.step_ms = r.ms_per_iteration();
  m.share = m.step_ms > 0 ? m.limit_ms / m.step_ms : 0;
  m.speed = walking ? double(r.frames) / (r.animate.wall_ms / 1e3) : r.dressed_wall_s();
  return m;
}

// the walking paper's advice (walking 3.2: Eq. 5 on a static body, Eq. 6 on a moving one) against this run: Eq. 5
// and Eq. 6 side by side at the papers' clock, 32 passes, on each case
std::string advice(const std::vector<Measured>& rows) {
  const auto find = [&](const Case* c, const char* limit) -> const Measured* {
    for (const Measured& m : rows)
      if (m.c == c && std::string(m.s.regime) == "papers" && std::string(m.s.limit) == limit && m.s.passes == 32)
        return &m;
    return nullptr;
  };
  const auto cell = [](const Measured* m) {
    if (!m) return std::string("not run");
    if (!m->ok) return std::string("diverged");
    return "strain " + num(m->strain_pct, 1) + " %, meets the limits: " + m->verdict;
  };
  std::string out;
  std::vector<const Case*> seen;
  for (const Measured& m : rows) {
    if (std::find(seen.begin(), seen.end(), m.c) != seen.end()) continue;
    seen.push_back(m.c);
    const Measured *eq5 = find(m.c, "velocity"), *eq6 = find(m.c, "directional");
    if (!eq5 && !eq6) continue;
    out += std::string("- ") + m.c->garment + ", " + (*m.c->clip ? m.c->clip : "static body") + ": Eq. 5 " + cell(eq5) +
           "; Eq. 6 " + cell(eq6) + "\n";
  }
  return out;
}

// per case and regime, the cheapest limiter setting that meets every limit (or that none does)
std::string cheapest(const std::vector<Measured>& rows) {
  std::string out;
  std::vector<std::pair<const Case*, std::string>> seen;
  for (const Measured& m : rows) {
    const auto key = std::make_pair(m.c, std::string(m.s.regime));
    if (std::find(seen.begin(), seen.end(), key) != seen.end()) continue;
    seen.push_back(key);
    const Measured* best = nullptr;
    for (const Measured& n : rows)
      if (n.c == m.c && std::string(n.s.regime) == m.s.regime && n.meets && (!best || n.limit_ms < best->limit_ms))
        best = &n;
    out +=
        std::string("- ") + m.c->garment + ", " + (*m.c->clip ? m.c->clip : "static body") + ", " + m.s.regime + ": " +
        (best ? std::string("`") + best->s.limit + "`" + after_words(best->s) + ", " + std::to_string(best->s.passes) +
                    (best->s.passes == 1 ? " pass, " : " passes, ") + num(best->limit_ms, 3) + " ms a step (" +
                    num(100 * best->share, 0) + " % of the step), strain " + num(best->strain_pct, 1) + " %"
              : std::string("no setting measured here meets every limit")) +
        "\n";
  }
  return out;
}

// the page's opening lines: what the papers ask of the limiter, ours per regime, the verdict on its share of a step
std::vector<std::string> summary(const std::vector<Measured>& rows, std::size_t cases) {
  std::vector<std::string> lines{
      "The papers: velocity modification holds the stretch of soft springs at a fixed step of the papers' clock "
      "(dressing section 4, walking section 3); they give no figure for its cost."};
  for (const char* regime : {"papers", "stable"}) {
    int meets = 0, all = 0;
    const Measured* least = nullptr;
    for (const Measured& m : rows) {
      if (std::string(m.s.regime) != regime) continue;
      ++all;
      if (!m.meets) continue;
      ++meets;
      if (!least || m.share < least->share) least = &m;
    }
    lines.push_back(std::string("Ours, ") +
                    (regime == std::string("papers") ? "the papers' clock" : "our stable regime") + ", one run each: " +
                    std::to_string(meets) + " of " + std::to_string(all) + " rows meet every limit, strain included" +
                    (least ? "; the smallest limiter share among them " + num(100 * least->share, 0) +
                                 " % of the step (`" + least->s.limit + "`, " + std::to_string(least->s.passes) +
                                 (least->s.passes == 1 ? " pass, " : " passes, ") + least->c->garment + ", " +
                                 (*least->c->clip ? least->c->clip : "static body") + ")"
                           : std::string()) +
                    ".");
  }
  // cases with a setting within every limit at most a quarter of the step, per regime
  const auto quarter = [&](const char* regime) {
    std::vector<const Case*> seen;
    for (const Measured& m : rows)
      if (std::string(m.s.regime) == regime && m.meets && m.share <= 0.25 &&
          std::find(seen.begin(), seen.end(), m.c) == seen.end())
        seen.push_back(m.c);
    return std::to_string(seen.size()) + " of the " + std::to_string(cases) + " garment and body cases";
  };
  lines.push_back(
      "Verdict: the target, a limiter within every limit at most a quarter of the step at the papers' "
      "clock, is met in " +
      quarter("papers") + "; in our stable regime (beside the target) in " + quarter("stable") + ".");
  return lines;
}

// the garments and bodies, each with its settings. The papers' clock: every method at 1, 4 and 32 passes on the
// shirt, the main ones at 4 and 32 (the projection at 4, 8 and 16) on the other garments; the stable regime: its one
// pass and eight; the second clip: the fullest settings only; in the stable regime Eq. 5 again after the response
// too (its default: impulses, 1 pass)
std::vector<std::pair<Case, std::vector<Setting>>> limiter_cases() {
  std::vector<Setting> papers_all, papers_main, stable;
  for (const char* limit : kLimits)
    for (int passes : {1, 4, 32}) papers_all.push_back({"papers", limit, passes});
  for (const char* limit : {"velocity", "directional", "tethers", "follow"})
    for (int passes : {4, 32}) papers_main.push_back({"papers", limit, passes});
  // the projection's passes are Newton iterations: it converges in fewer
  for (int passes : {4, 8, 16}) papers_main.push_back({"papers", "projection", passes});
  // (tethers in the stable regime: found again at nearly every one of its short steps, they cost more than the
  // step; the papers' clock measures them)
  for (const char* limit : {"velocity", "directional"})
    for (int passes : {1, 8}) stable.push_back({"stable", limit, passes});
  stable.push_back({"stable", "velocity", 8, true});
  // the warm-started impulses: one pass, once a step and again after the response, and two
  const std::vector<Setting> impulses{
      {"stable", "impulses", 1}, {"stable", "impulses", 1, true}, {"stable", "impulses", 2, true}};
  stable.insert(stable.end(), impulses.begin(), impulses.end());
  const auto join = [](std::vector<Setting> a, const std::vector<Setting>& b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
  };
  // walking: Eq. 5's sweeps after the response at 8 and 16 passes (the walking skirt's setting), and the regime's
  // warm-started impulses at one, two, three and four (the walking dress's)
  const std::vector<Setting> walking_after{{"stable", "velocity", 8, true},  {"stable", "velocity", 16, true},
                                           {"stable", "impulses", 1, true},  {"stable", "impulses", 2, true},
                                           {"stable", "impulses", 3, true},  {"stable", "impulses", 4, true}};
  const std::vector<Setting> second_clip = join({{"papers", "velocity", 32},
                                                 {"papers", "tethers", 32},
                                                 {"papers", "projection", 8},
                                                 {"stable", "directional", 8}},
                                                walking_after);
  return {{{"shirt", "dressing/shirt.toml", 1800, ""}, join(papers_all, stable)},
          {{"dress", "dressing/dress.toml", 2300, ""}, join(papers_main, stable)},
          {{"skirt", "walking/skirt.toml", 672, "walk_07_01"},
           join(join(papers_main, stable), {{"stable", "velocity", 16, true}})},
          {{"dress with sleeves", "walking/dress_sleeves.toml", 2300, "walk_07_01"},
           join(join(papers_main, {{"stable", "directional", 1}, {"stable", "directional", 8}}), walking_after)},
          {{"skirt", "walking/skirt.toml", 672, "walk_08_02"}, second_clip},
          {{"dress with sleeves", "walking/dress_sleeves.toml", 2300, "walk_08_02"}, second_clip}};
}

// the chart: strain against the limiter's cost, one series per limiter at the papers' clock
nlohmann::json chart_series(const std::vector<Measured>& rows) {
  nlohmann::json series = nlohmann::json::array();
  for (const char* limit : kLimits) {
    std::vector<double> x, y;
    for (const Measured& m : rows)
      if (m.ok && std::string(m.s.limit) == limit && std::string(m.s.regime) == "papers")
        x.push_back(std::max(m.limit_ms, 1e-4)), y.push_back(std::max(m.strain_pct, 1e-2));
    if (!x.empty()) series.push_back({{"label", limit}, {"x", x}, {"y", y}, {"style", "o"}});
  }
  return series;
}

// the page's text above the table
std::string description(const std::string& collider, const std::vector<Measured>& rows) {
  return "Every strain limiter of `solver.limit` (scenes/README.md; dressing section 4, walking section 3, and four "
         "methods beyond the papers: `tethers`, long-range attachments after Kim, Chentanez and Mueller 2012, "
         "`follow`, follow the leader after Mueller, Kim and Chentanez 2012, `projection`, fast projection of the "
         "structural springs after Goldenthal et al. 2007, its passes Newton iterations, and `impulses`, walking Eq. 5 "
         "on the structural springs as accumulated impulses warm-started from the last step, the body's contacts in "
         "the same solve, after Catto 2005) at a few pass counts "
         "(`solver.limit_passes`, the most per call), with " +
         collider +
         ": the shirt and the dress sewn and draped on the static body, and the skirt and the dress with sleeves "
         "dressed and walking in place for two seconds on both clips (scenes/walking/*.toml), at the papers' clock "
         "(`solver.regime = papers`: dt 5 ms, equal point masses, springs as soft as that dt allows, so that the "
         "limiter alone holds the stretch; the limit runs again after the response) and in our stable regime (its "
         "stiff springs at the automatic dt; the limit once per step unless the row says it runs again after the "
         "collision response, `solver.limit_after_response`, as the walking scenes set it). Strain is the largest "
         "structural strain at the end (static) or at any "
         "frame (walking; p99 the worst frame's 99th percentile); inside, depth and crossings the end state's or the "
         "worst frame's; the limiter's ms a step and its share of the step (CD&R + CS, walk_*: the cloth's steps, "
         "not the frame's skinning and maps); frames/s is the whole animation phase's wall time (skinning, maps, "
         "cloth) on one thread. A row meets the limits when it meets every one of them (every frame when walking), "
         "strain at most threshold + 1 % included.\n\nThe cheapest setting measured that meets every limit, per "
         "garment and body:\n\n" +
         cheapest(rows) +
         "\nThe walking paper's advice (section 3.2: Eq. 5, `velocity`, on a static body, Eq. 6, `directional`, on "
         "a moving one) beside this run, at the papers' clock with 32 passes (the regime's default is `directional` "
         "on both bodies; walking-t2's rows at that clock run `velocity`; the stable regime's default is `impulses`, 1 "
         "pass, again after the response, the walking dress's 4 passes, the walking skirt's `velocity`, 16):\n\n" +
         advice(rows) + "\n";
}

void limiters(ExperimentContext& ctx) {
  const auto cases = limiter_cases();
  const std::string collider = ctx.colliders({"is-cpu"}).front();  // the limiters are compared, on one collider
  MarkdownTable t({"garment", "body", "regime", "limiter", "passes", "vertices", "strain max / p99 [%]",
                   "springs over the strain limit [%] (end)", "inside [%] / depth [mm] / crossings [%]",
                   "limiter ms/step", "limiter share of the step [%]", "ms/step (CD&R + CS)",
                   "frames/s (walking) or wall to dressed [s]", "iterations", "meets the limits"});
  std::vector<Measured> rows;
  for (const auto& [c, settings] : cases) {
    // --quick: the code paths once (the second clip adds none, as in walking-t2)
    if (ctx.quick() && std::string(c.clip) == "walk_08_02") continue;
    RunOptions options;
    options.measure_frames = *c.clip;
    for (const Setting& s : settings) {
      if (ctx.quick() && repeats_a_code_path(settings, s)) continue;
      const RunResult& r = ctx.run(c.scene, collider, overrides(ctx, c, s), options);
      ctx.add_run(r, row_name(c, s));
      const Measured m = measure(c, s, r);
      t.row(row_cells(m, r));
      rows.push_back(m);
    }
  }
  ctx.chart("limiters", {{"title", "Strain limiters at the papers' clock: worst strain against the limiter's cost"},
                         {"xlabel", "the limiter's ms per step"},
                         {"ylabel", "largest structural strain (worst frame when walking) [%]"},
                         {"logx", true},
                         {"logy", true},
                         {"series", chart_series(rows)}});
  ctx.write("limiters", "Strain limiters against each other",
            description(collider, rows) + t.str() + "\n![chart](limiters.png)\n", summary(rows, cases.size()));
}

}  // namespace

void add_limiters_experiments(std::vector<Experiment>& out) {
  out.push_back({"limiters", "Strain limiters against each other", limiters});
}

}  // namespace clothbench
