#include "clothbench/bench/registry.hpp"

#include <functional>

#include "clothbench/config.h"
#include "clothbench/io/errors.hpp"
#include "clothbench/sim/brute_collider.hpp"

// the image-space colliders are built always (is-gl only with CLOTHBENCH_WITH_GL); each
// object-space backend's header exists only when its module was configured (CMake option on)
#include "clothbench/collide_is/image_space_collider.hpp"
#if defined(CLOTHBENCH_WITH_EGL) && __has_include("clothbench/collide_is/egl_collider.hpp")
#include "clothbench/collide_is/egl_collider.hpp"
#define CLOTHBENCH_HAS_EGL 1
#endif
#if defined(CLOTHBENCH_WITH_FCL) && __has_include("clothbench/collide_os/fcl_collider.hpp")
#include "clothbench/collide_os/fcl_collider.hpp"
#define CLOTHBENCH_HAS_FCL 1
#endif
#if defined(CLOTHBENCH_WITH_EMBREE) && __has_include("clothbench/collide_os/embree_collider.hpp")
#include "clothbench/collide_os/embree_collider.hpp"
#define CLOTHBENCH_HAS_EMBREE 1
#endif
#if defined(CLOTHBENCH_WITH_BBTREE) && __has_include("clothbench/collide_os/bbtree_collider.hpp")
#include "clothbench/collide_os/bbtree_collider.hpp"
#define CLOTHBENCH_HAS_BBTREE 1
#endif
#if defined(CLOTHBENCH_WITH_VDB) && __has_include("clothbench/collide_os/vdb_collider.hpp")
#include "clothbench/collide_os/vdb_collider.hpp"
#define CLOTHBENCH_HAS_VDB 1
#endif

namespace clothbench {

namespace {

using Factory = std::function<std::unique_ptr<Collider>(const ColliderOptions&)>;

struct Entry {
  ColliderInfo info;
  Factory make;  // empty when not built
};

std::vector<Entry> entries() {
  std::vector<Entry> e;
  const std::string is_desc = "image space: front/back depth, normal, velocity maps ";
#ifdef CLOTHBENCH_WITH_GL
  e.push_back({{"is-gl", is_desc + "rendered with OpenGL (OSMesa)", true, "CLOTHBENCH_WITH_GL"}, make_is_gl_collider});
#else
  e.push_back({{"is-gl", is_desc + "rendered with OpenGL (OSMesa)", false, "CLOTHBENCH_WITH_GL"}, {}});
#endif
  const std::string egl_desc =
      is_desc + "rendered with OpenGL in a windowless EGL context (a GPU where the driver offers one)";
#ifdef CLOTHBENCH_HAS_EGL
  e.push_back({{"is-egl", egl_desc, true, "CLOTHBENCH_WITH_EGL"}, make_is_egl_collider});
#else
  e.push_back({{"is-egl", egl_desc, false, "CLOTHBENCH_WITH_EGL"}, {}});
#endif
  e.push_back({{"is-cpu", is_desc + "from our CPU rasteriser", true, ""}, make_is_cpu_collider});
  const std::string fcl_desc = "object space: FCL kIOS tree, closest point per query (temporal coherence), refit";
  const std::string embree_desc = "object space: Embree BVH, rtcPointQuery closest point (temporal coherence), refit";
  const std::string bbtree_desc =
      "object space, the dressing paper's own: quad tree of face bounding boxes, vertex-face test with face normals";
  const std::string vdb_desc =
      "object space: OpenVDB narrow-band signed distance field, trilinear depth and gradient normal, rebuilt per frame";
#ifdef CLOTHBENCH_HAS_FCL
  e.push_back({{"fcl", fcl_desc, true, "CLOTHBENCH_WITH_FCL"}, make_fcl_collider});
#else
  e.push_back({{"fcl", fcl_desc, false, "CLOTHBENCH_WITH_FCL"}, {}});
#endif
#ifdef CLOTHBENCH_HAS_EMBREE
  e.push_back({{"embree", embree_desc, true, "CLOTHBENCH_WITH_EMBREE"}, make_embree_collider});
#else
  e.push_back({{"embree", embree_desc, false, "CLOTHBENCH_WITH_EMBREE"}, {}});
#endif
#ifdef CLOTHBENCH_HAS_VDB
  e.push_back({{"vdb", vdb_desc, true, "CLOTHBENCH_WITH_VDB"}, make_vdb_collider});
#else
  e.push_back({{"vdb", vdb_desc, false, "CLOTHBENCH_WITH_VDB"}, {}});
#endif
#ifdef CLOTHBENCH_HAS_BBTREE
  e.push_back({{"bbtree", bbtree_desc, true, "CLOTHBENCH_WITH_BBTREE"}, make_bbtree_collider});
#else
  e.push_back({{"bbtree", bbtree_desc, false, "CLOTHBENCH_WITH_BBTREE"}, {}});
#endif
  e.push_back({{"brute", "exact, every triangle per point (tests and oracle reference)", true, ""},
               [](const ColliderOptions& o) { return std::make_unique<BruteForceCollider>(o); }});
  return e;
}

}  // namespace

std::vector<ColliderInfo> all_colliders() {
  std::vector<ColliderInfo> out;
  for (auto& e : entries()) out.push_back(e.info);
  return out;
}

std::vector<std::string> available_colliders() {
  std::vector<std::string> out;
  for (auto& e : entries())
    if (e.info.built) out.push_back(e.info.name);
  return out;
}

std::unique_ptr<Collider> make_collider(const std::string& name, const ColliderOptions& options) {
  std::string known;
  for (auto& e : entries()) {
    if (e.info.name == name) {
      if (!e.info.built)
        throw InputError("collider '" + name + "' was not built: configure with -D" + e.info.option + "=ON");
      return e.make(options);
    }
    known += (known.empty() ? "" : ", ") + e.info.name;
  }
  throw InputError("unknown collider '" + name + "' (known: " + known + ")");
}

}  // namespace clothbench
