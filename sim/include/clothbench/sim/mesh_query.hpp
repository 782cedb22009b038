#pragma once
/// Exact point-to-mesh geometry shared by the brute-force collider, the object-space
/// colliders and the accuracy oracle: one implementation of closest point, sign and
/// interpolation, so every exact method answers identically.
#include <cstdint>
#include <vector>

#include "clothbench/sim/body_frame.hpp"
#include "clothbench/sim/collider.hpp"

namespace clothbench {

/// Closest point of a triangle to a query point.
struct ClosestPoint {
  Vec3 point = Vec3::Zero();  ///< closest point on the triangle [m]
  Vec3 bary = Vec3::Zero();   ///< its barycentric coordinates (sum 1)
  Real dist2 = 0;             ///< squared distance to the query point [m^2]
  int triangle = -1;          ///< triangle index in the mesh, -1 when none found
  int feature = 0;            ///< 0 face interior, 1..3 edge (ab, bc, ca), 4..6 vertex (a, b, c)
};

/// Closest point on triangle (a, b, c) to p (Ericson, Real-Time Collision Detection 5.1.5).
ClosestPoint closest_point_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

/// Angle-weighted pseudo-normals of a closed mesh (Baerentzen & Aanaes 2005): the sign of
/// (p - closest) . pseudo_normal(feature) decides inside/outside exactly for closed meshes.
class PseudoNormals {
 public:
  PseudoNormals() = default;
  /// Builds face, edge and vertex pseudo-normals from the frame's positions and triangles.
  explicit PseudoNormals(const BodyFrame& body);
  /// Pseudo-normal of the feature of `cp` (face, edge or vertex), not normalised.
  Vec3 at(const ClosestPoint& cp) const;

 private:
  Points3 face_;                   // unit face normals (3 x nt)
  Points3 edge_;                   // sum of the two adjacent face normals per (tri, edge) (3 x 3nt)
  Points3 vertex_;                 // angle-weighted vertex normals (3 x nv)
  const Tris* tris_ = nullptr;
};

/// Turns an exact closest point into the contract's Contact: depth signed by the pseudo-normal,
/// normal and body velocity interpolated barycentrically from the frame's vertex attributes (with
/// `face_normal`, the normal is the closest triangle's face normal, the dressing paper's object-space
/// response, section 7), hit when inside or closer than tol.
Contact contact_from_closest(const BodyFrame& body, const PseudoNormals& pseudo, const Vec3& p,
                             const ClosestPoint& cp, Real tol, bool face_normal = false);

/// Exhaustive closest point over every triangle (O(nt)); the reference for tests.
ClosestPoint closest_point_brute(const BodyFrame& body, const Vec3& p);

}  // namespace clothbench
