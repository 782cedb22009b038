#include "clothbench/collide_os/fcl_collider.hpp"

#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/geometry/shape/sphere.h>
#include <fcl/narrowphase/distance.h>

#include <limits>
#include <vector>

#include "clothbench/sim/timer.hpp"
#include "object_space.hpp"

namespace clothbench {

namespace {

using Mesh = fcl::BVHModel<fcl::kIOSd>;

fcl::Vector3d to_double(const Points3& positions, Eigen::Index i) { return positions.col(i).cast<double>(); }

}  // namespace

struct FclCollider::Impl {
  ColliderOptions options;
  std::shared_ptr<Mesh> mesh;            // kIOS tree over the body, double precision
  fcl::Sphered point{0.0};               // the query point as a sphere of radius 0
  fcl::DistanceRequestd request{false};  // nearest triangle only; the closest point is ours
  BodyFrame body;                        // the current frame (exact closest points in float)
  PseudoNormals pseudo;                  // sign of the depth; points into body.triangles
  Box3 box;                              // bounding box of body.positions [m]
  detail::Coherence coherence;           // per-point bounds between queries (options.coherent)
  bool has_body = false;
  CollideStats stats;

  // exact closest point strictly within radius: FCL finds the nearest triangle (the result's
  // min_distance starts at radius, which prunes the traversal), we recompute it exactly
  ClosestPoint closest(const Vec3& p, Real radius) const {
    fcl::DistanceResultd result;
    result.min_distance =
        radius == std::numeric_limits<Real>::infinity() ? std::numeric_limits<double>::max() : double(radius);
    fcl::Transform3d at = fcl::Transform3d::Identity();
    at.translation() = p.cast<double>();
    fcl::distance(mesh.get(), fcl::Transform3d::Identity(), &point, at, request, result);
    ClosestPoint cp;
    if (result.b1 == fcl::DistanceResultd::NONE) return cp;
    const int t = result.b1;
    cp = closest_point_on_triangle(p, body.positions.col(body.triangles(0, t)),
                                   body.positions.col(body.triangles(1, t)), body.positions.col(body.triangles(2, t)));
    cp.triangle = t;
    if (!(cp.dist2 < radius * radius)) cp.triangle = -1;
    return cp;
  }
};

FclCollider::FclCollider(const ColliderOptions& options) : impl_(std::make_unique<Impl>()) { impl_->options = options; }

FclCollider::~FclCollider() = default;

void FclCollider::set_body(const BodyFrame& body) {
  Stopwatch sw;
  validate_body(body, "fcl collider");
  impl_->has_body = false;
  impl_->body = body;
  impl_->pseudo = PseudoNormals(impl_->body);
  impl_->box = bounding_box(impl_->body.positions);
  impl_->coherence.forget();
  // conversion to double, then the kIOS tree
  std::vector<fcl::Vector3d> vertices(static_cast<std::size_t>(body.vertex_count()));
  for (Eigen::Index i = 0; i < body.positions.cols(); ++i) vertices[std::size_t(i)] = to_double(body.positions, i);
  std::vector<fcl::Triangle> triangles(static_cast<std::size_t>(body.triangle_count()));
  for (Eigen::Index t = 0; t < body.triangles.cols(); ++t)
    triangles[std::size_t(t)] = fcl::Triangle(std::size_t(body.triangles(0, t)), std::size_t(body.triangles(1, t)),
                                              std::size_t(body.triangles(2, t)));
  auto mesh = std::make_shared<Mesh>();
  if (mesh->beginModel(body.triangle_count(), body.vertex_count()) != fcl::BVH_OK ||
      mesh->addSubModel(vertices, triangles) != fcl::BVH_OK || mesh->endModel() != fcl::BVH_OK)
    throw std::runtime_error("fcl collider: building the kIOS tree failed");
  impl_->mesh = std::move(mesh);
  impl_->has_body = true;
  impl_->stats.setup_ms += sw.ms();
}

void FclCollider::update_body(const BodyFrame& body) {
  Stopwatch sw;
  detail::check_update(impl_->body, impl_->has_body, body, "fcl collider");
  impl_->coherence.body_moves(impl_->body.positions, body.positions);
  detail::adopt_frame(impl_->body, body);
  impl_->pseudo = PseudoNormals(impl_->body);
  impl_->box = bounding_box(impl_->body.positions);
  // refit every node from its triangles, top-down (no rebuild): FCL's bottom-up refit merges
  // children with the bounding volumes' operator+ (OBBRSS at the time), which gave wrong nearest triangles on the walking body
  // (1981 of 2000 points off); FCL fits each node over the previous and the new vertices
  Mesh& mesh = *impl_->mesh;
  if (mesh.beginUpdateModel() != fcl::BVH_OK) throw std::runtime_error("fcl collider: beginUpdateModel failed");
  for (Eigen::Index i = 0; i < body.positions.cols(); ++i) mesh.updateVertex(to_double(body.positions, i));
  if (mesh.endUpdateModel(true, false) != fcl::BVH_OK) throw std::runtime_error("fcl collider: endUpdateModel failed");
  impl_->stats.update_ms += sw.ms();
  ++impl_->stats.updates;
}

void FclCollider::query(PointsView points, ContactsOut out) {
  Impl& s = *impl_;
  const auto find = [&s](const Vec3& p, Real radius) { return s.closest(p, radius); };
  detail::PointMemory* memory = s.options.coherent && s.has_body ? s.coherence.memory(points.xyz, points.count) : nullptr;
  detail::answer_points(points, out, s.has_body, s.stats, [&](std::size_t i, const Vec3& p) {
    return detail::answer_point(s.body, s.pseudo, s.box, p, s.options, find, memory ? memory + i : nullptr,
                                s.coherence.body_moved(), s.stats.searches);
  });
}

CollideStats FclCollider::stats() const { return impl_->stats; }

std::unique_ptr<Collider> make_fcl_collider(const ColliderOptions& options) {
  return std::make_unique<FclCollider>(options);
}

}  // namespace clothbench
