#include <cassert>
#include <cmath>
#include <limits>

#include "clothbench/collide_os/embree_distance.hpp"
#include "embree_scene.hpp"
#include "object_space.hpp"

namespace clothbench {

struct EmbreeDistance::Impl {
  detail::EmbreeScene scene{1};
  BodyFrame body;        // positions and triangles of the current frame
  PseudoNormals pseudo;  // sign of the distance; points into body.triangles
  bool has_body = false;
};

EmbreeDistance::EmbreeDistance() : impl_(std::make_unique<Impl>()) {}
EmbreeDistance::~EmbreeDistance() = default;
EmbreeDistance::EmbreeDistance(EmbreeDistance&&) noexcept = default;
EmbreeDistance& EmbreeDistance::operator=(EmbreeDistance&&) noexcept = default;

void EmbreeDistance::set_body(const BodyFrame& body) {
  validate_body(body, "embree distance");
  impl_->has_body = false;
  impl_->body = body;
  impl_->pseudo = PseudoNormals(impl_->body);
  impl_->scene.build(impl_->body, impl_->body.moving);
  impl_->has_body = true;
}

void EmbreeDistance::update_body(const BodyFrame& body) {
  detail::check_update(impl_->body, impl_->has_body, body, "embree distance");
  impl_->body.positions = body.positions;
  impl_->pseudo = PseudoNormals(impl_->body);
  impl_->scene.refit(impl_->body);
}

void EmbreeDistance::signed_distance(PointsView points, Real* depth_out) const {
  const Real unbounded = std::numeric_limits<Real>::infinity();
  for (std::size_t i = 0; i < points.count; ++i) {
    const Vec3 p = points[i];
    if (!impl_ || !impl_->has_body || !p.allFinite()) {
      depth_out[i] = std::numeric_limits<Real>::quiet_NaN();
      continue;
    }
    // closest point over the whole body; sign of (p - closest) . pseudo-normal
    const ClosestPoint cp = impl_->scene.closest(p, unbounded);
    const Real dist = std::sqrt(cp.dist2);
    depth_out[i] = (p - cp.point).dot(impl_->pseudo.at(cp)) < 0 ? -dist : dist;
  }
}

void EmbreeDistance::segment_crossings(PointsView vertices, const Pairs& segments, std::uint8_t* crosses_out) const {
  for (Eigen::Index k = 0; k < segments.cols(); ++k) {
    const std::size_t i = static_cast<std::size_t>(segments(0, k)), j = static_cast<std::size_t>(segments(1, k));
    assert(i < vertices.count && j < vertices.count);
    const Vec3 a = vertices[i], b = vertices[j];
    // one ray per segment; nothing crosses before set_body or from a non-finite end
    const bool valid = impl_ && impl_->has_body && a.allFinite() && b.allFinite();
    crosses_out[k] = valid && impl_->scene.segment_hits(a, b) ? 1 : 0;
  }
}

}  // namespace clothbench
