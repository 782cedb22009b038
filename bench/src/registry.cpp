#include "clothbench/bench/registry.hpp"

#include <algorithm>
#include <mutex>
#include <stdexcept>
#include <utility>

#include "clothbench/config.h"
#include "clothbench/io/errors.hpp"
#include "clothbench/sim/brute_collider.hpp"

// each optional backend's factory where this build has it, else nullptr (an empty ColliderFactory: not built);
// an object-space backend's header exists only when its module was configured (its CMake option on)
#include "clothbench/collide_is/image_space_collider.hpp"
#ifdef CLOTHBENCH_WITH_GL
#define CLOTHBENCH_MAKE_IS_GL make_is_gl_collider
#else
#define CLOTHBENCH_MAKE_IS_GL nullptr
#endif
#if defined(CLOTHBENCH_WITH_EGL) && __has_include("clothbench/collide_is/egl_collider.hpp")
#include "clothbench/collide_is/egl_collider.hpp"
#define CLOTHBENCH_MAKE_IS_EGL make_is_egl_collider
#else
#define CLOTHBENCH_MAKE_IS_EGL nullptr
#endif
#if defined(CLOTHBENCH_WITH_FCL) && __has_include("clothbench/collide_os/fcl_collider.hpp")
#include "clothbench/collide_os/fcl_collider.hpp"
#define CLOTHBENCH_MAKE_FCL make_fcl_collider
#else
#define CLOTHBENCH_MAKE_FCL nullptr
#endif
#if defined(CLOTHBENCH_WITH_EMBREE) && __has_include("clothbench/collide_os/embree_collider.hpp")
#include "clothbench/collide_os/embree_collider.hpp"
#define CLOTHBENCH_MAKE_EMBREE make_embree_collider
#else
#define CLOTHBENCH_MAKE_EMBREE nullptr
#endif
#if defined(CLOTHBENCH_WITH_VDB) && __has_include("clothbench/collide_os/vdb_collider.hpp")
#include "clothbench/collide_os/vdb_collider.hpp"
#define CLOTHBENCH_MAKE_VDB make_vdb_collider
#else
#define CLOTHBENCH_MAKE_VDB nullptr
#endif
#if defined(CLOTHBENCH_WITH_BBTREE) && __has_include("clothbench/collide_os/bbtree_collider.hpp")
#include "clothbench/collide_os/bbtree_collider.hpp"
#define CLOTHBENCH_MAKE_BBTREE make_bbtree_collider
#else
#define CLOTHBENCH_MAKE_BBTREE nullptr
#endif

namespace clothbench {

namespace {

struct Entry {
  ColliderInfo info;
  ColliderFactory make;  // empty when not built
};

// an entry with the traits' defaults (object space, inexact, in the tables, needing nothing); built where `make` is
Entry entry(std::string name, std::string description, Family family, std::string option, ColliderFactory make) {
  ColliderInfo info;
  info.name = std::move(name);
  info.description = std::move(description);
  info.family = family;
  info.built = static_cast<bool>(make);
  info.option = std::move(option);
  return {std::move(info), std::move(make)};
}

// the built-in colliders in the order the tables list them: image space, object space, the reference
std::vector<Entry> image_space_entries() {
  const std::string is = "image space: front/back depth, normal, velocity maps ";
  Entry gl = entry("is-gl", is + "rendered with OpenGL (OSMesa)", Family::kImageSpace, "CLOTHBENCH_WITH_GL",
                   CLOTHBENCH_MAKE_IS_GL);
  gl.info.needs = Needs::kOpenGl;
  Entry egl =
      entry("is-egl", is + "rendered with OpenGL in a windowless EGL context (a GPU where the driver offers one)",
            Family::kImageSpace, "CLOTHBENCH_WITH_EGL", CLOTHBENCH_MAKE_IS_EGL);
  egl.info.needs = Needs::kGpu;
  egl.info.in_tables = false;  // is-gl's maps, bit for bit where EGL draws with Mesa too
  Entry cpu = entry("is-cpu", is + "from our CPU rasteriser", Family::kImageSpace, "", make_is_cpu_collider);
  return {gl, egl, cpu};
}

std::vector<Entry> object_space_entries() {
  Entry fcl = entry("fcl", "object space: FCL kIOS tree, closest point per query (temporal coherence), refit",
                    Family::kObjectSpace, "CLOTHBENCH_WITH_FCL", CLOTHBENCH_MAKE_FCL);
  Entry embree = entry("embree", "object space: Embree BVH, rtcPointQuery closest point (temporal coherence), refit",
                       Family::kObjectSpace, "CLOTHBENCH_WITH_EMBREE", CLOTHBENCH_MAKE_EMBREE);
  for (Entry* bvh : {&fcl, &embree}) bvh->info.exact = bvh->info.coherent = bvh->info.face_normals = true;
  Entry vdb = entry("vdb",
                    "object space: OpenVDB narrow-band signed distance field, trilinear depth and gradient normal, "
                    "rebuilt per frame",
                    Family::kObjectSpace, "CLOTHBENCH_WITH_VDB", CLOTHBENCH_MAKE_VDB);
  vdb.info.slow_update = true;
  Entry bbtree =
      entry("bbtree",
            "object space, the dressing paper's own: quad tree of face bounding boxes, vertex-face test with "
            "face normals",
            Family::kObjectSpace, "CLOTHBENCH_WITH_BBTREE", CLOTHBENCH_MAKE_BBTREE);
  return {fcl, embree, vdb, bbtree};
}

Entry brute_entry() {
  Entry brute = entry("brute", "exact, every triangle per point (tests and oracle reference)", Family::kReference, "",
                      [](const ColliderOptions& o) { return std::make_unique<BruteForceCollider>(o); });
  brute.info.exact = brute.info.face_normals = true;
  brute.info.in_tables = false;
  return brute;
}

// the registry: the built-in colliders, then those register_collider added; guarded by registry_mutex()
std::vector<Entry>& registry() {
  static std::vector<Entry> entries = [] {
    std::vector<Entry> e = image_space_entries();
    for (Entry& os : object_space_entries()) e.push_back(std::move(os));
    e.push_back(brute_entry());
    return e;
  }();
  return entries;
}

std::mutex& registry_mutex() {
  static std::mutex m;
  return m;
}

}  // namespace

std::vector<ColliderInfo> all_colliders() {
  const std::lock_guard<std::mutex> lock(registry_mutex());
  std::vector<ColliderInfo> out;
  for (const Entry& e : registry()) out.push_back(e.info);
  return out;
}

std::vector<std::string> colliders(const ColliderFilter& keep) {
  std::vector<std::string> out;
  for (const ColliderInfo& c : all_colliders())
    if (c.built && keep(c)) out.push_back(c.name);
  return out;
}

std::vector<std::string> available_colliders() {
  return colliders([](const ColliderInfo&) { return true; });
}

std::optional<ColliderInfo> collider_info(const std::string& name) {
  const std::lock_guard<std::mutex> lock(registry_mutex());
  for (const Entry& e : registry())
    if (e.info.name == name) return e.info;
  return std::nullopt;
}

std::unique_ptr<Collider> make_collider(const std::string& name, const ColliderOptions& options) {
  ColliderFactory make;
  std::string known;
  {
    const std::lock_guard<std::mutex> lock(registry_mutex());
    for (const Entry& e : registry()) {
      if (e.info.name == name) {
        if (!e.info.built)
          throw InputError("collider '" + name + "' was not built: configure with -D" + e.info.option + "=ON");
        make = e.make;
        break;
      }
      known += (known.empty() ? "" : ", ") + e.info.name;
    }
  }
  if (!make) throw InputError("unknown collider '" + name + "' (known: " + known + ")");
  return make(options);  // outside the lock: a factory may take long (OpenGL contexts, maps)
}

void register_collider(ColliderInfo info, ColliderFactory make) {
  if (info.name.empty() || !make)
    throw std::invalid_argument("register_collider: a collider needs a name and a factory");
  const std::lock_guard<std::mutex> lock(registry_mutex());
  std::vector<Entry>& entries = registry();
  if (std::any_of(entries.begin(), entries.end(), [&](const Entry& e) { return e.info.name == info.name; }))
    throw std::invalid_argument("register_collider: '" + info.name + "' is registered already");
  info.built = true;
  entries.push_back({std::move(info), std::move(make)});
}

bool unregister_collider(const std::string& name) {
  const std::lock_guard<std::mutex> lock(registry_mutex());
  std::vector<Entry>& entries = registry();
  const auto it = std::find_if(entries.begin(), entries.end(), [&](const Entry& e) { return e.info.name == name; });
  if (it == entries.end()) return false;
  entries.erase(it);
  return true;
}

}  // namespace clothbench
