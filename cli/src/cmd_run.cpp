// clothbench run SCENE [--collider NAME] [--set key=value]... [--json FILE] [--png FILE] [--gltf FILE] [--quiet]
//                 [--strict] [--estimate] [--every-frame] [--repetitions N] [--end-state]
#include <algorithm>
#include <cstdio>
#include <iostream>

#include "clothbench/bench/report.hpp"
#include "clothbench/bench/runner.hpp"
#include "clothbench/bench/timing_stats.hpp"
#include "clothbench/bench/viewer_export.hpp"
#include "clothbench/io/errors.hpp"
#include "clothbench/render/picture.hpp"
#include "commands.hpp"

namespace clothbench::cli {

namespace {

struct RunArgs {
  std::string scene, collider, json, png, gltf;
  std::vector<std::string> sets;
  bool quiet = false, strict = false, estimate = false, every_frame = false, end_state = false;
  int repetitions = 1;
};

// the scene as run: its file, the --set overrides and the hash of the effective configuration
void print_config(const RunArgs& a, const RunResult& r) {
  std::string sets;
  for (const auto& s : a.sets) sets += " " + s;
  std::printf("  scene %s, %s; config %s\n", a.scene.c_str(), sets.empty() ? "no --set" : ("--set" + sets).c_str(),
              r.config_hash.c_str());
}

// converged, and the verdict against the accuracy limits (report.hpp)
void print_verdict(const RunResult& r) {
  const std::vector<std::string> misses = limit_misses(r);
  std::string text;
  for (const auto& m : misses) text += (text.empty() ? "" : ", ") + m;
  std::printf(
      "  converged %s; accuracy: %s\n", r.converged ? "yes" : "no",
      misses.empty() ? ("meets the limits (" + limits_text(r) + ")").c_str() : ("MISSES the limits: " + text).c_str());
}

// the runs' JSON (runs_document) with the --set overrides in its context
nlohmann::json run_document(const RunArgs& a, const Scene& scene, const std::vector<RunResult>& runs) {
  nlohmann::json doc = runs_document(runs, scene.name + "/" + scene.collider, a.scene, a.end_state);
  doc["context"]["overrides"] = a.sets;
  return doc;
}

// the repetitions' spread of the time per iteration (the summary is the median run's)
void print_spread(const std::vector<RunResult>& runs) {
  if (runs.size() < 2) return;
  std::vector<double> t;
  for (const RunResult& r : runs) t.push_back(r.ms_per_iteration());
  std::printf(
      "  %zu repetitions: per iteration median %.4f ms, mean %.4f, stddev %.4f (cv %.1f %%), min %.4f, max %.4f\n",
      runs.size(), median(t), mean(t), stddev(t), 100 * stddev(t) / mean(t), *std::min_element(t.begin(), t.end()),
      *std::max_element(t.begin(), t.end()));
}

// ", the body posed N times a frame" where body.pose_fps poses it more than once
std::string poses_per_frame_note(const RunResult& r) {
  if (r.collider_updates <= r.frames) return "";
  return ", the body posed " + std::to_string(r.collider_updates / r.frames) + " times a frame";
}

void print_summary(const RunArgs& a, const RunResult& r) {
  std::printf("%s / %s: %d vertices (%d query points), body %ld triangles\n", r.scene.c_str(), r.collider.c_str(),
              r.vertices, r.query_points, r.body_triangles);
  if (r.collision_triangles > 0)
    std::printf(
        "  the colliders see a copy of %ld triangles (body.collision_triangles), every exact vertex within %.2f mm "
        "of it; the oracle measures against the exact body\n",
        r.collision_triangles, r.proxy_deviation_mm);
  if (!r.device.empty()) std::printf("  device: %s\n", r.device.c_str());
  print_config(a, r);
  std::printf("  %s\n", kDefinitions);
  std::printf("  %s, regime %s: dt %.3f ms (Eq. 4 bound %.3f ms, Gershgorin bound %.3f ms), set-up %.1f ms\n",
              r.integrator.c_str(), r.regime.c_str(), 1e3 * r.dt_s, 1e3 * r.dt_bound_s, 1e3 * r.dt_spectral_s,
              r.setup_ms);
  std::printf("  %-8s %10s %10s %s\n", "phase", "iterations", "time [s]", "reached");
  const auto phase = [](const char* name, const PhaseResult& p, const char* goal) {
    std::printf("  %-8s %10ld %10.2f %s\n", name, p.iterations, p.wall_ms / 1e3, p.reached ? goal : "no");
  };
  phase("sew", r.sew, "sewn");
  phase("drape", r.drape, "settled");
  if (r.frames > 0) phase("animate", r.animate, "clip done");
  std::printf("  per iteration %.3f ms (CD&R %.3f, CS %.3f of which velocity limits %.3f)\n", r.ms_per_iteration(),
              r.cdr_ms_per_iteration(), r.cs_ms_per_iteration(), r.limit_ms_per_iteration());
  if (r.frames > 0)
    std::printf(
        "  %ld frames, %.0f steps per frame, %.2f frames/s (skinning %.2f ms, collider update %.2f ms per frame%s)\n",
        r.frames, r.steps_per_frame, 1e3 * double(r.frames) / r.animate.wall_ms, r.skinning_ms / double(r.frames),
        r.collider_update_ms / double(r.frames), poses_per_frame_note(r).c_str());
  if (r.frames > 0 && r.collider_queries > 0)
    std::printf("  collider queries: %.1f batches per frame, %.3f ms each (%s)\n",
                double(r.collider_queries) / double(r.frames), r.collider_query_ms / double(r.collider_queries),
                "the points' upload and the answers' read-back included where a device answers");
  if (r.divergence) {
    std::printf("  DIVERGED at iteration %ld (%s), vertex %d: %s\n", r.divergence->iteration,
                to_string(r.divergence->phase), r.divergence->vertex, r.divergence->reason.c_str());
    return;
  }
  std::printf(
      "  accuracy: %.2f %% inside, depth max %.2f mm, p95 %.2f mm; crossings %zu (%.2f %% of structural springs); "
      "seam gap %.2f mm; strain max %.1f %%, p99 %.1f %%, %.2f %% of the springs over the limit\n",
      r.accuracy.inside_pct, r.accuracy.depth_max_mm, r.accuracy.depth_p95_mm, r.accuracy.crossings,
      r.accuracy.crossings_pct, r.seam_gap_max_mm, 100 * r.strain_max, 100 * r.strain_p99, 100 * r.strain_over);
  std::printf("  cloth through itself: %zu structural springs (%.2f %%) through a triangle of the cloth%s%s\n",
              r.accuracy.cloth_crossings, r.accuracy.cloth_crossings_pct,
              r.cloth_crossings_where.empty() ? "" : "; panels: ", r.cloth_crossings_where.c_str());
  if (r.frames > 0) std::printf("  seam gap when the measured window starts %.2f mm\n", r.window_seam_gap_mm);
  if (r.frames > 0 && a.every_frame)
    std::printf(
        "  worst frame: %.2f %% inside, depth max %.2f mm, crossings %.2f %%; strain max %.1f %%; cloth through "
        "itself %.2f %% (mean over %zu frames: %.2f %% inside, crossings %.2f %%)\n",
        r.frame_max(&FrameSample::inside_pct), r.frame_max(&FrameSample::depth_max_mm),
        r.frame_max(&FrameSample::crossings_pct), 100 * r.animate_strain_max,
        r.frame_max(&FrameSample::cloth_crossings_pct), r.frame_samples.size(), r.frame_mean(&FrameSample::inside_pct),
        r.frame_mean(&FrameSample::crossings_pct));
  else if (r.frames > 0)
    std::printf("  worst frame: strain max %.1f %% (--every-frame measures inside, depth and crossings too)\n",
                100 * r.animate_strain_max);
  if (!r.strain_max_where.empty()) std::printf("  strain max at %s\n", r.strain_max_where.c_str());
  if (!r.animate_strain_max_where.empty())
    std::printf("  worst frame's strain max at %s\n", r.animate_strain_max_where.c_str());
  if (!r.seam_gap_where.empty()) std::printf("  widest seam gap: %s\n", r.seam_gap_where.c_str());
  if (!r.depth_max_where.empty()) std::printf("  deepest: %s\n", r.depth_max_where.c_str());
  print_verdict(r);
}

int run(const RunArgs& a) {
  Scene scene = load_scene(a.scene, a.sets);
  if (!a.collider.empty()) scene.collider = a.collider;
  RunOptions options;
  options.progress = !a.quiet;
  options.estimate_only = a.estimate;
  options.measure_frames = a.every_frame;
  // --gltf on a moving body: every frame's positions, for the animated file (a repetition starts over)
  std::vector<ViewerFrame> frames;
  if (!a.gltf.empty())
    options.on_frame = [&frames](long frame, double t, const BodyFrame& body, const Simulator& cloth) {
      if (frame == 1) frames.clear();
      frames.push_back({t, body.positions, cloth.positions()});
    };
  std::vector<RunResult> runs;
  for (int i = 0; i < (a.estimate ? 1 : a.repetitions); ++i) {
    if (a.repetitions > 1 && !a.quiet) std::cerr << "repetition " << i + 1 << " of " << a.repetitions << "\n";
    runs.push_back(run_scene(scene, options));
  }
  if (a.estimate) return 0;
  const RunResult& r = median_run(runs);
  print_summary(a, r);
  print_spread(runs);
  if (!a.json.empty()) write_text_file(a.json, run_document(a, scene, runs).dump(2) + "\n");
  if (!a.png.empty()) {
    const std::unique_ptr<PictureRenderer> pictures = make_picture_renderer();
    std::vector<Image> views;
    for (View v : {View::kFront, View::kSide, View::kBack})
      views.push_back(pictures->render(r.final_body, r.mesh, 480, v));
    side_by_side(views).write_png(a.png);
    std::printf("  picture %s (front, side, back) drawn by %s\n", a.png.c_str(), pictures->name().c_str());
  }
  if (!a.gltf.empty()) export_viewer_gltf(a.gltf, r.final_body, r.mesh, frames);
  if (r.divergence) return 3;
  return a.strict && !limit_misses(r).empty() ? 4 : 0;
}

}  // namespace

void add_run_command(CLI::App& app, Action& action) {
  auto args = std::make_shared<RunArgs>();
  auto* cmd = app.add_subcommand(
      "run",
      "Run one scene with one collider; exit 2 on bad input, 3 when the simulation diverged, 4 when it "
      "missed the accuracy limits under --strict");
  cmd->add_option("scene", args->scene, "scene file (TOML)")->required();
  cmd->add_option("--collider", args->collider, "collider name (see `clothbench colliders`)");
  cmd->add_option("--set", args->sets, "override a scene field: section.key=value (repeatable)");
  cmd->add_option("--json", args->json, "write the result as JSON (Google Benchmark layout)");
  cmd->add_flag("--end-state", args->end_state,
                "--json: keep the cloth at its end in each row, as a reference or a run for `report --reference`");
  cmd->add_option("--png", args->png, "write a picture of the dressed body (front, side, back)");
  cmd->add_option("--gltf", args->gltf,
                  "export the dressed body as binary glTF (.glb): the end state, or for a moving body the animation "
                  "(morph targets, at most 16 frames kept); cloth vertices carry _STRAIN and _DISTANCE");
  cmd->add_flag("--quiet", args->quiet, "no progress lines on stderr");
  cmd->add_flag("--strict", args->strict, "exit 4 when the run misses the accuracy limits");
  cmd->add_flag("--estimate", args->estimate, "print how long the run may take and stop (nothing simulated)");
  cmd->add_option("--repetitions", args->repetitions,
                  "run N times: the summary is the median run's; --json writes every run and the aggregates "
                  "(mean, median, stddev, cv) in Google Benchmark's layout")
      ->check(CLI::Range(1, 1000))
      ->capture_default_str();
  cmd->add_flag("--every-frame", args->every_frame,
                "moving bodies: measure accuracy at every animation frame; the verdict counts the worst");
  cmd->callback([&action, args] { action = [args] { return run(*args); }; });
}

}  // namespace clothbench::cli
