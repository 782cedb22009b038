#pragma once
/// A body surface at one instant: what every collider and the accuracy oracle consume.
#include <string>

#include "clothbench/sim/types.hpp"

namespace clothbench {

/// One frame of a (possibly moving) closed triangle mesh in the body frame of DESIGN.md:
/// metres, +Y up, soles at y = 0, facing +Z. Triangles wind counter-clockwise seen from outside.
struct BodyFrame {
  Points3 positions;   ///< vertex positions [m] (3 x nv)
  Points3 normals;     ///< unit angle-weighted vertex normals, outward (3 x nv)
  Points3 velocities;  ///< vertex velocities [m/s] (3 x nv); all zero when !moving
  Tris triangles;      ///< vertex indices (3 x nt), outward counter-clockwise
  double time_s = 0;   ///< animation time of this frame [s]
  bool moving = false; ///< true when the body moves (colliders then need velocity look-ups)

  int vertex_count() const { return static_cast<int>(positions.cols()); }
  int triangle_count() const { return static_cast<int>(triangles.cols()); }
};

/// Axis-aligned bounding box [m].
struct Box3 {
  Vec3 min = Vec3::Constant(0);
  Vec3 max = Vec3::Constant(0);
  Vec3 size() const { return max - min; }
  Vec3 center() const { return 0.5f * (min + max); }
};

/// Bounding box of a point set; throws std::invalid_argument when it is empty.
Box3 bounding_box(const Points3& points);

/// Angle-weighted vertex normals (Thuermer-Wuethrich) of a triangle mesh, unit length (3 x nv).
/// Vertices touched by no triangle (or only by degenerate ones) get a zero normal.
Points3 angle_weighted_normals(const Points3& positions, const Tris& triangles);
/// As angle_weighted_normals, into `normals` (resized to 3 x nv; no allocation when it already is).
void angle_weighted_normals_into(const Points3& positions, const Tris& triangles, Points3& normals);

/// Number of edges used by exactly one triangle (a closed mesh has 0) and by more than two.
struct EdgeCheck {
  long boundary_edges = 0;
  long non_manifold_edges = 0;
  bool closed() const { return boundary_edges == 0 && non_manifold_edges == 0; }
};
EdgeCheck check_edges(const Tris& triangles);

/// Throws std::invalid_argument with a message naming `what` when the frame is malformed:
/// no vertices or triangles, an index out of range, a non-finite coordinate, mismatched sizes.
void validate_body(const BodyFrame& body, const std::string& what);

/// Fills normals from positions and triangles and zeroes velocities (moving = false).
void finish_static_body(BodyFrame& body);

/// A closed UV sphere (nlat >= 2 bands, nlon >= 3 sectors) of `radius` [m] at `center`.
BodyFrame make_sphere_body(const Vec3& center, Real radius, int nlat = 32, int nlon = 64);

/// A closed capsule along +Y: cylinder of `radius` [m] and length `length` between two
/// hemispheres, centre at `center`.
BodyFrame make_capsule_body(const Vec3& center, Real radius, Real length, int nlat = 16, int nlon = 48);

/// Loop-free 1-to-4 midpoint subdivision (positions only; normals recomputed; velocities
/// interpolated). Used to measure how query cost grows with body faces.
BodyFrame subdivide_body(const BodyFrame& body);

}  // namespace clothbench
