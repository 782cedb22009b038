// run_scene: wires body, garments, simulator, collider and oracle (the only place that does).
#include "clothbench/bench/runner.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <random>
#include <utility>
#include <vector>

#include "body_source.hpp"
#include "budget.hpp"
#include "dressing.hpp"
#include "clothbench/bench/body_between_frames.hpp"
#include "clothbench/bench/registry.hpp"
#include "clothbench/io/errors.hpp"
#include "clothbench/io/pattern_file.hpp"
#include "clothbench/io/pattern_loader.hpp"
#include "clothbench/sim/garment.hpp"
#include "clothbench/sim/sphere_collider.hpp"
#include "clothbench/sim/timer.hpp"
#include "frame_ahead.hpp"
#include "measurement.hpp"
#include "progress.hpp"
#include "run_context.hpp"

namespace clothbench {

double RunResult::per_iteration(double PhaseResult::*field) const {
  const long n = iterations();
  return n ? (sew.*field + drape.*field + animate.*field) / double(n) : 0;
}
double RunResult::ms_per_iteration() const { return cdr_ms_per_iteration() + cs_ms_per_iteration(); }
double RunResult::cdr_ms_per_iteration() const { return per_iteration(&PhaseResult::cdr_ms); }
double RunResult::cs_ms_per_iteration() const { return per_iteration(&PhaseResult::cs_ms); }
double RunResult::limit_ms_per_iteration() const { return per_iteration(&PhaseResult::limit_ms); }
double RunResult::cpu_ms_per_iteration() const { return per_iteration(&PhaseResult::cpu_ms); }

double RunResult::frame_mean(double FrameSample::*field) const {
  double sum = 0;
  for (const FrameSample& f : frame_samples) sum += f.*field;
  return frame_samples.empty() ? 0 : sum / double(frame_samples.size());
}

double RunResult::frame_max(double FrameSample::*field) const {
  double m = 0;
  for (const FrameSample& f : frame_samples) m = std::max(m, f.*field);
  return m;
}

const RunResult& median_run(const std::vector<RunResult>& runs) {
  std::vector<const RunResult*> by_time;
  for (const RunResult& r : runs) by_time.push_back(&r);
  std::sort(by_time.begin(), by_time.end(),
            [](const RunResult* a, const RunResult* b) { return a->ms_per_iteration() < b->ms_per_iteration(); });
  return *by_time[by_time.size() / 2];
}

namespace runner_detail {

namespace {

ClothMesh build_cloth(const Scene& scene, const BodyFrame& body) {
  if (scene.garments.empty()) throw InputError(located(scene.path, 0, "the scene has no [[garment]]"));
  ClothMesh cloth;
  for (const auto& g : scene.garments) {
    const std::string path = resolve_scene_path(scene, g.file);
    const Pattern pattern = load_pattern(path);
    for (const std::string& w : seam_length_warnings(pattern))
      std::fprintf(stderr, "clothbench: warning: %s: %s\n", path.c_str(), w.c_str());
    MeshingOptions options;
    options.target_vertices = g.vertices;
    options.spacing_cm = g.vertices > 0 ? 0 : g.spacing_cm;
    options.attach = g.attach;
    try {
      ClothMesh garment = build_garment(pattern, options, body);
      if (g.jitter_mm > 0) {  // a jittered placement: one random offset for the whole garment, from its seed
        std::mt19937 rng(static_cast<std::mt19937::result_type>(g.seed));
        std::uniform_real_distribution<Real> u(Real(-g.jitter_mm * 1e-3), Real(g.jitter_mm * 1e-3));
        const Vec3 offset(u(rng), u(rng), u(rng));
        garment.positions.colwise() += offset;
      }
      cloth.append(garment);
    } catch (const std::invalid_argument& e) {
      throw InputError(located(path, 0, e.what()));
    }
  }
  return cloth;
}

// a garment placed partly inside the body starts sewing from a tangle the push-out may not undo: say so, with how
// much and how deep (as the collider that dresses it answers, one query of every cloth vertex)
void warn_start_inside(const Scene& scene, const ClothMesh& cloth, Collider& collider) {
  std::vector<Contact> contacts(static_cast<std::size_t>(cloth.vertex_count()));
  collider.query(PointsView(cloth.positions), ContactsOut{contacts.data(), contacts.size()});
  long inside = 0;
  Real deepest = 0;
  for (const Contact& c : contacts)
    if (c.hit && c.depth < 0) ++inside, deepest = std::min(deepest, c.depth);
  const double share = contacts.empty() ? 0.0 : 100.0 * double(inside) / double(contacts.size());
  if (share > 1.0)
    std::fprintf(stderr,
                 "clothbench: warning: %s: the garment starts with %ld of %zu vertices (%.1f %%) inside the body, "
                 "the deepest %.1f mm (as %s answers): sewing starts from a tangle (move the pattern's panels out, "
                 "or check the body's size and facing)\n",
                 scene.path.c_str(), inside, contacts.size(), share, -1e3 * double(deepest),
                 std::string(collider.name()).c_str());
}

std::unique_ptr<Collider> make_scene_collider(const Scene& scene, const std::string& name, const BodySource& body) {
  if (name == "sphere") {
    if (!body.is_sphere()) throw InputError(located(scene.path, 0, "collider.name = \"sphere\" needs body.shape = \"sphere\""));
    return std::make_unique<SphereCollider>(body.sphere_center(0), scene.body.radius, scene.collider_options);
  }
  return make_collider(name, scene.collider_options);
}

// the queries of a frame come from the cloth's box grown by what it can move in `frames` frames (image space then
// draws only the map rows that spans)
void set_region(Collider& collider, const Simulator& sim, Real region_margin, int frames) {
  if (!(region_margin > 0)) return;
  Box3 region = bounding_box(sim.positions());
  region.min.array() -= Real(frames) * region_margin, region.max.array() += Real(frames) * region_margin;
  collider.set_query_region(region);
}

// one body frame: evaluate (timed), update the collider, move attachments, then `steps` cloth steps spread over
// the frame; with body.move_between_frames each step sees the body where it was at the step's time
// (BodyBetweenFrames), else the frame's end pose throughout. With `ahead`, a frame at t prepared during the last
// one is taken from it, and the frame at `t_next` (> 0) is prepared while this one's steps run (its map rows from
// the cloth's box now, grown by two frames' margin)
bool advance_frame(const BodySource& source, double t, double frame_dt, long steps, Simulator& sim,
                   BodyBetweenFrames& collider, bool between, Real region_margin, BodyFrame& frame, double& skinning_ms,
                   FrameAhead* ahead, double t_next) {
  // a frame prepared ahead is always the next one asked for (else the collider would make stale maps current)
  if (ahead && ahead->t >= 0 && ahead->t != t)
    throw std::logic_error("advance_frame: the frame prepared ahead is not next");
  if (ahead && ahead->t == t) {
    std::swap(frame, ahead->frame);
    ahead->t = -1;
    skinning_ms += ahead->skinning_ms;
    if (!ahead->prepared) set_region(collider, sim, region_margin, 1);
  } else {
    Stopwatch skin;
    source.frame_into(frame, t);
    skinning_ms += skin.ms();
    set_region(collider, sim, region_margin, 1);
  }
  collider.update_body(frame);
  if (ahead && t_next > 0) {
    set_region(collider, sim, region_margin, 2);
    ahead->start(collider, t_next);
  }
  const bool attached = !sim.mesh().attached.empty();
  if (attached && !between) sim.follow_attachments(frame);
  bool alive = true;
  sim.set_collider(&collider);
  for (long s = 0; s < steps && alive; ++s) {
    const Real tau = between ? Real(frame_dt * double(steps - 1 - s) / double(steps)) : Real(0);
    collider.set_time_before_pose(tau);
    // attached vertices start the step where the body had them a step before tau, and the step's dt v brings
    // them to tau (held once per frame, they would run a frame ahead of the body and jump back)
    if (attached && between) sim.follow_attachments(frame, tau + sim.dt());
    alive = sim.step();
  }
  if (ahead) ahead->wait();
  return alive;
}

// the lead-in (dress_at_s -> start_s, with the dressing collider, not measured), then the measured window
void animate(const Scene& scene, const BodySource& source, Simulator& sim, Collider& collider, Collider& dresser,
             BodyFrame& frame, Progress& progress, const RunOptions& options, RunResult& r) {
  if (!source.moves()) return;
  sim.set_phase(Phase::kAnimate);
  const double frame_dt = 1.0 / scene.body.fps;
  const auto [steps, lead_in, frames] = animation_plan(scene, source, sim.dt());
  r.steps_per_frame = double(steps);
  double unmeasured_ms = 0;
  bool alive = true;
  const Real tol = scene.collider_options.tol;
  const bool between = scene.body.move_between_frames;
  const Real skin = Real(scene.body.skin_mm * 1e-3);
  const Real margin = Real(scene.collider_options.query_margin_mm * 1e-3);
  BodyBetweenFrames dresser_between(dresser, tol, skin), collider_between(collider, tol, skin);
  std::optional<FrameAhead> lead_ahead, ahead;
  if (scene.body.prepare_ahead) lead_ahead.emplace(source), ahead.emplace(source);
  FrameAhead* const lead_pipe = lead_ahead ? &*lead_ahead : nullptr;
  FrameAhead* const pipe = ahead ? &*ahead : nullptr;
  const auto lead_in_time = [&](long f) { return source.dress_time() + double(f) * frame_dt; };
  const auto window_time = [&](long f) { return source.start() + double(f) * frame_dt; };
  for (long f = 1; f <= lead_in && alive; ++f) {
    alive = advance_frame(source, lead_in_time(f), frame_dt, steps, sim, dresser_between, between, margin, frame,
                          unmeasured_ms, lead_pipe, f < lead_in ? lead_in_time(f + 1) : 0);
    progress.report("animate (lead-in): frame %ld of %ld", f, lead_in);
  }
  collider.update_body(frame);
  r.window_seam_gap_mm = 1e3 * double(sim.seam_gap_max());
  progress.plan(frames * steps);  // the measured window's collider sets the pace from here
  PhaseClock clock{sim};
  const CollideStats before = collider.stats();
  double not_animation_ms = 0, not_animation_cpu_ms = 0;
  BodyFrame exact_scratch;  // the exact body of a frame, with a collision proxy
  for (long f = 1; f <= frames && alive; ++f) {
    const double t = window_time(f);
    alive = advance_frame(source, t, frame_dt, steps, sim, collider_between, between, margin, frame, r.skinning_ms,
                          pipe, f < frames ? window_time(f + 1) : 0);
    r.prepared_frames += pipe && f < frames && pipe->prepared;
    ++r.frames;
    Stopwatch outside;  // the strain, the oracle and the caller's callback are not the animation's time
    const double outside_cpu = thread_cpu_ms();
    const StrainStats strain = sim.strain();
    r.animate_strain_max = std::max(r.animate_strain_max, double(strain.max));
    const bool measured = options.measure_frames && alive;
    if (measured || options.on_frame) {  // the exact body only when something looks at it
      const BodyFrame& exact = source.exact(frame, exact_scratch);
      if (measured) measure_frame(exact, sim, strain, t, r);
      if (options.on_frame) options.on_frame(f, t, exact, sim);
    }
    not_animation_ms += outside.ms();
    not_animation_cpu_ms += thread_cpu_ms() - outside_cpu;
    progress.report("animate: frame %ld of %ld (t = %.2f s)", f, frames, t);
  }
  sim.set_collider(&collider);  // the wrappers end here
  r.animate.reached = alive && r.frames == frames;
  const CollideStats after = collider.stats();
  r.collider_update_ms = after.update_ms - before.update_ms;
  r.collider_queries = after.queries - before.queries;
  r.collider_query_ms = after.query_ms - before.query_ms;
  clock.finish(r.animate);
  r.animate.wall_ms -= not_animation_ms;
  r.animate.cpu_ms -= not_animation_cpu_ms;
}

RunResult run_unchecked(const Scene& scene, const RunOptions& options) {
  RunResult r;
  r.scene = scene.name;
  r.collider = scene.collider;
  r.integrator = scene.solver.integrator;
  r.regime = to_string(scene.solver.regime);
  r.config_hash = config_hash(scene);
  r.strain_threshold = scene.solver.limit == "none" ? 0 : double(scene.solver.threshold);
  // body, cloth, collider, simulator
  const BodySource source(scene);
  BodyFrame frame;
  source.frame_into(frame, source.dress_time());
  // the body stands still while the garment is sewn and draped on it: the clip's velocity at that pose (the
  // lead-in starts moving at once) is not the body's there (it stays `moving`: the colliders keep what a
  // moving body needs, velocity maps or a refittable hierarchy, for the animation)
  frame.velocities.setZero();
  BodyFrame exact_scratch;
  const BodyFrame& exact = source.exact(frame, exact_scratch);
  r.body_triangles = exact.triangles.cols();
  if (source.has_proxy()) {
    r.collision_triangles = frame.triangles.cols();
    r.proxy_deviation_mm = proxy_deviation_mm(frame, exact);
  }
  ClothMesh cloth = build_cloth(scene, exact);
  std::unique_ptr<Collider> collider = make_scene_collider(scene, scene.collider, source);
  collider->set_body(frame);
  r.setup_ms = collider->stats().setup_ms;
  std::unique_ptr<Collider> dresser;
  if (!scene.dress_with.empty() && scene.dress_with != scene.collider) {
    dresser = make_scene_collider(scene, scene.dress_with, source);
    dresser->set_body(frame);
  }
  warn_start_inside(scene, cloth, dresser ? *dresser : *collider);
  std::optional<Simulator> sim;
  try {
    sim.emplace(std::move(cloth), scene.material, scene.solver);
  } catch (const std::invalid_argument& e) {
    throw InputError(located(scene.path, 0, e.what()));
  }
  // the body is answered body.skin_mm thicker while dressing too (the animation wraps its colliders the same way)
  BodyBetweenFrames dressing(dresser ? *dresser : *collider, scene.collider_options.tol,
                             Real(scene.body.skin_mm * 1e-3));
  sim->set_collider(&dressing);
  r.vertices = sim->mesh().vertex_count();
  r.query_points = r.vertices + (scene.solver.face_queries ? static_cast<int>(sim->mesh().quads.cols()) : 0);
  r.dt_s = sim->dt();
  r.dt_bound_s = sim->stable_dt();
  r.dt_spectral_s = sim->spectral_dt();
  r.k_structural = sim->stiffness(SpringKind::kStructural);
  // up front: how long it may take
  const std::string label = options.label.empty() ? scene.name + "/" + scene.collider : options.label;
  const Budget budget = iteration_budget(scene, source, *sim);
  r.iteration_budget = budget.total();
  Estimate estimate;
  if (options.progress || options.estimate_only) {
    estimate = estimate_seconds(*sim, dresser ? *dresser : *collider, *collider, r.query_points, budget, r.setup_ms);
    r.estimate_s = estimate.dressing_s + estimate.animation_s;
  }
  // up front where the run may be long: the animation's prediction, or the dressing's bound ten times over (a bound
  // the shipped scenes end far inside, noise at every run)
  const double above = options.estimate_above_s;
  if (options.estimate_only ||
      (options.progress && (estimate.animation_s > above || estimate.dressing_s > 10 * above)))
    print_estimate(label, scene, r, budget, estimate);
  if (options.estimate_only) return r;
  // the estimate's timing queries are not the run's: its share of searches counts from here
  const CollideStats before = collider->stats();
  // sew -> attach -> drape -> animate
  Progress progress(options.progress, label, *sim);
  const RunContext run{scene, options, source, frame, *collider, dresser ? *dresser : *collider, *sim, progress};
  progress.plan(budget.total());
  sew(run, r);
  attach(run);
  progress.plan(budget.drape + budget.animate);
  if (!sim->divergence()) drape(run, r);
  progress.plan(budget.animate);
  if (!sim->divergence())
    animate(scene, source, *sim, *collider, dresser ? *dresser : *collider, frame, progress, options, r);
  r.divergence = sim->divergence();
  const CollideStats stats = collider->stats();
  r.threads = r.prepared_frames > 0 ? std::max(stats.threads, 2) : stats.threads;
  r.device = collider->device();
  const std::int64_t points = stats.points - before.points, searches = stats.searches - before.searches;
  r.search_share = points > 0 ? double(searches) / double(points) : 0;
  r.converged = !r.divergence && (r.sew.reached || !scene.stop.sew || sim->mesh().seam_pairs.cols() == 0) &&
                (r.drape.reached || scene.stop.drape_max_s == 0) && (!source.moves() || r.animate.reached);
  r.final_body = source.exact(frame, exact_scratch);
  if (!r.divergence) measure(scene, *sim, r);
  r.mesh = sim->mesh();
  r.mesh.positions = sim->positions();
  return r;
}

}  // namespace

}  // namespace runner_detail

RunResult run_scene(const Scene& scene, const RunOptions& options) {
  try {
    return runner_detail::run_unchecked(scene, options);
  } catch (const InputError& e) {
    // every input error of a run names the scene first, then what it referred to
    const std::string what = e.what();
    if (scene.path.empty() || what.rfind(scene.path, 0) == 0) throw;
    throw InputError(scene.path + ": " + what);
  }
}

}  // namespace clothbench
