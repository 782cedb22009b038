#pragma once
/// Scene files (TOML, documented in scenes/README.md): body and motion, garments, material,
/// solver, collider, stop rule. Every field has a default; unknown keys are errors (file:line, with
/// the nearest known key of the table).
#include <string>
#include <vector>

#include "clothbench/sim/collider.hpp"
#include "clothbench/sim/simulator.hpp"

namespace clothbench {

/// The body: a mesh file (static or animated) or an analytic sphere moving at constant velocity.
struct BodySpec {
  std::string file = "debian:human";  ///< "debian:human", "data:REL" (data root) or a path (scene-relative)
  std::string animation;              ///< empty: static rest pose
  double dress_at_s = 0;              ///< garments are sewn and draped on the frame at this time [s]
  double start_s = 0;                 ///< measured animation window [start_s, end_s] [s]; frames between
                                      ///< dress_at_s and start_s are a lead-in: simulated, not measured
  double end_s = -1;                  ///< < 0: the clip's end
  bool walk_in_place = true;          ///< remove the root's horizontal travel
  double fps = 60;                    ///< body frames per second of animation (collider updates)
  double pose_fps = 0;                ///< > 0: the body is posed (skinned, the colliders updated) this often, a
                                      ///< whole multiple of fps, so a fast limb does not pass through the cloth
                                      ///< between two poses; 0: once per frame
  bool move_between_frames = true;    ///< each cloth step sees the body at its own time (BodyBetweenFrames),
                                      ///< not the frame's end pose
  bool prepare_ahead = false;         ///< the next frame's body (skinning, the collider's maps) is prepared on a
                                      ///< second thread while the cloth steps through this one (Collider::prepare_body)
  int collision_triangles = 0;        ///< > 0: the colliders see a copy simplified to about this many triangles
                                      ///< (BodyModel::simplified); the oracle measures against the exact body
  double skin_mm = 0;              ///< the body is answered this much thicker in every phase (BodyBetweenFrames) [mm]
  Vec3 scale = Vec3::Ones();       ///< the mesh scaled along x, y, z about the origin (a broader or slimmer body)
  std::string shape = "mesh";      ///< "mesh" or "sphere"
  Real radius = 0.25f;             ///< sphere radius [m]
  Vec3 center = Vec3(0, 0.5f, 0);  ///< sphere centre at t = 0 [m]
  Vec3 velocity = Vec3::Zero();    ///< sphere velocity [m/s] during the animate phase
  double move_s = 0;               ///< sphere: seconds of motion (animate phase)
};

/// One garment of the scene.
struct GarmentSpec {
  std::string file;        ///< pattern file (scene-relative, or relative to scenes/); or:
  std::string fit;         ///< a garment type drafted from the body's measurements (garment_draft.hpp)
  std::string size = "M";  ///< fit: S, M, L or XL (the ease at the hip)
  double ease_cm = -1;     ///< fit: the ease at the hip [cm]; -1: the size's
  int vertices = 0;        ///< target vertex count (0: use spacing_cm)
  double spacing_cm = 2;   ///< grid spacing when vertices = 0 [cm]
  bool attach = true;      ///< honour the pattern's attached edges (Durupinar 3.2)
  bool on_grid = false;    ///< Durupinar's construction: the outline drawn on the grid (MeshingOptions::on_grid)
  bool smooth = false;     ///< on the grid: Durupinar's step 7, the outline made smooth (MeshingOptions::smooth)
  double jitter_mm = 0;    ///< > 0: the placed garment moved by a random offset, each axis uniform in +-jitter_mm
  int seed = 0;            ///< the jitter's random seed (deterministic: one seed, one placement)
  int layer = 0;           ///< garments are dressed a layer at a time, the lowest first, each placed clear of those
                           ///< dressed before it (clear_of_layer); garments of one layer are dressed together
};

/// When each phase ends (definitions printed in every table header).
struct StopRule {
  bool sew = true;               ///< run the sew phase (seam forces, no gravity)
  double sew_max_s = 1;          ///< sew phase limit [simulated s]
  Real sewn_gap_mm = 2;          ///< sewn: every seam pair closer than this [mm] (or merged)
  double drape_max_s = 1;        ///< drape phase limit [simulated s]
  Real settle_speed = 0.05f;     ///< settled: RMS cloth speed below this [m/s] ...
  double settle_window_s = 0.1;  ///< ... for this long [simulated s]
  long max_iterations = 0;       ///< > 0: stop every phase after this many iterations (timing runs)
};

/// A whole scene.
struct Scene {
  std::string path;  ///< the file it came from ("" when built in code)
  std::string name;
  std::string description;
  BodySpec body;
  std::vector<GarmentSpec> garments;
  Material material;
  SolverParams solver;
  std::string collider = "is-cpu";
  ColliderOptions collider_options;
  /// Collider of the sew and drape phases when it should differ from `collider` (animation
  /// tables dress once with it and measure `collider` on the animation only); "" = `collider`.
  std::string dress_with;
  /// Collider of an outer layer of garments against the cloth dressed under it ([[garment]] layer), given it as a
  /// moving body (Simulator::set_layers_under); "" = none. An image-space one.
  std::string cloth_under;
  /// The cloth under answered this much thicker [mm] (BodyBetweenFrames' skin), below collider_options.tol.
  double cloth_skin_mm = 0;
  StopRule stop;
};

/// The body's poses per animation frame: pose_fps / fps (1 when pose_fps is 0).
long poses_per_frame(const BodySpec& body);

/// Reads a scene file; `overrides` are "section.key=value" (TOML value syntax, bare words as
/// strings; "garment.key" applies to every garment). Throws InputError naming file:line.
Scene load_scene(const std::string& path, const std::vector<std::string>& overrides = {});
/// As load_scene, from text (`name` is used in messages and to resolve relative paths).
Scene parse_scene(const std::string& text, const std::string& name, const std::vector<std::string>& overrides = {});

/// One key of a scene file, from the field tables that read, check and hash it.
struct SceneKey {
  std::string section;  ///< "body", "garment", ... (scene.hpp's sections)
  std::string key;
  std::string unit;  ///< "" when none
  std::string doc;   ///< one line; scenes/README.md says the rest
};
/// Every key of every section, in the tables' order.
std::vector<SceneKey> scene_keys();

/// The effective configuration: every field that decides a run (defaults included; not the name,
/// description or path) as `section.key = value` lines in a fixed order, one block per garment.
std::string config_text(const Scene& scene);
/// FNV-1a 64-bit hash of config_text and of the bytes of the body and pattern files it names, 16 hex digits:
/// equal for runs of the same configuration, another for an edited file.
std::string config_hash(const Scene& scene);

/// Resolves a body or pattern reference of a scene ("debian:human", "data:REL", scene-relative,
/// or relative to the source tree's scenes/ folder) to an existing path; throws InputError naming
/// every path it tried (for "data:", the data root and CLOTHBENCH_DATA) when there is none.
std::string resolve_scene_path(const Scene& scene, const std::string& ref);

}  // namespace clothbench
