#include "clothbench/collide_os/embree_collider.hpp"

#include <algorithm>

#include "clothbench/collide_os/object_space_collider.hpp"
#include "embree_scene.hpp"

namespace clothbench {

namespace {

// the body as an Embree scene; rtcPointQuery gives the exact closest points, on options.threads
// workers per query
class EmbreeCollider final : public ObjectSpaceCollider {
 public:
  explicit EmbreeCollider(const ColliderOptions& options)
      : ObjectSpaceCollider(options, {"embree", Keeps::kPointBounds, std::max(1, options.threads), true}),
        scene_(std::max(1, options.threads)) {}

 private:
  void build(const BodyFrame& body) override { scene_.build(body, body.moving); }
  void refit(const BodyFrame& body) override { scene_.refit(body); }
  ClosestPoint nearest(const Vec3& p, Real radius) const override { return scene_.closest(p, radius); }

  detail::EmbreeScene scene_;
};

}  // namespace

std::unique_ptr<Collider> make_embree_collider(const ColliderOptions& options) {
  return std::make_unique<EmbreeCollider>(options);
}

}  // namespace clothbench
