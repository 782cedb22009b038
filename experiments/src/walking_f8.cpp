// walking-f8: walking paper Fig. 8, a tablecloth on a moving sphere (averaging, the directional rule as stated and
// ours).
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "clothbench/bench/oracle.hpp"
#include "clothbench/bench/report.hpp"
#include "clothbench/bench/viewer_export.hpp"
#include "clothbench/config.h"
#include "clothbench/experiments/experiment.hpp"
#include "clothbench/experiments/paper_figures.hpp"
#include "clothbench/experiments/row_names.hpp"
#include "clothbench/io/data_root.hpp"
#include "clothbench/render/picture.hpp"
#include "experiment_list.hpp"

namespace clothbench {

namespace {

// how far the cloth's centre trails the sphere's centre along +x, the motion [cm]
double lag_cm(const Points3& cloth, const BodyFrame& sphere) {
  return 100 * double(bounding_box(sphere.positions).center().x() - cloth.rowwise().mean().x());
}

// the share of the cloth's vertices within the collider's tol of the body (touching it) [%]
double touching_pct(const BodyFrame& body, const Points3& cloth, Real tol) {
  const Oracle oracle(body);
  std::vector<Real> d;
  oracle.signed_distance(PointsView(cloth), d);
  const auto n = std::count_if(d.begin(), d.end(), [&](Real x) { return x < tol; });
  return d.empty() ? 0 : 100.0 * double(n) / double(d.size());
}

// what one limit's run did over the motion, from its frames
struct Motion {
  std::string label;
  bool diverged = false;
  double peak_touching = 0, peak_at = 0;  // the most vertices touching the sphere [%] and when [s]
  double end_touching = 0, end_lag = 0;   // at the motion's last frame [%], [cm]
  double off_at = -1;                     // the first frame after the peak with none touching [s] (-1: never)
};

Motion motion(const std::string& label, bool diverged, const std::vector<double>& times,
              const std::vector<double>& touching, const std::vector<double>& lags) {
  Motion m{label, diverged || times.empty()};
  if (m.diverged) return m;
  const auto peak = std::max_element(touching.begin(), touching.end()) - touching.begin();
  m.peak_touching = touching[peak], m.peak_at = times[peak];
  m.end_touching = touching.back(), m.end_lag = lags.back();
  for (auto i = peak; m.peak_touching > 0 && i < std::ptrdiff_t(touching.size()); ++i)
    if (touching[i] == 0) {
      m.off_at = times[i];
      break;
    }
  return m;
}

// the limits whose cloth still touches the sphere at the end of the motion, "; "-separated ("none")
std::string following(const std::vector<Motion>& runs) {
  std::string follow;
  for (const Motion& m : runs)
    if (!m.diverged && m.off_at < 0 && m.end_touching > 0) follow += std::string(follow.empty() ? "" : "; ") + m.label;
  return follow.empty() ? "none" : follow;
}

// the page's opening lines: the paper's figure, each limit's strain and whether its cloth stayed, the verdict
std::vector<std::string> summary(const std::vector<Motion>& runs, const std::vector<double>& strain_pct) {
  std::string ours = "Ours, one run each:";
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const Motion& m = runs[i];
    ours += std::string(i ? ";" : "") + " " + m.label + " " +
            (m.diverged
                 ? std::string("diverged")
                 : "strain max " + num(strain_pct[i], 1) + " % during the motion, " + num(m.end_touching, 1) +
                       " % touching at the end" + (m.off_at >= 0 ? " (slid off at " + num(m.off_at, 2) + " s)" : ""));
  }
  return {
      "The paper (walking Fig. 8): with the directional modification the tablecloth follows the moving sphere "
      "(pictures, no figures).",
      ours + ".",
      "Verdict: the limits whose cloth still touches the sphere at the end of the motion: " + following(runs) + "."};
}

// the paragraph under the charts, every figure from the frames of this run
std::string motion_text(const std::vector<Motion>& runs) {
  std::string out = "What the charts show, frame by frame:";
  for (const Motion& m : runs) {
    out += " " + m.label + ": ";
    if (m.diverged) {
      out += "diverged (no frames to chart).";
      continue;
    }
    out += "touching peaks at " + num(m.peak_touching, 1) + " % at " + num(m.peak_at, 2) + " s and ends at " +
           num(m.end_touching, 1) + " %" +
           (m.off_at >= 0 ? " (none touching from " + num(m.off_at, 2) + " s: the cloth slid off)" : "") +
           ", the lag at the end " + num(m.end_lag, 1) + " cm.";
  }
  return out +
         " The paper's Fig. 8 shows the directional cloth following the sphere; here the rows whose cloth still " +
         "touches the sphere at the end of the motion are: " + following(runs) + ".";
}

// one limit's row: its strain, lag, contact and status (a diverged run has no end state)
std::vector<std::string> row_cells(const char* label, const RunResult& r, const std::vector<double>& touching) {
  const std::string status = r.divergence ? "diverged at iteration " + std::to_string(r.divergence->iteration) + " (" +
                                                to_string(r.divergence->phase) + ", " + r.divergence->reason + ")"
                                          : "ok";
  const auto end_value = [&](double v) { return r.divergence ? std::string("-") : num(100 * v, 1); };
  return {label,
          "5 %",
          r.frames ? num(100 * r.animate_strain_max, 1) : "-",
          end_value(r.strain_max),
          end_value(r.strain_p99),
          r.divergence ? "-" : num(lag_cm(r.mesh.positions, r.final_body), 1),
          r.divergence || touching.empty() ? "-" : num(touching.back(), 1),
          r.divergence ? "-" : num(r.accuracy.inside_pct, 2),
          status};
}

// the two charts against time; the page's links to those written
std::string write_charts(ExperimentContext& ctx, const nlohmann::json& lag_series, const nlohmann::json& touch_series) {
  std::string charts;
  if (ctx.chart("walking-f8-lag", {{"title", "walking-f8: the cloth's centroid behind the sphere's centre along x"},
                                   {"xlabel", "time of the motion [s]"},
                                   {"ylabel", "lag [cm]"},
                                   {"series", lag_series}}))
    charts += "![lag against time](walking-f8-lag.png) ";
  if (ctx.chart("walking-f8-touching", {{"title", "walking-f8: cloth vertices within tol of the sphere"},
                                        {"xlabel", "time of the motion [s]"},
                                        {"ylabel", "touching [%]"},
                                        {"series", touch_series}}))
    charts += "![touching against time](walking-f8-touching.png)";
  return charts;
}

// the page's text above the table
const char* const kDescription =
    "A square tablecloth draped on a sphere that then moves along +x at 1 m/s for 1 s "
    "(scenes/walking/tablecloth_sphere.toml; analytic sphere collider, so the comparison isolates the "
    "super-elasticity limit). Limits: none; velocity averaging (walking Eq. 5); the directional modification as "
    "the paper states it (walking Eq. 6: springs with |cos alpha| < 0.3 to v_dir average, on the others the rear "
    "point takes the front one's velocity); and ours, which adds two rules (a held rear point, attached or in "
    "contact, makes the front follow it; catching up that would add kinetic energy to the pair averages "
    "instead). Lag = distance from the cloth's centroid to the sphere's centre along the motion; touching = "
    "vertices within the collider's tol of the sphere. Both are charted at every frame of the motion; a cloth "
    "that slides off the sphere shows as touching falling to 0 while the lag grows.\n\n";

void walking_f8(ExperimentContext& ctx) {
  MarkdownTable t({"limit", "threshold", "strain max during motion [%]", "strain max end [%]", "strain p99 end [%]",
                   "lag behind the sphere [cm]", "touching the sphere [%] end", "inside [%] end", "status"});
  std::vector<Image> pictures;
  std::vector<Motion> motions;
  std::vector<double> strain_pct;  // per limit: the largest strain during the motion
  nlohmann::json lag_series = nlohmann::json::array(), touch_series = nlohmann::json::array();
  const std::pair<const char*, const char*> limits[] = {{"none", "no limit"},
                                                        {"velocity", "velocity averaging (Eq. 5)"},
                                                        {"directional-literal", "directional, as stated (Eq. 6)"},
                                                        {"directional", "directional, ours (guarded)"}};
  const Real tol =
      load_scene(std::string(CLOTHBENCH_SOURCE_DIR) + "/scenes/walking/tablecloth_sphere.toml").collider_options.tol;
  for (const auto& [limit, label] : limits) {
    std::vector<std::string> sets{std::string("solver.limit=") + limit};
    if (ctx.quick()) sets.push_back("stop.max_iterations=60");
    // every frame: the lag and the share touching the sphere, outside the measured time
    std::vector<double> times, lags, touching;
    RunOptions options;
    options.on_frame = [&](long frame, double at, const BodyFrame& body, const Simulator& sim) {
      if (frame == 1) times.clear(), lags.clear(), touching.clear();
      times.push_back(at);
      lags.push_back(lag_cm(sim.positions(), body));
      touching.push_back(touching_pct(body, sim.positions(), tol));
    };
    const RunResult& r = ctx.run("walking/tablecloth_sphere.toml", "sphere", sets, options);
    t.row(row_cells(label, r, touching));
    nlohmann::json extra = nlohmann::json::object();
    if (r.frames) extra["animate_strain_max"] = r.animate_strain_max;
    if (!r.divergence) extra["lag_cm"] = lag_cm(r.mesh.positions, r.final_body);
    ctx.add_run(r, row_names::walking_f8(limit), extra);
    motions.push_back(motion(label, bool(r.divergence), times, touching, lags));
    strain_pct.push_back(100 * r.animate_strain_max);
    if (!times.empty()) {
      lag_series.push_back({{"label", label}, {"x", times}, {"y", lags}, {"style", "-"}});
      touch_series.push_back({{"label", label}, {"x", times}, {"y", touching}, {"style", "-"}});
    }
    if (!r.divergence) pictures.push_back(ctx.pictures().render(r.final_body, r.mesh, 300, View::kFront));
  }
  side_by_side(pictures).write_png(ctx.path("pictures/walking-f8.png"));
  const std::string charts = write_charts(ctx, lag_series, touch_series);
  ctx.write("walking-f8", "Walking paper Fig. 8: tablecloth on a moving sphere",
            kDescription + t.str() + "\n" + charts + "\n\n" + motion_text(motions) + "\n\n![" +
                "the rows that did not diverge, in order](pictures/walking-f8.png)\n\nPictures drawn by " +
                ctx.pictures().name() + ".\n",
            summary(motions, strain_pct));
}

}  // namespace

void add_walking_f8_experiments(std::vector<Experiment>& out) {
  out.push_back({"walking-f8", "Walking paper Fig. 8", walking_f8});
}

}  // namespace clothbench
