#pragma once
/// `bbtree`: the dressing paper's own object-space baseline (dressing §7), rebuilt small: a quad
/// tree of axis-aligned bounding boxes whose leaves are the body's faces with their normal
/// vectors, and a vertex-face test per query point. Per point: among the faces whose box, grown by
/// tol, contains the point and onto which the point projects inside the triangle, the one nearest
/// along its normal; depth = the point's distance along that face normal (< 0 behind the face),
/// normal = the face normal, body velocity interpolated at the projection. A point deeper inside
/// than tol from every face box, or beside every face (over a convex edge), is not seen: the
/// method's own blind spots ("holes", dressing §7), which the exact colliders do not have.
/// The papers split the body into five parts (torso, arms, legs) under the root; our bodies carry
/// no such segmentation, so the root splits into four like every node.
#include <memory>

#include "clothbench/sim/collider.hpp"

namespace clothbench {

/// The bounding-box-tree collider, name "bbtree" (used by the registry): an ObjectSpaceCollider
/// (object_space_collider.hpp) whose set_body builds the tree (stats().setup_ms) and whose
/// update_body refits every box and face normal (stats().update_ms). Uses options.tol [m]; queries
/// run on one thread. One Contact per point as above: hit when a face is found with depth < tol;
/// otherwise hit = false, depth = tol (a lower bound only where the method sees). Every finite
/// point is one tree search (stats().searches).
std::unique_ptr<Collider> make_bbtree_collider(const ColliderOptions& options);

}  // namespace clothbench
