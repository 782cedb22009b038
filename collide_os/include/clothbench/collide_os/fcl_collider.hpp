#pragma once
/// `fcl`: object-space collider on an FCL kIOS bounding-volume tree (double precision; kIOS
/// answered the dressing shirt's queries faster than OBBRSS, see collide_os/README.md).
/// Per query point: the nearest body triangle within a bound from FCL's sphere-to-mesh distance, then the exact closest point, pseudo-normal sign and barycentric
/// normal/velocity from mesh_query.hpp, so answers equal `brute`'s. Moving bodies are refitted
/// (beginUpdateModel / updateVertex / endUpdateModel, top-down refit), never rebuilt.
#include <memory>

#include "clothbench/sim/collider.hpp"

namespace clothbench {

/// The FCL collider, name "fcl" (used by the registry): an ObjectSpaceCollider with its exact
/// answers (object_space_collider.hpp), conversion to double and the tree's build timed in
/// stats().setup_ms, refits in stats().update_ms. Uses options.tol [m], options.search_radius [m],
/// options.coherent and options.face_normals; queries run on one thread. Throws
/// std::runtime_error (from set_body / update_body) when FCL fails to build or refit the tree.
std::unique_ptr<Collider> make_fcl_collider(const ColliderOptions& options);

}  // namespace clothbench
