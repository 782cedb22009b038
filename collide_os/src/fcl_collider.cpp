#include "clothbench/collide_os/fcl_collider.hpp"

#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/geometry/shape/sphere.h>
#include <fcl/narrowphase/distance.h>

#include <limits>
#include <stdexcept>
#include <vector>

#include "clothbench/collide_os/object_space_collider.hpp"

namespace clothbench {

namespace {

using Mesh = fcl::BVHModel<fcl::kIOSd>;

fcl::Vector3d to_double(const Points3& positions, Eigen::Index i) { return positions.col(i).cast<double>(); }

// the body as an FCL kIOS tree in double precision; its nearest triangle gives the exact closest
// point in float
class FclCollider final : public ObjectSpaceCollider {
 public:
  explicit FclCollider(const ColliderOptions& options) : ObjectSpaceCollider(options, {"fcl"}) {}

 private:
  // conversion to double, then the kIOS tree
  void build(const BodyFrame& body) override {
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
    mesh_ = std::move(mesh);
  }

  // refit every node from its triangles, top-down (no rebuild): FCL's bottom-up refit merges
  // children with the bounding volumes' operator+ (OBBRSS at the time), which gave wrong nearest
  // triangles on the walking body (1981 of 2000 points off); FCL fits each node over the previous
  // and the new vertices
  void refit(const BodyFrame& body) override {
    if (mesh_->beginUpdateModel() != fcl::BVH_OK) throw std::runtime_error("fcl collider: beginUpdateModel failed");
    for (Eigen::Index i = 0; i < body.positions.cols(); ++i) mesh_->updateVertex(to_double(body.positions, i));
    if (mesh_->endUpdateModel(true, false) != fcl::BVH_OK)
      throw std::runtime_error("fcl collider: endUpdateModel failed");
  }

  // FCL finds the nearest triangle (the result's min_distance starts at radius, which prunes the
  // traversal), we recompute its closest point exactly
  ClosestPoint nearest(const Vec3& p, Real radius) const override {
    fcl::DistanceResultd result;
    result.min_distance =
        radius == std::numeric_limits<Real>::infinity() ? std::numeric_limits<double>::max() : double(radius);
    fcl::Transform3d at = fcl::Transform3d::Identity();
    at.translation() = p.cast<double>();
    fcl::distance(mesh_.get(), fcl::Transform3d::Identity(), &point_, at, request_, result);
    ClosestPoint cp;
    if (result.b1 == fcl::DistanceResultd::NONE) return cp;
    const int t = result.b1;
    const BodyFrame& b = body();
    cp = closest_point_on_triangle(p, b.positions.col(b.triangles(0, t)), b.positions.col(b.triangles(1, t)),
                                   b.positions.col(b.triangles(2, t)));
    cp.triangle = t;
    if (!(cp.dist2 < radius * radius)) cp.triangle = -1;
    return cp;
  }

  std::shared_ptr<Mesh> mesh_;            // kIOS tree over the body, double precision
  fcl::Sphered point_{0.0};               // the query point as a sphere of radius 0
  fcl::DistanceRequestd request_{false};  // nearest triangle only; the closest point is ours
};

}  // namespace

std::unique_ptr<Collider> make_fcl_collider(const ColliderOptions& options) {
  return std::make_unique<FclCollider>(options);
}

}  // namespace clothbench
