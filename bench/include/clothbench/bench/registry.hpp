#pragma once
/// The collider registry: names of DESIGN.md to implementations, with the traits the experiments and tests
/// choose colliders by. The only place that knows every backend (besides the driver that wires them to the
/// simulator); a test adds its own with register_collider.
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "clothbench/sim/collider.hpp"

namespace clothbench {

/// How a collider finds the body.
enum class Family {
  kImageSpace,   ///< depth, normal and velocity maps of the body (dressing section 5, walking section 4)
  kObjectSpace,  ///< the body's triangles or a field of them (BVHs, a distance field, the papers' box tree)
  kReference,    ///< every triangle per point: what the others are compared with, listed in no table
};

/// What a collider needs from the machine beyond its CPU.
enum class Needs {
  kNothing,  ///< runs anywhere
  kOpenGl,   ///< an OpenGL context (OSMesa, Mesa's software renderer)
  kGpu,      ///< an OpenGL context from EGL, made for a GPU (Mesa's software renderer where there is none)
};

/// One registry entry: what a collider is, what it offers, whether this build has it.
struct ColliderInfo {
  std::string name;         ///< "is-gl", "is-cpu", "fcl", "embree", "brute", ...
  std::string description;  ///< one line
  Family family = Family::kObjectSpace;
  /// Answers the closest point of the body's triangles to float rounding (fcl, embree, brute); false for maps, a
  /// sampled field (vdb) and a test that skips faces by design (bbtree's vertex-face test).
  bool exact = false;
  /// Listed by every results table that lists its family; false for one named only where a table wants it:
  /// the reference (brute), or another collider's answers from another device (is-egl: is-gl's maps in EGL).
  bool in_tables = true;
  Needs needs = Needs::kNothing;
  /// Honours ColliderOptions::coherent (each point's bound carried between queries): a table of costs adds
  /// its from-scratch row.
  bool coherent = false;
  /// Honours ColliderOptions::face_normals (the dressing paper's face-normal response, section 7).
  bool face_normals = false;
  /// update_body to a moved body costs seconds (vdb voxelises it again): the walking table gives it half a
  /// second of the walk.
  bool slow_update = false;
  bool built = false;  ///< false when the CMake option that enables it was off
  std::string option;  ///< the CMake option that builds it ("" when every build has it)
};

/// Makes a collider with the options of a run.
using ColliderFactory = std::function<std::unique_ptr<Collider>(const ColliderOptions&)>;
/// Chooses colliders by their traits.
using ColliderFilter = std::function<bool(const ColliderInfo&)>;

/// Every collider clothbench knows, built or not, in registry order (the order tables list them in).
std::vector<ColliderInfo> all_colliders();
/// Names of the colliders built in (the conformance suite runs over these).
std::vector<std::string> available_colliders();
/// Names of the built colliders `keep` accepts, in registry order.
std::vector<std::string> colliders(const ColliderFilter& keep);
/// The entry of `name`, built or not; nullopt for a name the registry does not know (the runner's analytic
/// "sphere" among them).
std::optional<ColliderInfo> collider_info(const std::string& name);
/// Creates a collider by name. Throws InputError for an unknown name (listing the valid ones)
/// or a backend that was not built (naming the CMake option that enables it).
std::unique_ptr<Collider> make_collider(const std::string& name, const ColliderOptions& options = {});

/// Adds a collider after the built-in ones, built (as benchmark::RegisterBenchmark adds a benchmark): from then on
/// every query above and every table of its family lists it. Throws std::invalid_argument for an empty name or
/// factory, or a name already registered.
void register_collider(ColliderInfo info, ColliderFactory make);
/// Removes a collider by name (a test's, once it is done with it); false when there is none.
bool unregister_collider(const std::string& name);

}  // namespace clothbench
