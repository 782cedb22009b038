#pragma once
/// `vdb`: object-space collider on an OpenVDB narrow-band signed distance field of the body
/// (tools::meshToVolume, with its closest-polygon index grid), voxel ColliderOptions::voxel_size.
/// Per query point: depth = trilinear sample of the field, normal = its normalised gradient
/// (central differences of trilinear samples, one voxel apart), body velocity interpolated
/// barycentrically on the closest point of the voxel's closest triangle. Moving bodies rebuild
/// the field every frame (the object-space analogue of re-rendering maps).
#include <cstdint>
#include <memory>

#include "clothbench/collide_os/object_space_collider.hpp"

namespace clothbench {

/// The OpenVDB collider, name "vdb". OpenVDB and TBB types stay inside vdb_collider.cpp (pimpl).
/// set_body builds the field (stats().setup_ms); update_body rebuilds it for new positions
/// (stats().update_ms), or keeps it, shifted, for a body that only translated. Both throw
/// std::invalid_argument, beyond ObjectSpaceCollider's checks, for a body that needs more than
/// about 1e8 band voxels at this voxel size, and warn on stderr (once per collider after
/// set_body) when the field misses part of the body (uncaptured_share() > 0).
/// One Contact per point: hit when the field is below tol. Outside the exterior band: hit =
/// false, depth = the band width (a lower bound). Inside deeper than the interior band, or on a
/// flat gradient: the exact answer of the closest triangle (found on a box tree over the
/// triangles, as `brute` answers; counted in deep_points() and stats().searches).
class VdbCollider final : public ObjectSpaceCollider {
 public:
  /// Uses options.tol [m], options.voxel_size [m] and options.threads (TBB threads of the field's
  /// build, recorded in stats().threads; queries run on one thread). Throws std::invalid_argument
  /// for a voxel_size that is not positive and finite.
  explicit VdbCollider(const ColliderOptions& options);
  ~VdbCollider() override;

  /// Share of the current frame's surface area (vertex areas: a third of each adjacent
  /// triangle's) the field does not represent: vertices whose voxel cell has no sign change or
  /// where the field is farther than half a voxel from zero. These are parts (or gaps between
  /// parts) thinner than about a voxel and surfaces lying inside other parts of the body.
  double uncaptured_share() const;
  /// Points answered by the exact fallback since construction (stats().searches).
  std::int64_t deep_points() const;

 private:
  void check(const BodyFrame& body) const override;
  void build(const BodyFrame& body) override;
  void refit(const BodyFrame& body) override;
  Contact answer(const Vec3& p, detail::PointMemory* memory, std::int64_t& searches) const override;

  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// Factory used by the registry (name "vdb").
std::unique_ptr<Collider> make_vdb_collider(const ColliderOptions& options);

}  // namespace clothbench
