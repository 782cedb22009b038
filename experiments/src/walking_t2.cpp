// walking-t2: walking paper Table 2, garments on the walking body (every frame measured, ablations of how the body
// moves).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <optional>

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
#include "walking_t2_media.hpp"
#include "walking_t2_speed.hpp"

namespace clothbench {

namespace {

// the papers'-clock rows' solver.limit_tolerance_mm [mm]
constexpr const char* kPapersTolerance = "0.05";

bool walking_body_present(ExperimentContext& ctx, const std::string& id) {
  const std::string body = data_path("body/mh_female_walk.glb");
  if (std::filesystem::exists(body)) return true;
  std::cerr << "  " << id << " skipped: the walking body " << body
            << " is absent (the data root is scenes/data unless CLOTHBENCH_DATA points elsewhere)\n";
  ctx.write(id, "skipped", "Skipped: the walking body `" + body + "` was not found. Set `CLOTHBENCH_DATA`.\n",
            {"The paper (walking Table 2): garments animated on a walking body.",
             "Ours: not run, the walking body was not found.", "No verdict."});
  return false;
}

// how much cloth time a frame of the walk is in one regime: steps of dt against the body's frame
std::string frame_clock(const std::string& regime, const RunResult& r, double fps) {
  const int digits = r.steps_per_frame == std::floor(r.steps_per_frame) ? 0 : 2;
  return regime + " " + num(r.steps_per_frame, digits) + " steps of " + num(1e3 * r.dt_s, 3) +
         " ms = " + num(1e3 * r.steps_per_frame * r.dt_s, 1) + " ms of cloth time per " + num(1e3 / fps, 1) +
         " ms frame";
}

// a walking run of walking-t2: which clip, regime and collider, and what it changes from the scene
struct WalkVariant {
  std::string label, clip, regime, row_suffix;
  std::vector<std::string> sets, colliders;
  bool speed = false;  // a row of the speed paragraph's frontier (taken from the dress with is-cpu)
};

// the papers' clock with walking Eq. 5's averaging limit (with the directional one, Eq. 6, the dress diverges
// there), the regime's 32 passes stopping at 0.05 mm, then `more`
std::vector<std::string> papers_clock(std::vector<std::string> more,
                                      const std::string& tolerance_mm = kPapersTolerance) {
  more.insert(more.begin(), {"solver.limit=velocity", "solver.limit_tolerance_mm=" + tolerance_mm});
  return more;
}

// the papers' image space: the front/back pair of views with the papers' own test
std::vector<std::string> papers_image_space_sets() {
  std::vector<std::string> sets{"collider.views=2"};
  for (const auto& o : papers_image_space("is-cpu")) sets.push_back(o);
  return sets;
}

// stable and papers' regimes with every collider of the speed tables on walk_07_01, stable on walk_08_02 with image
// space and the lead object-space collider; the other limits at the papers' clock (is-cpu)
std::vector<WalkVariant> collider_variants(const ExperimentContext& ctx) {
  const std::vector<std::string> all =
      ctx.colliders([](const ColliderInfo& c) { return in_speed_tables(c) && !c.slow_update; });
  // a collider whose update to the moved body takes seconds (vdb voxelises the skinned body again every frame):
  // half a second of walking only
  const std::vector<std::string> slow =
      ctx.colliders([](const ColliderInfo& c) { return in_speed_tables(c) && c.slow_update; });
  const std::vector<std::string> some = ctx.colliders([](const ColliderInfo& c) {
    return in_speed_tables(c) && (c.family == Family::kImageSpace || c.name == kLeadObjectSpace);
  });
  std::vector<WalkVariant> v;
  v.push_back({"stable", "walk_07_01", "stable", "", {}, all, true});
  v.push_back({"stable, 0.5 s", "walk_07_01", "stable", "/0.5s", {"body.end_s=1.5"}, slow});
  v.push_back({"stable", "walk_08_02", "stable", "/walk_08_02", {"body.animation=walk_08_02"}, some, true});
  v.push_back({"papers' clock, Eq. 5 limit", "walk_07_01", "papers", "/papers", papers_clock({}), all});
  const std::vector<std::string> is_cpu{"is-cpu"};
  v.push_back({"papers' clock, directional limit (Eq. 6)",
               "walk_07_01",
               "papers",
               "/papers-eq6",
               {"solver.limit=directional"},
               is_cpu});
  v.push_back({"papers' clock, Eq. 5 limit", "walk_08_02", "papers", "/papers/walk_08_02",
               papers_clock({"body.animation=walk_08_02"}), is_cpu});
  // beyond the papers: the strain limit as a fast projection (Goldenthal et al. 2007), 8 Newton iterations a call
  const std::vector<std::string> projection{"solver.limit=projection", "solver.limit_passes=8"};
  v.push_back({"papers' clock, projection limit (8 iterations)", "walk_07_01", "papers", "/papers-projection",
               projection, is_cpu});
  std::vector<std::string> projection_08 = projection;
  projection_08.push_back("body.animation=walk_08_02");
  v.push_back({"papers' clock, projection limit (8 iterations)", "walk_08_02", "papers",
               "/papers-projection/walk_08_02", projection_08, is_cpu});
  return v;
}

// how the maps and the body are taken (is-cpu; every row's maps with the image space of the tables), and the next
// frame prepared ahead
std::vector<WalkVariant> map_variants(const ExperimentContext& ctx) {
  const std::vector<std::string> is_cpu{"is-cpu"};
  std::vector<WalkVariant> v;
  v.push_back({"stable, the papers' image space (front/back, z test, 8-bit)", "walk_07_01", "stable", "/papers-is",
               papers_image_space_sets(), is_cpu});
  v.push_back({"stable, one surface per camera (visual hull)",
               "walk_07_01",
               "stable",
               "/onelayer",
               {"collider.layers=1"},
               is_cpu});
  v.push_back({"stable, no skin", "walk_07_01", "stable", "/noskin", {"body.skin_mm=0"}, is_cpu});
  v.push_back({"stable, maps of every row",
               "walk_07_01",
               "stable",
               "/allrows",
               {"collider.query_margin_mm=0"},
               ctx.colliders(in_tables(Family::kImageSpace))});
  // the next frame skinned and its maps drawn on a second thread while the cloth steps (the same run: timing rows)
  v.push_back({"stable, next frame prepared ahead (2 threads)",
               "walk_07_01",
               "stable",
               "/ahead",
               {"body.prepare_ahead=true"},
               is_cpu,
               true});
  return v;
}

// the speed paragraph's rows (is-cpu)
std::vector<WalkVariant> speed_variants() {
  const std::vector<std::string> is_cpu{"is-cpu"};
  std::vector<WalkVariant> v;
  // the speed row: the papers' clock with the next frame prepared on a second thread; then what looser limit passes
  // with one surface per camera, and one pass with the papers' own image space, buy in speed and cost in accuracy
  // (the speed paragraph's frontier)
  v.push_back({"papers' clock, Eq. 5 limit, next frame prepared ahead (2 threads)", "walk_07_01", "papers",
               "/papers-ahead", papers_clock({"body.prepare_ahead=true"}), is_cpu, true});
  v.push_back(
      {"papers' clock, Eq. 5 limit, passes stopping at 1 mm, one surface per camera, prepared ahead (2 "
       "threads)",
       "walk_07_01", "papers", "/papers-ahead-1mm", papers_clock({"body.prepare_ahead=true", "collider.layers=1"}, "1"),
       is_cpu, true});
  // the colliders' body simplified (body.collision_triangles): cheaper maps, the oracle still on the exact body
  v.push_back(
      {"papers' clock, Eq. 5 limit, the colliders' body simplified to 6,000 triangles, prepared ahead (2 "
       "threads)",
       "walk_07_01", "papers", "/papers-ahead-proxy",
       papers_clock({"body.prepare_ahead=true", "body.collision_triangles=6000"}), is_cpu, true});
  // everything that buys speed at once, the skin 1 mm thicker for the simplified body's error (2.8 mm at 6,000
  // triangles); on both clips
  const std::vector<std::string> fast =
      papers_clock({"body.prepare_ahead=true", "collider.layers=1", "collider.map_size=224",
                    "body.collision_triangles=6000", "body.skin_mm=5", "collider.tol=0.007"},
                   "2");
  const std::string fast_label =
      "papers' clock, Eq. 5 limit, passes stopping at 2 mm, one surface per camera, 224² maps, the colliders' body "
      "simplified to 6,000 triangles, 5 mm skin (7 mm hit distance), prepared ahead (2 threads)";
  v.push_back({fast_label, "walk_07_01", "papers", "/papers-ahead-fast", fast, is_cpu, true});
  std::vector<std::string> fast_08 = fast;
  fast_08.push_back("body.animation=walk_08_02");
  v.push_back({fast_label, "walk_08_02", "papers", "/papers-ahead-fast/walk_08_02", fast_08, is_cpu, true});
  std::vector<std::string> published = papers_clock({"body.prepare_ahead=true", "solver.limit_passes=1"});
  const std::vector<std::string> papers_is = papers_image_space_sets();
  published.insert(published.end(), papers_is.begin(), papers_is.end());
  v.push_back(
      {"papers' clock, Eq. 5 limit, 1 limit pass, the papers' image space (front/back, z test, 8-bit), "
       "prepared ahead (2 threads)",
       "walk_07_01", "papers", "/papers-ahead-published", published, is_cpu, true});
  // beyond the papers: the stable regime's springs and masses by the projective solve (Liu et al. 2013) at 20 steps
  // a frame (1.67 ms), walking Eq. 5's sweeps, 16 passes (the regime's impulses miss or diverge at the projective
  // solve's step: results/limiters.md), prepared ahead; on both clips
  const std::vector<std::string> projective{"solver.integrator=projective", "solver.dt=0.0016667",
                                            "solver.limit=velocity", "solver.limit_passes=16",
                                            "body.prepare_ahead=true"};
  const std::string projective_label =
      "projective solve (Liu et al. 2013), 20 steps a frame, 16 limit passes, prepared ahead (2 threads)";
  v.push_back({projective_label, "walk_07_01", "stable", "/projective-ahead", projective, is_cpu, true});
  std::vector<std::string> projective_08 = projective;
  projective_08.push_back("body.animation=walk_08_02");
  v.push_back({projective_label, "walk_08_02", "stable", "/projective-ahead/walk_08_02", projective_08, is_cpu, true});
  return v;
}

// the response's ablations (is-cpu) and the travelling body (is-cpu and embree)
std::vector<WalkVariant> response_variants() {
  const std::vector<std::string> is_cpu{"is-cpu"};
  std::vector<WalkVariant> v;
  v.push_back({"stable, no push-out", "walk_07_01", "stable", "/nopush", {"solver.push_out=false"}, is_cpu});
  v.push_back({"stable, without Eq. 16",
               "walk_07_01",
               "stable",
               row_names::kWithoutEq16,
               {"solver.reaction_force=false"},
               is_cpu});
  v.push_back(
      {"stable, body held per frame", "walk_07_01", "stable", "/held", {"body.move_between_frames=false"}, is_cpu});
  // the dress's scene poses the body twice a frame (body.pose_fps): once, the knee can pass through the hem on
  // walk_08_02
  v.push_back({"stable, body posed once per frame",
               "walk_08_02",
               "stable",
               "/posed-per-frame",
               {"body.animation=walk_08_02", "body.pose_fps=0"},
               is_cpu});
  v.push_back(
      {"stable, travelling", "walk_07_01", "stable", "/travel", {"body.walk_in_place=false"}, {"is-cpu", "embree"}});
  // beyond the papers: the cloth against itself answered (solver.self_contact_mm), on both clips
  for (const char* clip : {"walk_07_01", "walk_08_02"})
    v.push_back({"stable, cloth against itself (5 mm)",
                 clip,
                 "stable",
                 std::string("/self-contact/") + clip,
                 {"solver.self_contact_mm=5", std::string("body.animation=") + clip},
                 is_cpu});
  return v;
}

// every walking-t2 row's variant, in the table's order
std::vector<WalkVariant> walk_variants(const ExperimentContext& ctx) {
  std::vector<WalkVariant> v = collider_variants(ctx);
  for (const auto& part : {map_variants(ctx), speed_variants(), response_variants()})
    v.insert(v.end(), part.begin(), part.end());
  return v;
}

// "worst / mean" of a per-frame figure
std::string worst_mean(const RunResult& r, double FrameSample::*field, int digits) {
  return num(r.frame_max(field), digits) + " / " + num(r.frame_mean(field), digits);
}

// a garment is dressed when its seams were sewn before the measured walk starts
bool dressed(const RunResult& r) { return r.window_seam_gap_mm <= kAccuracyLimits.seam_gap_mm; }

// the row of one run: timings only for a dressed garment that did not diverge
std::vector<std::string> walk_row(const std::string& product, const WalkVariant& v, const std::string& collider,
                                  const RunResult& r, const FrameRates& rates, const paper::WalkingT2Row& p) {
  std::vector<std::string> row{product,
                               v.label,
                               v.clip,
                               collider,
                               std::to_string(r.vertices),
                               std::to_string(r.frames),
                               num(r.steps_per_frame, 0) + " at " + num(1e3 * r.dt_s, 3) + " ms"};
  // no measured frame: the run diverged while dressing or in the lead-in
  if (r.frames == 0 || !dressed(r)) {
    for (int i = 0; i < 11; ++i) row.push_back("-");
    row.push_back(r.frames == 0 && r.divergence
                      ? "no: diverged before the walk (" + std::string(to_string(r.divergence->phase)) +
                            ", iteration " + std::to_string(r.divergence->iteration) + ")"
                      : "no: not dressed, seam gap " + num(r.window_seam_gap_mm, 1) + " mm when the walk starts");
    return row;
  }
  const FrameTimes f = frame_times(r);
  const bool ok = !r.divergence;
  row.insert(
      row.end(),
      {num(f.s, 4), num(1 / f.s, 1) + (rates.fps.size() > 1 ? " (" + rates.text() + ")" : ""), num(f.skinning_ms, 2),
       num(f.maps_ms, 2), num(f.cloth_ms, 2), num(p.s_per_frame, 3) + " / " + num(p.fps, 1),
       ok ? worst_mean(r, &FrameSample::inside_pct, 2) : "diverged",
       ok ? num(r.frame_max(&FrameSample::depth_max_mm), 1) : "-",
       ok ? worst_mean(r, &FrameSample::crossings_pct, 2) : "-",
       num(100 * r.animate_strain_max, 1) + " / " + num(100 * r.frame_max(&FrameSample::strain_p99), 1),
       ok ? num(r.frame_max(&FrameSample::cloth_crossings_pct), 2) : "-", limits_cell(r)});
  return row;
}

// the walk's garments, as the paper's Table 2 has them
struct WalkGarment {
  const char* product;
  const char* name;
  int vertices;
};

// a run of walk_garment waiting for its row (the request, for run() to answer again once the contenders for the
// headline have their runs)
struct WalkRun {
  std::size_t garment;
  WalkVariant variant;
  std::string scene, collider;
  std::vector<std::string> sets;
  double body_fps;
};

// what walking-t2 gathers over its runs for the page
struct WalkPage {
  std::vector<WalkRun> runs;
  MarkdownTable table{{"garment", "variant", "clip", "collider", "vertices", "frames", "steps/frame at dt", "s/frame",
                       "frames/s", "skinning ms/frame", "maps, refit or field ms/frame", "cloth ms/frame (CD&R + CS)",
                       "paper s/frame / frames/s", "inside [%] worst / mean frame", "depth max [mm] worst frame",
                       "crossings [%] worst / mean frame", "strain max / p99 [%] worst frame",
                       "cloth through itself [%] worst frame", "meets the limits (every frame)"}};
  std::string media, charts, models, clocks;
  std::vector<SpeedRun> frontier;
  std::vector<std::pair<std::string, std::pair<int, int>>> meeting;  // per garment: rows within every limit, rows
  std::optional<RunResult> speed_run;
  std::optional<SpeedRun> fastest;  // the dress's fastest row of any collider on walk_07_01 within every limit
  double proxy_mm = 0;  // the simplified body's largest distance from the exact one, where a row simplifies it
};

// the is-cpu run of the stable regime: its frame sequence (every frame, front view), a video of it in real time (the
// scene's `fps`) where Debian's ffmpeg is installed, and its end state from the front and the side
void write_pictures(ExperimentContext& ctx, const WalkGarment& g, double fps,
                    const std::vector<SequenceFrame>& sequence, const RunResult& r, WalkPage& page) {
  const std::string stem = std::string("pictures/walking-t2-") + g.name;
  write_sequence(ctx.pictures(), sequence, r, ctx.path(stem + "/" + stem.substr(9)));
  const bool video = make_video(ctx.path(stem + "/" + stem.substr(9) + "-frame%03d.png"), ctx.path(stem + ".mp4"), fps);
  page.media += "- " + std::string(g.product) + ": [end state](" + stem + ".png), " + std::to_string(sequence.size()) +
                " frames in `" + stem + "/`" +
                (video ? ", [video](" + stem + ".mp4)" : std::string(", no video (ffmpeg absent)")) + "\n";
  std::vector<Image> views;
  for (View v : {View::kFront, View::kSide}) views.push_back(ctx.pictures().render(r.final_body, r.mesh, 360, v));
  side_by_side(views).write_png(ctx.path(stem + ".png"));
}

// the report's 3-D viewer: a walk as animated binary glTF (12 frames kept)
void write_model(ExperimentContext& ctx, const WalkGarment& g, const std::string& collider,
                 const std::vector<SequenceFrame>& sequence, const RunResult& r, WalkPage& page) {
  std::vector<ViewerFrame> frames;
  for (const auto& f : sequence) frames.push_back({f.t, f.body_positions, f.cloth_positions});
  const std::string glb = std::string("pictures/walking-t2-") + g.name + "-" + collider + ".glb";
  export_viewer_gltf(ctx.path(glb), r.final_body, r.mesh, frames, 12);
  page.models +=
      (page.models.empty() ? "" : ", ") + ("[" + std::string(g.product) + ", " + collider + "](" + glb + ")");
}

// the animation's frame rate of each run of the request that returned r (0 for a run that did not walk)
FrameRates frame_rates(const ExperimentContext& ctx, const RunResult& r) {
  FrameRates out;
  for (const RunResult* each : ctx.repetitions_of(r))
    out.fps.push_back(each->frames && !each->divergence ? 1 / frame_times(*each).s : 0);
  return out;
}

// of the runs of the request that returned r, the one with the median frame rate (of an even count the upper middle)
const RunResult& median_rate_run(const ExperimentContext& ctx, const RunResult& r) {
  auto runs = ctx.repetitions_of(r);
  std::sort(runs.begin(), runs.end(),
            [](const RunResult* a, const RunResult* b) { return frame_times(*a).s > frame_times(*b).s; });
  return *runs[runs.size() / 2];
}

// the dress's rows on walk_07_01 within every limit at every frame whose one run reaches kContender of the fastest
// such row's rate, of any collider or of the speed paragraph's is-cpu rows, run kVerdictRuns times: the headlines
// are chosen among them by their median (--quick: the code paths once, no repetitions)
constexpr double kContender = 0.75;
void repeat_contenders(ExperimentContext& ctx, const std::vector<WalkRun>& runs) {
  if (ctx.quick()) return;
  const auto rate = [&](const WalkRun& w) {
    const RunResult& r = ctx.run(w.scene, w.collider, w.sets);
    const bool within = w.garment == 1 && w.variant.clip == "walk_07_01" && r.frames && !r.divergence && dressed(r) &&
                        limit_misses(r).empty();
    return within ? 1 / frame_times(r).s : 0.0;
  };
  const auto frontier = [](const WalkRun& w) { return w.collider == "is-cpu" && w.variant.speed; };
  double any = 0, speed = 0;
  for (const WalkRun& w : runs) {
    any = std::max(any, rate(w));
    if (frontier(w)) speed = std::max(speed, rate(w));
  }
  RunOptions options;
  options.measure_frames = true;
  for (const WalkRun& w : runs) {
    const double fps = rate(w);
    if (fps > 0 && (fps >= kContender * any || (frontier(w) && fps >= kContender * speed)))
      ctx.run(w.scene, w.collider, w.sets, options, kVerdictRuns);
  }
}

// one run's row and what the page gathers from it (garment i of the table)
void account(ExperimentContext& ctx, std::size_t i, const WalkGarment& g, const WalkVariant& variant,
             const std::string& c, const RunResult& r, const FrameRates& rates, double fps, WalkPage& page) {
  const bool main = variant.label == "stable" && variant.clip == "walk_07_01";
  page.table.row(walk_row(g.product, variant, c, r, rates, paper::kWalkingT2[i]));
  // the cloth's clock and what holds the garment, from the is-cpu runs of both regimes on walk_07_01
  if (c == "is-cpu" && (main || (variant.row_suffix == "/papers" && r.frames))) {
    if (main)
      page.clocks += std::string(page.clocks.empty() ? "" : "; ") + g.product + ": " +
                     (r.mesh.attached.empty() ? std::string("nothing attached")
                                              : std::to_string(r.mesh.attached.size()) +
                                                    " vertices attached to the body (its waist, Durupinar 3.2)");
    page.clocks += ", " + frame_clock(variant.regime, r, fps);
  }
  // the speed paragraph's rows: the dress with is-cpu prepared ahead at the papers' clock, and in the stable
  // regime (one thread and prepared ahead)
  if (i == 1 && c == "is-cpu" && variant.speed) {
    const bool failed = r.frames == 0 || r.divergence || !dressed(r);
    page.frontier.push_back({variant.label, variant.clip, failed ? 0.0 : 1 / frame_times(r).s,
                             failed ? std::string("diverged or not dressed") : accuracy_misses(r), frame_times(r),
                             100 * r.animate_strain_max, limit_misses(r).size() > limit_misses(r, false).size(),
                             rates});
    if (variant.row_suffix == "/papers-ahead") page.speed_run = r;
  }
  page.proxy_mm = std::max(page.proxy_mm, r.proxy_deviation_mm);
  ctx.add_run(r, row_names::walking_t2(g.name, c, variant.row_suffix));
  page.meeting[i].second.first += limit_misses(r).empty() ? 1 : 0;
  ++page.meeting[i].second.second;
  const double rate = r.frames ? 1 / frame_times(r).s : 0;
  if (i == 1 && variant.clip == "walk_07_01" && limit_misses(r).empty() && (!page.fastest || rate > page.fastest->fps))
    page.fastest = SpeedRun{variant.label + ", " + c,   variant.clip, rate, "", frame_times(r),
                            100 * r.animate_strain_max, false,        rates};
}

// every variant and collider on one garment (garment i of the table), and its chart of every frame
void walk_garment(ExperimentContext& ctx, std::size_t i, const WalkGarment& g, WalkPage& page) {
  std::vector<std::string> sets_quick;
  if (ctx.quick()) sets_quick = {"body.start_s=0.1", "body.end_s=0.2", "stop.max_iterations=60"};
  const std::string scene = std::string("walking/") + g.name + ".toml";
  const double fps = load_scene(std::string(CLOTHBENCH_SOURCE_DIR) + "/scenes/" + scene).body.fps;
  std::vector<std::pair<std::string, RunResult>> charted;
  page.meeting.push_back({g.product, {0, 0}});
  for (const WalkVariant& variant : walk_variants(ctx))
    for (const auto& c : ctx.colliders(variant.colliders)) {
      // --quick: the code paths once (the second clip and the travelling body add none; the dress adds no collider
      // path to the skirt's)
      if (ctx.quick() && (variant.clip != "walk_07_01" || variant.row_suffix == "/travel" || (i > 0 && c != "is-cpu")))
        continue;
      std::vector<std::string> sets{"garment.vertices=" + std::to_string(g.vertices),
                                    "solver.regime=" + variant.regime};
      sets.insert(sets.end(), variant.sets.begin(), variant.sets.end());
      sets.insert(sets.end(), sets_quick.begin(), sets_quick.end());
      // the is-cpu run of the stable regime also leaves pictures, and the 3-D viewer takes the is-cpu walk of each
      // garment and embree beside it on the skirt; frames are only copied during the run and drawn after it, so
      // the pictures stay out of the measured s/frame
      RunOptions options;
      options.measure_frames = true;  // accuracy at every frame, not the last one only
      const bool main = variant.label == "stable" && variant.clip == "walk_07_01";
      const bool animated = main && (c == "is-cpu" || (c == "embree" && i == 0));
      std::vector<SequenceFrame> sequence;
      if (animated)
        options.on_frame = [&](long frame, double at, const BodyFrame& body, const Simulator& sim) {
          if (frame == 1) sequence.clear();  // a repetition starts over
          sequence.push_back({frame, at, body.positions, body.normals, sim.positions()});
        };
      const RunResult& r = ctx.run(scene, c, sets, options);
      page.runs.push_back({i, variant, scene, c, sets, fps});
      if (main) charted.emplace_back(c, r);
      if (animated) write_model(ctx, g, c, sequence, r, page);
      if (c == "is-cpu" && main) write_pictures(ctx, g, fps, sequence, r, page);
    }
  const std::string chart = std::string("walking-t2-frames-") + g.name;
  if (ctx.chart(chart, frames_chart(g.product, charted)))
    page.charts += "![" + std::string(g.product) + ": inside and crossings at every frame](" + chart + ".png)\n";
}

// the page's text before the table: what runs, how the body moves, what each ablation row changes
// the page's second paragraph: how the body moves and is answered, and the ablation rows
std::string body_description(double proxy_mm) {
  return "How the body moves (scenes/README.md, `[body]`): it is posed once per frame, at the frame's end (the dress "
         "twice, `body.pose_fps = 60`: on walk_08_02 a knee moves farther in a frame than half its thickness and "
         "can pass through the hem between two poses; the row \"body posed once per frame\" measures it), and each "
         "cloth step within the pose's interval sees the contacts as they were at the step's time, d(t - tau) = d(t) + "
         "(n . v_body) tau (`body.move_between_frames`); points found inside are moved out along the contact normal "
         "(`solver.push_out`, Durupinar Eq. 3); the walking paper's reaction force is on (walking Eq. 16, "
         "`solver.reaction_force`); the body is answered `body.skin_mm` thicker (scenes/walking/*.toml; while it is "
         "dressed too), "
         "which keeps the straight springs between resting vertices from cutting the curved surface they lie on (by up "
         "to L^2 / 8R, a spring of length L on a surface of radius R); image space renders the cube of six views "
         "(`collider.views = 6`): with the papers' front/back pair the swinging hands hide the hips and the cloth "
         "caught between is pushed the wrong way (the ablation row runs the papers' image space whole: the front/back "
         "pair, one surface per camera, the z comparison of walking Eq. 12 on 8-bit maps); and each pair peels five "
         "surfaces along its axis (`collider.layers = 5`, depth peeling; with the far camera's nearest one, the six a "
         "line through both arms and the torso crosses): with one surface per camera the six views make a visual "
         "hull, and a sleeve point inside the arm next to the armpit, hidden from the side cameras by the "
         "torso and the other arm and from the rest by the arm itself, was answered by the arm's front or back and "
         "stayed inside. Each of these has an ablation row (is-cpu, walk_07_01). Image space draws and "
         "reads back only the map rows that the cloth's bounding box, grown by `collider.query_margin_mm` (100 mm), "
         "spans, since a frame's queries come from there; the row \"maps of every row\" (is-gl, is-cpu) draws them "
         "all: the same motion, the maps' cost beside. The rows \"next frame prepared ahead (2 threads)\" "
         "(`body.prepare_ahead`) skin the next frame and draw its maps on a second thread while the cloth steps "
         "through "
         "this one (the body's motion is prescribed): the same motion bit for bit, s/frame is then wall time with two "
         "threads, and skinning and maps ms/frame are the second thread's (is-cpu only: llvmpipe already draws is-gl's "
         "maps on both cores of this machine, and drawn beside the cloth they took longer than the cloth saved). The "
         "rows \"the colliders' body simplified\" (`body.collision_triangles`) hand the colliders a copy of the body "
         "with fewer triangles (edge collapses that keep some of its own vertices and their skin; every exact vertex "
         "within " +
         num(proxy_mm, 1) +
         " mm of the copy) while the oracle measures against the exact body. \"Travelling\" keeps the root's motion "
         "(the maps follow the body). And \"cloth against itself\" stops a point of the garment moving into a "
         "triangle of the garment nearer than the thickness (`solver.self_contact_mm`, Bridson, Fedkiw and Anderson "
         "2002, beyond the papers; scenes/README.md): its column \"cloth through itself\" beside the others'.\n\n";
}

std::string description(const WalkPage& page) {
  return "Garments dressed on the bind pose (t = 0, sew + drape with `collider.dress_with`), carried through the "
         "clip's "
         "lead-in (0 - 1 s), then measured over **two seconds of walking** (1 - 3 s, about two gait cycles) in place, "
         "on "
         "both clips (`walk_07_01`, `walk_08_02`); the body frames are evaluated at `body.fps` frames per second of "
         "animation time and the cloth takes `steps/frame` steps of dt per frame, in our stable regime (its limit the "
         "walking scenes': walking Eq. 5 as warm-started impulses, 4 passes, for the dress, Eq. 5's sweeps, 16 passes, "
         "for "
         "the skirt, run again after the collision response; results/limiters.md "
         "measures the alternatives, Eq. 6 and fewer passes among them) and at the papers' "
         "clock (`solver.regime = papers`: dt 5 ms, equal point masses, soft springs, 32 limit passes; see "
         "dressing-t1; "
         "the passes here stop once they change no point by more than " +
         std::string(kPapersTolerance) +
         " mm, `solver.limit_tolerance_mm`) with the walking "
         "paper's averaging limit (Eq. 5, `solver.limit = velocity`): with its directional limit (Eq. 6, the paper's "
         "choice for moving bodies, and the regime's default) the dress with sleeves diverges at that clock within the "
         "first frames of the walk (the ablation row: that limit's rear-catches-up rule does not keep momentum), "
         "while Eq. 5's mass-weighted mean keeps it; the rows \"projection limit\" hold the strain by a fast "
         "projection of "
         "the structural springs instead (Goldenthal et al. 2007, beyond the papers; results/limiters.md); the rows "
         "\"projective solve\" keep the stable regime's springs and masses and step them by backward Euler in "
         "local/global iterations on a matrix factored once (Liu et al. 2013, beyond the papers; `solver.integrator = "
         "projective`, 2 iterations) at 20 steps of 1.67 ms a frame instead of about 200 explicit ones. s/frame = wall "
         "time of the animation phase "
         "per frame: skinning (LBS, our analogue of the paper's reading the body file), map re-render, BVH refit or "
         "(vdb) the body's signed distance field voxelised again, and cloth (CD&R + CS); vdb runs half a second in the "
         "stable regime only, its per-frame voxelisation costing seconds. The paper's figures include rendering the "
         "scene on screen, ours do not. The exact oracle measures **every frame** (outside s/frame): the worst and the "
         "mean frame's inside and crossings, the worst frame's depth; the verdict counts the worst frame. Beside "
         "them, not a limit: the cloth through itself, the share of structural springs through a triangle of the "
         "garment itself at the worst frame (a fold or a sleeve through the cloth; no collider answers cloth against "
         "cloth yet). A garment "
         "whose "
         "seams are still open when the walk starts (gap > 2 mm) gets no timings: it is listed as not dressed. "
         "The walk is in place (`body.walk_in_place`: the root's travel removed). "
         "Every row is one run, except the contenders for the headline: the dress's rows on walk_07_01 within every "
         "limit at every frame whose one run reached " +
         num(100 * kContender, 0) +
         " % of the fastest such row's frame rate (of any collider, or of the speed paragraph's is-cpu rows) run " +
         std::to_string(kVerdictRuns) +
         " times in all; their frames/s is the median run's (the run whose figures the row shows) with the range, "
         "and the headlines are chosen by it. "
         "The cloth's own clock and what holds each garment besides collisions (is-cpu, walk_07_01): " +
         page.clocks + ".\n\n" + body_description(page.proxy_mm);
}

void walking_t2(ExperimentContext& ctx) {
  if (!walking_body_present(ctx, "walking-t2")) return;
  const WalkGarment garments[] = {{"skirt", "skirt", 672}, {"dress with sleeves", "dress_sleeves", 2300}};
  WalkPage page;
  for (std::size_t i = 0; i < 2; ++i) walk_garment(ctx, i, garments[i], page);
  repeat_contenders(ctx, page.runs);
  for (const WalkRun& w : page.runs) {
    const RunResult& r = ctx.run(w.scene, w.collider, w.sets);
    account(ctx, w.garment, garments[w.garment], w.variant, w.collider, median_rate_run(ctx, r), frame_rates(ctx, r),
            w.body_fps, page);
  }
  ctx.write(
      "walking-t2", "Walking paper Table 2: animation speed on the walking body",
      description(page) + page.table.str() + "\n" +
          (page.speed_run ? speed_figure(*page.speed_run, paper::kWalkingT2[1], page.frontier) : std::string()) +
          page.charts +
          (page.media.empty()
               ? std::string()
               : "\nPictures of the is-cpu runs (front view; " + ctx.pictures().name() +
                     "; frames are copied during the run and drawn after it, outside s/frame):\n\n" + page.media) +
          (page.models.empty() ? std::string()
                               : "\nAnimated binary glTF of the walks (12 frames kept, for results/index.html's "
                                 "viewer): " +
                                     page.models + ".\n"),
      speed_summary(page.frontier, page.meeting, page.fastest));
}

}  // namespace

void add_walking_t2_experiments(std::vector<Experiment>& out) {
  out.push_back({"walking-t2", "Walking paper Table 2", walking_t2});
}

}  // namespace clothbench
