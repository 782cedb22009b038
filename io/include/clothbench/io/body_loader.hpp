#pragma once
/// Bodies and their motion through assimp: a welded, closed rest mesh in the DESIGN.md frame
/// (metres, +Y up, soles at y = 0, facing +Z) plus its skeleton animations, evaluated by linear
/// blend skinning into BodyFrames at any time t.
#include <memory>
#include <string>
#include <vector>

#include "clothbench/sim/body_frame.hpp"

namespace clothbench {

/// How load_body treats the file.
struct BodyLoadOptions {
  bool require_closed = true;   ///< throw InputError when the welded mesh has boundary/non-manifold edges
  bool drop_open_parts = true;  ///< remove small open parts (< 10 % of the vertices: eyes, lashes), reported
  bool normalise = true;        ///< convert to metres, +Y up, soles at y = 0 (else keep the file's frame)
  /// assimp crashes or loops on some malformed files (fuzz/assimp-findings): the file is first read
  /// in a child process, and a crash, or no answer within this many seconds, is an InputError.
  /// 0 reads it in this process only (faster; for trusted files and fuzzing).
  double isolate_timeout_s = 60;
};

/// One animation of the file.
struct AnimationInfo {
  std::string name;             ///< the file's name (or "animation_K" when it has none)
  double duration_s = 0;        ///< length [s]; valid times are [0, duration_s]
  double ticks_per_second = 0;  ///< the file's time unit (assimp ticks per second)
  int channels = 0;             ///< animated nodes
};

class BodyModelImpl;

/// Rest mesh + skin + animations; cheap to evaluate at any t. Movable, not copyable.
class BodyModel {
 public:
  explicit BodyModel(std::unique_ptr<BodyModelImpl> impl);
  BodyModel(BodyModel&&) noexcept;
  BodyModel& operator=(BodyModel&&) noexcept;
  BodyModel(const BodyModel&) = delete;
  BodyModel& operator=(const BodyModel&) = delete;
  ~BodyModel();

  /// The welded, normalised rest (bind) mesh with angle-weighted normals and zero velocities.
  const BodyFrame& rest() const;
  /// Small open parts removed at load (drop_open_parts) and their vertex count.
  int dropped_parts() const;
  int dropped_vertices() const;
  /// What loading changed to reach the design frame (metres, +Y up, front +Z: the up axis turned, the scale) and
  /// warnings about the result (a body that seems to face +-X or -Z), one sentence each; empty when neither.
  const std::vector<std::string>& notes() const;
  /// Number of skin bones (0 for a static mesh).
  int bone_count() const;
  /// The file's animations, in file order.
  const std::vector<AnimationInfo>& animations() const;
  /// Index of an animation by name; throws InputError listing the names when unknown.
  int animation_index(const std::string& name) const;
  /// Skinned frame at time t [s] (LBS, the file's interpolation); velocities from the motion
  /// itself; walk_in_place removes the root's horizontal travel (positions and velocities).
  /// Throws InputError when t is outside [0, duration] or the animation index is invalid.
  BodyFrame frame(int animation, double t, bool walk_in_place = false) const;
  /// As frame(), reusing the storage of `out` (no allocation once `out` has the right size).
  void frame_into(BodyFrame& out, int animation, double t, bool walk_in_place = false) const;
  /// A coarser copy for collision (scene key body.collision_triangles): about `target_triangles` triangles by edge
  /// collapses (meshoptimizer's quadric simplifier), keeping a subset of this body's vertices with their skin, so
  /// the copy's vertices lie on this body in every frame. Throws InputError unless 0 < target < triangles().
  BodyModel simplified(int target_triangles) const;
  /// The file this model was loaded from.
  const std::string& path() const;

 private:
  std::unique_ptr<BodyModelImpl> impl_;
};

/// Loads any format assimp reads. Throws InputError("PATH: what is wrong") for a missing, unreadable,
/// empty, non-triangulable file, or (require_closed) a mesh that is not closed after welding
/// ("... is not closed: N boundary edges"), or a file with no mesh (a BVH skeleton). `path` may be a
/// data reference ("data:REL", "debian:human"; see resolve_data_reference).
BodyModel load_body(const std::string& path, const BodyLoadOptions& options = {});

}  // namespace clothbench
