// run_scene: wires body, garments, simulator, collider and oracle (the only place that does).
#include "clothbench/bench/runner.hpp"

#include <algorithm>
#include <cstdio>
#include <memory>
#include <optional>
#include <random>
#include <utility>
#include <vector>

#include "animation.hpp"
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
  if (!sim->divergence()) animate(run, r);
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
