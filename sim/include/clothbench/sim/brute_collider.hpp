#pragma once
/// `brute`: exact answers by testing every body triangle, O(points x triangles).
/// The reference of the conformance suite and of the accuracy oracle's tests.
#include "clothbench/sim/collider.hpp"
#include "clothbench/sim/mesh_query.hpp"

namespace clothbench {

class BruteForceCollider final : public Collider {
 public:
  explicit BruteForceCollider(ColliderOptions options = {});
  std::string_view name() const override { return "brute"; }
  void set_body(const BodyFrame& body) override;
  void update_body(const BodyFrame& body) override;
  void query(PointsView points, ContactsOut out) override;
  CollideStats stats() const override { return stats_; }

 private:
  ColliderOptions options_;
  BodyFrame body_;
  PseudoNormals pseudo_;
  CollideStats stats_;
};

}  // namespace clothbench
