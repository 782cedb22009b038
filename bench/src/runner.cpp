// run_scene: wires body, garments, simulator, collider and oracle (the only place that does); the phases are
// dressing.cpp and animation.cpp, the measurements measurement.cpp.
#include "clothbench/bench/runner.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <map>
#include <memory>
#include <optional>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "animation.hpp"
#include "body_source.hpp"
#include "budget.hpp"
#include "clothbench/bench/body_between_frames.hpp"
#include "clothbench/bench/registry.hpp"
#include "clothbench/io/errors.hpp"
#include "clothbench/io/pattern_file.hpp"
#include "clothbench/io/pattern_loader.hpp"
#include "clothbench/sim/body_measure.hpp"
#include "clothbench/sim/garment.hpp"
#include "clothbench/sim/garment_draft.hpp"
#include "clothbench/sim/layers.hpp"
#include "clothbench/sim/sphere_collider.hpp"
#include "dressing.hpp"
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
double RunResult::cloth_ms_per_iteration() const { return per_iteration(&PhaseResult::cloth_ms); }
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

// the body, the colliders and the simulator of one run, made in this order (and unmade in reverse)
struct Rig {
  explicit Rig(const Scene& scene) : source(scene) {}
  Collider& dressing_collider() const { return dresser ? *dresser : *collider; }

  BodySource source;
  BodyFrame frame;                              // the body as the colliders see it (the collision proxy's, with one)
  BodyFrame exact_scratch;                      // the exact body of `frame`, with a collision proxy
  std::unique_ptr<Collider> collider, dresser;  // under test; collider.dress_with's (null without)
  std::unique_ptr<Collider> under;              // collider.cloth_under's (null without)
  std::optional<BodyBetweenFrames> under_skin;  // it as the simulator sees it: collider.cloth_skin_mm thicker
  std::optional<Simulator> sim;
  std::optional<BodyBetweenFrames> dressing;  // the dressing collider as the simulator sees it
};

// the scene as run, in the result
RunResult configuration(const Scene& scene) {
  RunResult r;
  r.scene = scene.name;
  r.collider = scene.collider;
  r.integrator = scene.solver.integrator;
  r.regime = to_string(scene.solver.regime);
  r.config_hash = config_hash(scene);
  r.strain_threshold = scene.solver.limit == "none" ? 0 : double(scene.solver.threshold);
  return r;
}

// the body at the dressing pose (its triangles, and the collision proxy's with its deviation, in the result);
// returns the exact body there
const BodyFrame& pose_body(Rig& rig, RunResult& r) {
  rig.source.frame_into(rig.frame, rig.source.dress_time());
  // the body stands still while the garment is sewn and draped on it: the clip's velocity at that pose (the
  // lead-in starts moving at once) is not the body's there (it stays `moving`: the colliders keep what a
  // moving body needs, velocity maps or a refittable hierarchy, for the animation)
  rig.frame.velocities.setZero();
  const BodyFrame& exact = rig.source.exact(rig.frame, rig.exact_scratch);
  r.body_triangles = exact.triangles.cols();
  if (rig.source.has_proxy()) {
    r.collision_triangles = rig.frame.triangles.cols();
    r.proxy_deviation_mm = proxy_deviation_mm(rig.frame, exact);
  }
  return exact;
}

// how far an outer layer of garments starts clear of the cloth dressed under it, at least [m]: a few millimetres of
// the cloth's own thickness and of the cloth under it sagging while the new layer is sewn
constexpr Real kLayerClearance = 0.01f;
// how far from the dressed cloth an outer layer's point may start and still be moved clear of it [m]: farther than
// the outer garment's placement clears the body by (garment_draft.cpp), so a point placed inside the dressed cloth
// is always moved
constexpr Real kLayerReach = 0.1f;

// a garment of type g.fit drafted from the body's measurements (Durupinar section 2) at the dressing pose
Pattern fitted_pattern(const Scene& scene, const GarmentSpec& g, const BodyFrame& body) {
  try {
    return draft_garment(g.fit, body, measure_body(body), g.ease_cm >= 0 ? g.ease_cm : size_ease_cm(g.size));
  } catch (const std::invalid_argument& e) {
    throw InputError(located(scene.path, 0, "garment.fit = \"" + g.fit + "\": " + e.what()));
  }
}

// one garment of the scene meshed and placed on the exact body (a jittered placement moved by its seed's offset);
// `worn`: how many garments of each pattern name the scene has listed before it
ClothMesh garment_cloth(const Scene& scene, const GarmentSpec& g, const BodyFrame& body,
                        std::map<std::string, int>& worn) {
  const std::string path = g.fit.empty() ? resolve_scene_path(scene, g.file) : scene.path;
  const Pattern pattern = g.fit.empty() ? load_pattern(path) : fitted_pattern(scene, g, body);
  const int nth = ++worn[pattern.name];
  for (const std::string& w : seam_length_warnings(pattern))
    std::fprintf(stderr, "clothbench: warning: %s: %s\n", path.c_str(), w.c_str());
  MeshingOptions options;
  options.target_vertices = g.vertices;
  options.spacing_cm = g.vertices > 0 ? 0 : g.spacing_cm;
  options.attach = g.attach;
  options.on_grid = g.on_grid;
  options.smooth = g.smooth;
  try {
    ClothMesh garment = build_garment(pattern, options, body);
    if (g.jitter_mm > 0) {  // a jittered placement: one random offset for the whole garment, from its seed
      std::mt19937 rng(static_cast<std::mt19937::result_type>(g.seed));
      std::uniform_real_distribution<Real> u(Real(-g.jitter_mm * 1e-3), Real(g.jitter_mm * 1e-3));
      const Vec3 offset(u(rng), u(rng), u(rng));
      garment.positions.colwise() += offset;
    }
    // with several garments a panel is named after its garment too ("shirt.front", "skirt.front"; a pattern
    // worn again is numbered, "skirt#2.front"), so that what a run reports says which garment it means
    if (scene.garments.size() > 1)
      for (std::string& name : garment.panel_names)
        name = pattern.name + (nth > 1 ? "#" + std::to_string(nth) : "") + "." + name;
    return garment;
  } catch (const std::invalid_argument& e) {
    throw InputError(located(path, 0, e.what()));
  }
}

// the scene's garments meshed and placed on the exact body, one cloth per layer ([[garment]] layer), the lowest
// layer first; a layer's garments in the order the scene lists them
std::vector<ClothMesh> build_layers(const Scene& scene, const BodyFrame& body) {
  if (scene.garments.empty()) throw InputError(located(scene.path, 0, "the scene has no [[garment]]"));
  std::map<int, ClothMesh> layers;
  std::map<std::string, int> worn;  // how many garments of each pattern name so far
  for (const auto& g : scene.garments) layers[g.layer].append(garment_cloth(scene, g, body, worn));
  std::vector<ClothMesh> out;
  for (auto& [layer, cloth] : layers) out.push_back(std::move(cloth));
  return out;
}

std::unique_ptr<Collider> make_scene_collider(const Scene& scene, const std::string& name, const BodySource& body) {
  if (name == "sphere") {
    if (!body.is_sphere())
      throw InputError(located(scene.path, 0, "collider.name = \"sphere\" needs body.shape = \"sphere\""));
    return std::make_unique<SphereCollider>(body.sphere_center(0), scene.body.radius, scene.collider_options);
  }
  return make_collider(name, scene.collider_options);
}

// the collider under test on the dressing pose (its set-up time in the result) and, with collider.dress_with,
// the dressing one
void set_up_colliders(const Scene& scene, Rig& rig, RunResult& r) {
  rig.collider = make_scene_collider(scene, scene.collider, rig.source);
  rig.collider->set_body(rig.frame);
  r.setup_ms = rig.collider->stats().setup_ms;
  if (!scene.dress_with.empty() && scene.dress_with != scene.collider) {
    rig.dresser = make_scene_collider(scene, scene.dress_with, rig.source);
    rig.dresser->set_body(rig.frame);
  }
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

// the simulator of the cloth, dressing with the dressing collider (its sizes and steps in the result)
void set_up_simulator(const Scene& scene, ClothMesh cloth, Rig& rig, RunResult& r) {
  try {
    rig.sim.emplace(std::move(cloth), scene.material, scene.solver);
  } catch (const std::invalid_argument& e) {
    throw InputError(located(scene.path, 0, e.what()));
  }
  const Simulator& sim = *rig.sim;
  // the body is answered body.skin_mm thicker while dressing too (the animation wraps its colliders the same way)
  rig.dressing.emplace(rig.dressing_collider(), scene.collider_options.tol, Real(scene.body.skin_mm * 1e-3));
  rig.sim->set_collider(&*rig.dressing);
  r.vertices = sim.mesh().vertex_count();
  r.query_points = r.vertices + (scene.solver.face_queries ? static_cast<int>(sim.mesh().quads.cols()) : 0);
  r.dt_s = sim.dt();
  r.dt_bound_s = sim.stable_dt();
  r.dt_spectral_s = sim.spectral_dt();
  r.k_structural = sim.stiffness(SpringKind::kStructural);
}

// a phase of one layer's dressing added to the run's (whether each was reached is the caller's)
void add_phase(PhaseResult& run, const PhaseResult& layer) {
  run.iterations += layer.iterations, run.wall_ms += layer.wall_ms, run.cpu_ms += layer.cpu_ms;
  run.cdr_ms += layer.cdr_ms, run.cs_ms += layer.cs_ms, run.limit_ms += layer.limit_ms;
  run.cloth_ms += layer.cloth_ms;
}

// the next layer of garments placed clear of the cloth dressed so far (by twice the cloth's thickness, at least
// kLayerClearance) and joined to it, one simulator for both: the dressed cloth where it lies, at rest; its seams,
// closed, merge again at the first step
void wear_next_layer(const RunContext& run, Rig& rig, ClothMesh next, RunResult& r) {
  ClothMesh worn = run.sim.mesh();
  worn.positions = run.sim.positions();
  clear_of_layer(worn.positions, worn.quads, next.positions,
                 std::max(kLayerClearance, 2 * run.scene.solver.self_contact), kLayerReach);
  const Eigen::Index under = worn.positions.cols();
  worn.append(next);
  set_up_simulator(run.scene, std::move(worn), rig, r);
  if (run.scene.cloth_under.empty()) return;
  const Real tol = run.scene.collider_options.tol;
  if (!rig.under) {
    // an open sheet, not a skinned body: its layers overlap where the cloth lies on itself, and a wrinkle that faces
    // in folds a line through it, without either meaning a point is caught between two parts
    ColliderOptions sheet = run.scene.collider_options;
    sheet.overlapping_parts = false;
    rig.under = make_collider(run.scene.cloth_under, sheet);
    rig.under_skin.emplace(*rig.under, tol, Real(run.scene.cloth_skin_mm * 1e-3));
  }
  // drawn again once the cloth under has moved half the distance a point is answered within
  rig.sim->set_layers_under(&*rig.under_skin, under, tol / 2);
}

// sew -> drape (attach) for each layer of garments (the next worn over the dressed ones, then all of them sewn and
// draped together) -> animate, the ETA planned over what is left; a diverged simulation stops there
void run_phases(const RunContext& run, Rig& rig, std::vector<ClothMesh>& layers, const Budget& budget, RunResult& r) {
  bool sewn = true, settled = true;  // every layer
  for (std::size_t k = 0; k < layers.size() && !run.sim.divergence(); ++k) {
    if (k > 0) wear_next_layer(run, rig, std::move(layers[k]), r);
    RunResult layer;
    run.progress.plan(budget.total());
    sew(run, layer);
    run.progress.plan(budget.drape + budget.animate);
    if (!run.sim.divergence()) drape(run, layer);
    if (k == 0)
      r.sew = layer.sew, r.drape = layer.drape;
    else
      add_phase(r.sew, layer.sew), add_phase(r.drape, layer.drape);
    r.sew_iteration_ms.insert(r.sew_iteration_ms.end(), layer.sew_iteration_ms.begin(), layer.sew_iteration_ms.end());
    sewn = sewn && (layer.sew.reached || !run.scene.stop.sew || run.sim.mesh().seam_pairs.cols() == 0);
    settled = settled && layer.drape.reached;
  }
  if (layers.size() > 1) r.sew.reached = sewn, r.drape.reached = settled;
  run.progress.plan(budget.animate);
  if (!run.sim.divergence()) animate(run, r);
  r.divergence = run.sim.divergence();
}

// after the phases: the collider's threads and share of searches (counted from `before`), whether the run
// converged, and the end state measured against the exact body
void finish(const RunContext& run, BodyFrame& exact_scratch, const CollideStats& before, RunResult& r) {
  const Scene& scene = run.scene;
  const Simulator& sim = run.sim;
  const CollideStats stats = run.collider.stats();
  r.threads = r.prepared_frames > 0 ? std::max(stats.threads, 2) : stats.threads;
  r.device = run.collider.device();
  const std::int64_t points = stats.points - before.points, searches = stats.searches - before.searches;
  r.search_share = points > 0 ? double(searches) / double(points) : 0;
  r.converged = !r.divergence && (r.sew.reached || !scene.stop.sew || sim.mesh().seam_pairs.cols() == 0) &&
                (r.drape.reached || scene.stop.drape_max_s == 0) && (!run.source.moves() || r.animate.reached);
  r.final_body = run.source.exact(run.frame, exact_scratch);
  if (!r.divergence) measure(scene, sim, r);
  r.mesh = sim.mesh();
  r.mesh.positions = sim.positions();
}

// collider.cloth_under: an image-space collider. The maps of a sheet of cloth say where a point is behind it as its
// cameras see it; an object-space collider takes the side of the nearest triangle for inside, which past a
// garment's hem or opening is not behind it
void check_cloth_under(const Scene& scene, std::size_t layers) {
  if (scene.cloth_under.empty()) return;
  const auto info = collider_info(scene.cloth_under);
  if (!info || info->family != Family::kImageSpace) {
    std::string names;
    for (const std::string& n : colliders([](const ColliderInfo& c) { return c.family == Family::kImageSpace; }))
      names += (names.empty() ? "" : ", ") + n;
    throw InputError(located(scene.path, 0,
                             "collider.cloth_under = \"" + scene.cloth_under + "\": " +
                                 (info ? "not an image-space collider" : "unknown collider") + " (image space: " +
                                 names + "; cloth against cloth in object space is solver.self_contact_mm)"));
  }
  if (layers < 2)
    std::fprintf(stderr,
                 "clothbench: warning: %s: collider.cloth_under has nothing to answer: the garments are one layer "
                 "([[garment]] layer)\n",
                 scene.path.c_str());
}

RunResult run_unchecked(const Scene& scene, const RunOptions& options) {
  RunResult r = configuration(scene);
  // body, cloth, collider, simulator
  Rig rig(scene);
  std::vector<ClothMesh> layers = build_layers(scene, pose_body(rig, r));
  check_cloth_under(scene, layers.size());
  set_up_colliders(scene, rig, r);
  for (const ClothMesh& layer : layers) warn_start_inside(scene, layer, rig.dressing_collider());
  if (layers.size() > 1 && scene.solver.self_contact <= 0 && scene.cloth_under.empty())
    std::fprintf(stderr,
                 "clothbench: warning: %s: garments dressed in %zu layers without cloth against cloth "
                 "(solver.self_contact_mm = 0, no collider.cloth_under): an outer layer may pass through the one "
                 "under it\n",
                 scene.path.c_str(), layers.size());
  set_up_simulator(scene, std::move(layers[0]), rig, r);
  // up front: how long it may take
  const std::string label = options.label.empty() ? scene.name + "/" + scene.collider : options.label;
  const Budget budget = iteration_budget(scene, rig.source, *rig.sim);
  r.iteration_budget = budget.total();
  Estimate estimate;
  if (options.progress || options.estimate_only) {
    estimate = estimate_seconds(*rig.sim, rig.dressing_collider(), *rig.collider, r.query_points, budget, r.setup_ms);
    r.estimate_s = estimate.dressing_s + estimate.animation_s;
  }
  // up front where the run may be long: the animation's prediction, or the dressing's bound ten times over (a bound
  // the shipped scenes end far inside, noise at every run)
  const double above = options.estimate_above_s;
  if (options.estimate_only || (options.progress && (estimate.animation_s > above || estimate.dressing_s > 10 * above)))
    print_estimate(label, scene, r, budget, estimate);
  if (options.estimate_only) return r;
  // the estimate's timing queries are not the run's: its share of searches counts from here
  const CollideStats before = rig.collider->stats();
  Progress progress(options.progress, label, *rig.sim);
  const RunContext run{scene,    options, rig.source, rig.frame, *rig.collider, rig.dressing_collider(),
                       *rig.sim, progress};
  run_phases(run, rig, layers, budget, r);
  finish(run, rig.exact_scratch, before, r);
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
