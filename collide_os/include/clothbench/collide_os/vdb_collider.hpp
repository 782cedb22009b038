#pragma once
/// `vdb`: object-space collider on an OpenVDB narrow-band signed distance field of the body
/// (tools::meshToVolume, with its closest-polygon index grid), voxel ColliderOptions::voxel_size.
/// Per query point: depth = trilinear sample of the field, normal = its normalised gradient
/// (central differences of trilinear samples, one voxel apart), body velocity interpolated
/// barycentrically on the closest point of the voxel's closest triangle. Moving bodies rebuild
/// the field every frame (the object-space analogue of re-rendering maps).
#include <cstdint>
#include <memory>

#include "clothbench/sim/collider.hpp"

namespace clothbench {

/// The OpenVDB collider. Non-copyable; OpenVDB and TBB types stay inside vdb_collider.cpp (pimpl).
class VdbCollider final : public Collider {
 public:
  /// Uses options.tol [m], options.voxel_size [m] and options.threads (TBB threads of the field's
  /// build; queries run on one thread). Throws std::invalid_argument for a voxel_size that is not
  /// positive and finite.
  explicit VdbCollider(const ColliderOptions& options);
  ~VdbCollider() override;

  std::string_view name() const override { return "vdb"; }
  /// Builds the field (stats().setup_ms). Throws std::invalid_argument for an empty body,
  /// non-finite vertices, an out-of-range index, or a body that needs more than about 1e8 band
  /// voxels at this voxel size. Warns on stderr when the field misses part of the body
  /// (uncaptured_share() > 0).
  void set_body(const BodyFrame& body) override;
  /// Rebuilds the field for new positions (same topology); timed in stats().update_ms. Throws
  /// std::invalid_argument when set_body was not called or the topology differs. Warns once per
  /// collider if a frame misses part of the body and set_body's frame did not.
  void update_body(const BodyFrame& body) override;
  /// One Contact per point: hit when the field is below tol. Outside the exterior band: hit =
  /// false, depth = the band width (a lower bound). Inside deeper than the interior band: the
  /// exact answer of the closest triangle (found on a box tree over the triangles, as `brute`
  /// answers; counted in deep_points() and stats().searches). NaN points: hit = false, counted in stats().degenerate.
  void query(PointsView points, ContactsOut out) override;
  CollideStats stats() const override;

  /// Share of the current frame's surface area (vertex areas: a third of each adjacent
  /// triangle's) the field does not represent: vertices whose voxel cell has no sign change or
  /// where the field is farther than half a voxel from zero. These are parts (or gaps between
  /// parts) thinner than about a voxel and surfaces lying inside other parts of the body.
  double uncaptured_share() const;
  /// Points answered by the exact fallback (inside, deeper than the interior band) since construction.
  std::int64_t deep_points() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// Factory used by the registry (name "vdb").
std::unique_ptr<Collider> make_vdb_collider(const ColliderOptions& options);

}  // namespace clothbench
