#pragma once
/// Runs a scene: body and garments loaded, sew (seam forces, no gravity) -> drape (gravity) until
/// settled -> animate (moving bodies), one collider, accuracy from the exact oracle at the end.
#include <functional>
#include <optional>
#include <string>

#include "clothbench/bench/oracle.hpp"
#include "clothbench/bench/scene.hpp"
#include "clothbench/sim/simulator.hpp"

namespace clothbench {

/// The definitions every table prints in its header.
inline constexpr const char* kDefinitions =
    "iteration = one step of dt of the scene's solver.integrator (explicit Euler, Eq. 3, unless stated) with detection, "
    "response and limits; "
    "sewn = every seam pair closer than stop.sewn_gap_mm (or merged); "
    "settled = RMS cloth speed below stop.settle_speed for stop.settle_window_s of simulated time; "
    "times are wall clock on one thread, set-up (maps/BVH) excluded";

/// One phase of a run.
struct PhaseResult {
  long iterations = 0;
  double wall_ms = 0;    ///< simulation wall time of the phase (CD&R + CS + body updates)
  double cpu_ms = 0;     ///< CPU time of the phase's thread over the same span (the stop checks included)
  double cdr_ms = 0;     ///< collision detection and response
  double cs_ms = 0;      ///< cloth simulation
  double limit_ms = 0;   ///< of cs_ms: the velocity limits
  double cloth_ms = 0;   ///< of cdr_ms: cloth against cloth (solver.self_contact_mm, collider.cloth_under)
  bool reached = false;  ///< sew: sewn; drape: settled; animate: clip finished
};

/// The exact oracle at one animation frame (RunOptions::measure_frames).
struct FrameSample {
  double t_s = 0;              ///< animation time [s]
  double inside_pct = 0, depth_max_mm = 0, crossings_pct = 0;
  double strain_max = 0;       ///< largest structural strain, fraction
  double strain_p99 = 0;       ///< 99th percentile of the structural strains, fraction
  double cloth_crossings_pct = 0;  ///< structural springs through the cloth itself [%] (cloth_crossings.hpp)
};

/// What a run measured. Times in ms unless named otherwise.
struct RunResult {
  std::string scene, collider;
  std::string device;  ///< what answered the collider's queries, where hardware or a driver (Collider::device())
  std::string integrator, regime;  ///< solver.integrator and solver.regime of the run
  std::string config_hash;      ///< config_hash of the scene as run (scene.hpp)
  double strain_threshold = 0;  ///< solver.threshold when a super-elasticity limit was on, else 0
  long iteration_budget = 0;    ///< most iterations the stop rule allows (phases end early at their goal)
  double estimate_s = 0;        ///< simulation time estimated up front, sewing and draping at their budget [s] (results never depend on it)
  int vertices = 0, query_points = 0;
  long body_triangles = 0;        ///< the exact body's (the oracle's)
  long collision_triangles = 0;   ///< body.collision_triangles: the colliders' simplified copy's; 0 without one
  double proxy_deviation_mm = 0;  ///< with a simplified copy: the largest distance of an exact body vertex from it
                                  ///< (at the dressing pose) [mm]
  double dt_s = 0, dt_bound_s = 0, dt_spectral_s = 0;
  double k_structural = 0;      ///< the structural springs' stiffness as run (the automatic one when 0 was given) [N/m]
  PhaseResult sew, drape, animate;
  long frames = 0;              ///< animation frames (body updates)
  double steps_per_frame = 0;
  double skinning_ms = 0;       ///< all body frame evaluations (LBS)
  double collider_update_ms = 0;///< all collider updates (re-render / refit)
  long collider_updates = 0;    ///< the measured window's body poses (Collider::update_body calls; body.pose_fps)
  long collider_queries = 0;    ///< the measured animation's query batches (Collider::query calls)
  double collider_query_ms = 0; ///< their time (is-egl: the points' upload and the answers' read-back included)
  double setup_ms = 0;          ///< collider set-up (maps rendered / BVH built)
  double search_share = 0;      ///< object space: share of the collider's query points that needed a
                                ///< closest-point search (CollideStats::searches); 0 for the others
  int threads = 1;              ///< the collider's worker threads; 2 at least when frames were prepared ahead
  long prepared_frames =
      0;  ///< measured frames whose body the collider prepared on a second thread (body.prepare_ahead)
  Accuracy accuracy;            ///< vertices and (with face queries) quad midpoints, end state
  double seam_gap_max_mm = 0;   ///< widest opening along the seams, pairs and vertices without a partner [mm]
  double strain_max = 0, strain_p99 = 0;
  double strain_over = 0;       ///< share of the structural springs over threshold + 1 %, fraction
  std::string strain_max_where; ///< the most strained structural spring: its ends, height, contacts, seams
  std::string cloth_crossings_where;  ///< the panels of the springs through the cloth and of the triangles they pass (end)
  std::string seam_gap_where;   ///< the widest opening along the seams: its vertices and panels ("" when closed)
  std::string depth_max_where;  ///< the deepest point inside the body: of the deepest measured frame (where, when,
                                ///< contact), or of the end state when that is deeper ("" when none is inside)
  double kinetic_energy = 0;
  double animate_strain_max = 0;           ///< largest structural strain seen at any animation frame
  std::string animate_strain_max_where;    ///< that frame's most strained spring (as strain_max_where) and its time
  std::vector<FrameSample> frame_samples;  ///< RunOptions::measure_frames: every measured animation frame
  double window_seam_gap_mm = 0;      ///< largest seam pair gap when the measured animation window starts [mm]
  std::vector<float> sew_iteration_ms;  ///< wall time of every sew iteration (RunOptions::trace)
  bool converged = false;       ///< sewn (when sewing) and settled
  std::optional<Divergence> divergence;
  BodyFrame final_body;         ///< for pictures
  ClothMesh mesh;               ///< topology of the cloth (positions: the end state)

  long iterations() const { return sew.iterations + drape.iterations + animate.iterations; }
  double total_s() const { return (sew.wall_ms + drape.wall_ms + animate.wall_ms) / 1e3; }
  /// Wall time to dressed on one thread, the collider's set-up included [s].
  double dressed_wall_s() const { return setup_ms / 1e3 + total_s(); }
  /// A phase field (ms) summed over the phases, per iteration (0 without iterations).
  double per_iteration(double PhaseResult::*field) const;
  double ms_per_iteration() const;
  double cdr_ms_per_iteration() const;
  double cs_ms_per_iteration() const;
  double limit_ms_per_iteration() const;  ///< of cs: the velocity limits' passes
  double cloth_ms_per_iteration() const;  ///< of cdr: cloth against cloth
  /// CPU time of the running thread per iteration over the phases (collider worker threads not counted).
  double cpu_ms_per_iteration() const;
  /// Mean and largest value over frame_samples of a field (0 without samples): the worst frame's inside,
  /// depth and crossings are frame_max(&FrameSample::inside_pct) and so on.
  double frame_mean(double FrameSample::*field) const;
  double frame_max(double FrameSample::*field) const;
};

/// Of repetitions of one configuration, the run with the median time per iteration (of an even count the
/// upper middle one); the simulation is deterministic, so only the times differ. `runs` must not be empty.
const RunResult& median_run(const std::vector<RunResult>& runs);

/// Called after every animation frame: frame number (1-based), animation time [s], body, cloth.
using FrameCallback = std::function<void(long frame, double t, const BodyFrame& body, const Simulator& cloth)>;

/// How run_scene reports.
struct RunOptions {
  bool progress = true;   ///< progress lines on stderr when a run takes more than a second
  std::string label;      ///< prefix of progress lines
  bool trace = false;     ///< record the wall time of every sew iteration
  FrameCallback on_frame; ///< optional, per animation frame
  bool measure_frames = false;  ///< oracle accuracy at every animation frame (animate_*_max)
  double estimate_above_s = 10; ///< with progress: print the estimate up front when the animation's exceeds this, or the dressing's bound ten times this [s]
  bool estimate_only = false;   ///< print the estimate and return before the sew phase (nothing simulated)
};

/// "2 min 25 s", "12 s", "1 h 05 min": a duration for people.
std::string format_duration(double seconds);

/// Runs the scene with its collider. Throws InputError for bad input (files, parameters);
/// a diverged simulation is reported in the result, not thrown.
RunResult run_scene(const Scene& scene, const RunOptions& options = {});

}  // namespace clothbench
