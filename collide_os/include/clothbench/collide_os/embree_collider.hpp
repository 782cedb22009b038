#pragma once
/// `embree`: object-space collider on an Embree BVH with rtcPointQuery closest points. It shares
/// one scene wrapper over a shared float vertex buffer with EmbreeDistance (embree_distance.hpp),
/// the exact signed distance of the accuracy oracle: a static body is built at quality HIGH; once it moves, a dynamic scene
/// (build quality LOW, geometry REFIT) is refitted per frame. Answers equal `brute`'s (same closest-point, sign and interpolation code).
#include <memory>

#include "clothbench/sim/collider.hpp"

namespace clothbench {

/// The Embree collider, name "embree" (used by the registry): an ObjectSpaceCollider with its exact
/// answers (object_space_collider.hpp). set_body builds the BVH, HIGH quality for a static body,
/// refittable for a moving one (stats().setup_ms); update_body refits it (a static build is
/// rebuilt refittable the first time; stats().update_ms). Uses options.tol [m],
/// options.search_radius [m], options.coherent, options.face_normals and options.threads (Embree
/// build threads and query worker threads, at least 256 points each; recorded in
/// stats().threads). Throws std::runtime_error for an Embree error (no device, a failed build).
std::unique_ptr<Collider> make_embree_collider(const ColliderOptions& options);

}  // namespace clothbench
