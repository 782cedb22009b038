#pragma once
/// The image-space colliders of the papers (dressing section 5, walking section 4): a point
/// collides when it lies between the front and back depth surfaces of the body, within tol.
#include <memory>

#include "clothbench/collide_is/map_set.hpp"
#include "clothbench/sim/collider.hpp"

namespace clothbench {

/// Image-space collider with maps drawn by OpenGL through OSMesa; name() "is-gl".
/// Static bodies are rendered once in set_body, moving ones again in every update_body
/// (velocity maps only when body.moving). Query per point (dressing Eq. 8/9, walking Eq. 11/12):
///   (col, row) from world (x, y); zf, zb = front and back surface z at that pixel;
///   depth = max(z - zf, zb - z) (< 0 between the surfaces); hit when depth < tol;
///   normal and velocity from the map whose surface is nearer (z beyond the local body centre
///   (zf + zb) / 2 takes the front map, the papers' choice by the sign of z).
/// Side-layer hits (dressing 5.4) report depth >= 0. Throws std::runtime_error when no GL
/// context can be created.
std::unique_ptr<Collider> make_is_gl_collider(const ColliderOptions& options);

/// The same collider with maps from the CPU rasteriser; name() "is-cpu".
std::unique_ptr<Collider> make_is_cpu_collider(const ColliderOptions& options);

/// Either collider over an explicit renderer ("gl" or "cpu"); the MapSet stays readable for
/// pictures and tests through maps().
class ImageSpaceCollider final : public Collider {
 public:
  ImageSpaceCollider(std::unique_ptr<MapRenderer> renderer, const ColliderOptions& options, double setup_ms);
  std::string_view name() const override;
  void set_body(const BodyFrame& body) override;
  void update_body(const BodyFrame& body) override;
  void query(PointsView points, ContactsOut out) override;
  CollideStats stats() const override { return stats_; }
  /// The current maps (empty before set_body).
  const MapSet& maps() const { return maps_; }

 private:
  void render(const BodyFrame& body);

  std::unique_ptr<MapRenderer> renderer_;
  ColliderOptions options_;
  MapSet maps_;
  int vertex_count_ = 0;
  CollideStats stats_;
};

}  // namespace clothbench
