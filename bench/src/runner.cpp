// run_scene: wires body, garments, simulator, collider and oracle (the only place that does).
#include "runner.hpp"

#include <cmath>
#include <cstdio>
#include <memory>

#include "clothbench/io/body_loader.hpp"
#include "clothbench/io/errors.hpp"
#include "clothbench/sim/garment.hpp"
#include "clothbench/sim/sphere_collider.hpp"
#include "clothbench/sim/timer.hpp"
#include "pattern_file.hpp"
#include "registry.hpp"

namespace clothbench {

double RunResult::ms_per_iteration() const { return cdr_ms_per_iteration() + cs_ms_per_iteration(); }
double RunResult::cdr_ms_per_iteration() const {
  const long n = iterations();
  return n ? (sew.cdr_ms + drape.cdr_ms + animate.cdr_ms) / double(n) : 0;
}
double RunResult::cs_ms_per_iteration() const {
  const long n = iterations();
  return n ? (sew.cs_ms + drape.cs_ms + animate.cs_ms) / double(n) : 0;
}

namespace {

// the body and its motion: a (possibly animated) mesh, or a sphere moving at constant velocity
class BodySource {
 public:
  BodySource(const Scene& scene) : spec_(scene.body) {
    if (spec_.shape == "sphere") {
      sphere_ = make_sphere_body(Vec3::Zero(), spec_.radius, 48, 96);
      t1_ = spec_.move_s;
      return;
    }
    model_.emplace(load_body(resolve_scene_path(scene, spec_.file)));
    if (spec_.animation.empty()) return;
    anim_ = model_->animation_index(spec_.animation);
    const double clip = model_->animations()[anim_].duration_s;
    dress_ = spec_.dress_at_s;
    t0_ = spec_.start_s;
    t1_ = spec_.end_s < 0 ? clip : spec_.end_s;
    if (!(dress_ <= t0_ && t0_ < t1_) || t1_ > clip + 1e-9)
      throw InputError(located(scene.path, 0, "body: need dress_at_s <= start_s < end_s inside the clip [0, " +
                                                   std::to_string(clip) + "] s, got " + std::to_string(dress_) +
                                                   ", " + std::to_string(t0_) + ", " + std::to_string(t1_)));
  }

  bool moves() const { return t1_ > t0_; }
  double dress_time() const { return dress_; }
  double start() const { return t0_; }
  double end() const { return t1_; }
  bool is_sphere() const { return !model_; }
  Vec3 sphere_center(double t) const { return spec_.center + spec_.velocity * Real(t); }

  // the frame at time t (animation time, or seconds of sphere motion)
  void frame_into(BodyFrame& out, double t) const {
    if (model_) {
      if (anim_ < 0) {
        out = model_->rest();
      } else {
        model_->frame_into(out, anim_, t, spec_.walk_in_place);
      }
      return;
    }
    // at rest while dressing (t = 0), moving at constant velocity during the animation
    out = sphere_;
    out.positions.colwise() += sphere_center(t);
    if (t > 0) {
      out.velocities.colwise() = spec_.velocity;
      out.moving = true;
    }
  }

 private:
  BodySpec spec_;
  std::optional<BodyModel> model_;
  BodyFrame sphere_;
  int anim_ = -1;
  double dress_ = 0, t0_ = 0, t1_ = 0;
};

ClothMesh build_cloth(const Scene& scene, const BodyFrame& body) {
  if (scene.garments.empty()) throw InputError(located(scene.path, 0, "the scene has no [[garment]]"));
  ClothMesh cloth;
  for (const auto& g : scene.garments) {
    const Pattern pattern = load_pattern(resolve_scene_path(scene, g.file));
    MeshingOptions options;
    options.target_vertices = g.vertices;
    options.spacing_cm = g.vertices > 0 ? 0 : g.spacing_cm;
    options.attach = g.attach;
    try {
      cloth.append(build_garment(pattern, options, body));
    } catch (const std::invalid_argument& e) {
      throw InputError(located(resolve_scene_path(scene, g.file), 0, e.what()));
    }
  }
  return cloth;
}

std::unique_ptr<Collider> make_scene_collider(const Scene& scene, const std::string& name, const BodySource& body) {
  if (name == "sphere") {
    if (!body.is_sphere()) throw InputError(located(scene.path, 0, "collider.name = \"sphere\" needs body.shape = \"sphere\""));
    return std::make_unique<SphereCollider>(body.sphere_center(0), scene.body.radius, scene.collider_options);
  }
  return make_collider(name, scene.collider_options);
}

// progress on stderr, at most once a second, only after the first second
class Progress {
 public:
  Progress(bool on, std::string label) : on_(on), label_(std::move(label)) {}
  template <class... A>
  void report(const char* format, A... args) {
    if (!on_ || clock_.ms() < next_ms_) return;
    next_ms_ = clock_.ms() + 1000;
    std::fprintf(stderr, "  [%s %.0f s] ", label_.c_str(), clock_.ms() / 1e3);
    std::fprintf(stderr, format, args...);
    std::fputc('\n', stderr);
  }

 private:
  bool on_;
  std::string label_;
  Stopwatch clock_;
  double next_ms_ = 1000;
};

// the simulator's cumulative timings as a phase's share
struct PhaseClock {
  const Simulator& sim;
  SimTimings start = sim.timings();
  Stopwatch wall;
  void finish(PhaseResult& r) const {
    r.iterations = sim.timings().iterations - start.iterations;
    r.cdr_ms = sim.timings().cdr_ms - start.cdr_ms;
    r.cs_ms = sim.timings().cs_ms - start.cs_ms;
    r.wall_ms = wall.ms();
  }
};

long iteration_cap(const Scene& scene, double seconds, double dt) {
  const long by_time = static_cast<long>(std::ceil(seconds / dt));
  return scene.stop.max_iterations > 0 ? std::min(by_time, scene.stop.max_iterations) : by_time;
}

void sew(const Scene& scene, Simulator& sim, Progress& progress, bool trace, RunResult& run) {
  PhaseResult& r = run.sew;
  if (!scene.stop.sew || sim.mesh().seam_pairs.cols() == 0) return;
  sim.set_phase(Phase::kSew);
  PhaseClock clock{sim};
  const long cap = iteration_cap(scene, scene.stop.sew_max_s, sim.dt());
  const Real gap = scene.stop.sewn_gap_mm * 1e-3f;
  for (long i = 0; i < cap && !r.reached; ++i) {
    Stopwatch iteration;
    const bool alive = sim.step();
    if (trace) run.sew_iteration_ms.push_back(float(iteration.ms()));
    if (!alive) break;
    r.reached = sim.seam_gap_max() <= gap || sim.sewn_fraction() >= 1;
    progress.report("sew: iteration %ld, seam gap %.1f mm", i + 1, 1e3 * double(sim.seam_gap_max()));
  }
  clock.finish(r);
}

Real rms_speed(const Simulator& sim) {
  const double mass = sim.masses().sum();
  return mass > 0 ? Real(std::sqrt(2 * sim.kinetic_energy() / mass)) : 0;
}

void drape(const Scene& scene, Simulator& sim, Progress& progress, PhaseResult& r) {
  sim.set_phase(Phase::kDrape);
  PhaseClock clock{sim};
  const long cap = iteration_cap(scene, scene.stop.drape_max_s, sim.dt());
  const long window = std::max(1L, static_cast<long>(std::ceil(scene.stop.settle_window_s / sim.dt())));
  long calm = 0;
  for (long i = 0; i < cap && !r.reached; ++i) {
    if (!sim.step()) break;
    calm = rms_speed(sim) < scene.stop.settle_speed ? calm + 1 : 0;
    r.reached = calm >= window;
    progress.report("drape: iteration %ld, RMS speed %.3f m/s", i + 1, double(rms_speed(sim)));
  }
  clock.finish(r);
}

// one body frame: evaluate (timed), update the collider, move attachments, then `steps` cloth steps
bool advance_frame(const BodySource& source, double t, long steps, Simulator& sim, Collider& collider,
                   BodyFrame& frame, double& skinning_ms) {
  Stopwatch skin;
  source.frame_into(frame, t);
  skinning_ms += skin.ms();
  if (auto* sphere = dynamic_cast<SphereCollider*>(&collider)) sphere->set_sphere(source.sphere_center(t), frame.velocities.col(0));
  collider.update_body(frame);
  if (!sim.mesh().attached.empty()) sim.follow_attachments(frame);
  bool alive = true;
  for (long s = 0; s < steps && alive; ++s) alive = sim.step();
  return alive;
}

// the lead-in (dress_at_s -> start_s, with the dressing collider, not measured), then the measured window
void animate(const Scene& scene, const BodySource& source, Simulator& sim, Collider& collider, Collider& dresser,
             BodyFrame& frame, Progress& progress, const RunOptions& options, RunResult& r) {
  if (!source.moves()) return;
  sim.set_phase(Phase::kAnimate);
  const double frame_dt = 1.0 / scene.body.fps;
  const long steps = std::max(1L, static_cast<long>(std::ceil(frame_dt / sim.dt())));
  r.steps_per_frame = double(steps);
  const long lead_in = static_cast<long>(std::floor((source.start() - source.dress_time()) / frame_dt + 1e-9));
  const long frames = static_cast<long>(std::floor((source.end() - source.start()) / frame_dt + 1e-9));
  double unmeasured_ms = 0;
  bool alive = true;
  sim.set_collider(&dresser);
  for (long f = 1; f <= lead_in && alive; ++f) {
    alive = advance_frame(source, source.dress_time() + double(f) * frame_dt, steps, sim, dresser, frame, unmeasured_ms);
    progress.report("animate (lead-in): frame %ld of %ld", f, lead_in);
  }
  sim.set_collider(&collider);
  collider.update_body(frame);
  PhaseClock clock{sim};
  const double update_before = collider.stats().update_ms;
  for (long f = 1; f <= frames && alive; ++f) {
    const double t = source.start() + double(f) * frame_dt;
    alive = advance_frame(source, t, steps, sim, collider, frame, r.skinning_ms);
    ++r.frames;
    r.animate_strain_max = std::max(r.animate_strain_max, double(sim.strain().max));
    if (options.measure_frames && alive) {
      const Oracle oracle(frame);
      Accuracy a = oracle.measure(sim.positions());
      oracle.measure_crossings(sim.positions(), structural_springs(sim.mesh()), a);
      r.animate_inside_max_pct = std::max(r.animate_inside_max_pct, a.inside_pct);
      r.animate_depth_max_mm = std::max(r.animate_depth_max_mm, a.depth_max_mm);
      r.animate_crossings_max_pct = std::max(r.animate_crossings_max_pct, a.crossings_pct);
    }
    if (options.on_frame) options.on_frame(f, t, frame, sim);
    progress.report("animate: frame %ld of %ld (t = %.2f s)", f, frames, t);
  }
  r.animate.reached = alive && r.frames == frames;
  r.collider_update_ms = collider.stats().update_ms - update_before;
  clock.finish(r.animate);
}

// accuracy of the end state against the exact body (vertices, and quad midpoints with face queries;
// crossings of the structural springs; penetrating faces)
void measure(const Scene& scene, const Simulator& sim, RunResult& r) {
  Oracle oracle(r.final_body);
  Points3 points = sim.positions();
  if (scene.solver.face_queries && sim.quad_midpoints().cols() > 0) {
    Points3 all(3, points.cols() + sim.quad_midpoints().cols());
    all << points, sim.quad_midpoints();
    points = std::move(all);
  }
  r.accuracy = oracle.measure(points);
  oracle.measure_crossings(sim.positions(), structural_springs(sim.mesh()), r.accuracy);
  oracle.measure_faces(sim.positions(), sim.mesh().quads, r.accuracy);
  r.seam_gap_max_mm = 1e3 * double(sim.seam_gap_max());
  const StrainStats strain = sim.strain();
  r.strain_max = strain.max;
  r.strain_p99 = strain.p99;
  r.kinetic_energy = sim.kinetic_energy();
}

}  // namespace

namespace {

RunResult run_unchecked(const Scene& scene, const RunOptions& options) {
  RunResult r;
  r.scene = scene.name;
  r.collider = scene.collider;
  // body, cloth, collider, simulator
  const BodySource source(scene);
  BodyFrame frame;
  source.frame_into(frame, source.dress_time());
  r.body_triangles = frame.triangles.cols();
  ClothMesh cloth = build_cloth(scene, frame);
  std::unique_ptr<Collider> collider = make_scene_collider(scene, scene.collider, source);
  collider->set_body(frame);
  r.setup_ms = collider->stats().setup_ms;
  std::unique_ptr<Collider> dresser;
  if (!scene.dress_with.empty() && scene.dress_with != scene.collider) {
    dresser = make_scene_collider(scene, scene.dress_with, source);
    dresser->set_body(frame);
  }
  std::optional<Simulator> sim;
  try {
    sim.emplace(std::move(cloth), scene.material, scene.solver);
  } catch (const std::invalid_argument& e) {
    throw InputError(located(scene.path, 0, e.what()));
  }
  sim->set_collider(dresser ? dresser.get() : collider.get());
  r.vertices = sim->mesh().vertex_count();
  r.query_points = r.vertices + (scene.solver.face_queries ? static_cast<int>(sim->mesh().quads.cols()) : 0);
  r.dt_s = sim->dt();
  r.dt_bound_s = sim->stable_dt();
  r.dt_spectral_s = sim->spectral_dt();
  // sew -> drape -> animate
  Progress progress(options.progress, options.label.empty() ? scene.name + "/" + scene.collider : options.label);
  sew(scene, *sim, progress, options.trace, r);
  // attachments (Durupinar 3.2) bind where sewing left the waistband, before gravity comes on
  if (!sim->mesh().attached.empty()) sim->attach(frame);
  if (!sim->divergence()) drape(scene, *sim, progress, r.drape);
  if (!sim->divergence())
    animate(scene, source, *sim, *collider, dresser ? *dresser : *collider, frame, progress, options, r);
  r.divergence = sim->divergence();
  r.threads = collider->stats().threads;
  r.converged = !r.divergence && (r.sew.reached || !scene.stop.sew || sim->mesh().seam_pairs.cols() == 0) &&
                (r.drape.reached || scene.stop.drape_max_s == 0) && (!source.moves() || r.animate.reached);
  r.final_body = frame;
  if (!r.divergence) measure(scene, *sim, r);
  r.mesh = sim->mesh();
  r.mesh.positions = sim->positions();
  return r;
}

}  // namespace

RunResult run_scene(const Scene& scene, const RunOptions& options) {
  try {
    return run_unchecked(scene, options);
  } catch (const InputError& e) {
    // every input error of a run names the scene first, then what it referred to
    const std::string what = e.what();
    if (scene.path.empty() || what.rfind(scene.path, 0) == 0) throw;
    throw InputError(scene.path + ": " + what);
  }
}

}  // namespace clothbench
