#pragma once
/// The image-space colliders of the papers (dressing section 5, walking section 4): a point
/// collides when it lies between the front and back depth surfaces of the body, within tol.
#include <memory>
#include <optional>

#include "clothbench/collide_is/map_set.hpp"
#include "clothbench/sim/collider.hpp"

namespace clothbench {

/// How a query point's depth is measured against the maps.
enum class DepthTest {
  /// The papers' comparison along z only (dressing Eq. 9, walking Eq. 12):
  ///   depth = max(z - zf, zb - z), zf / zb = front / back surface z at the point's pixel.
  kPapers,
  /// The same comparison, refined for points within tol + one pixel of the nearer surface by
  /// the normal map: depth = (p - s) . n, s the surface point at the pixel centre, n its normal
  /// (signed distance to the surface's tangent plane instead of the distance along z); normal
  /// and velocity then blended bilinearly at the foot of the perpendicular p - depth n.
  kTangentPlane,
};

/// How the axis pairs of more than two views (ColliderOptions::views 4, 6; beyond the papers)
/// combine. Each pair whose image holds the point answers as the papers' front/back pair does along
/// its own axis: depth_k = max(p - front surface, back surface - p) (dressing Eq. 9, walking Eq. 12).
/// With 2 views every rule is the papers' test.
enum class ViewRule {
  /// The default. Inside only when every pair says between its two surfaces (a visual hull:
  /// depth = the largest depth_k, the surface nearest along any axis); outside as soon as one pair
  /// says beyond its surfaces, sees nothing or answers from its side layer: the smallest positive
  /// depth_k of a body pixel answers (the nearest surface seen from outside, an upper bound on the
  /// distance), else a side-layer answer (a one-pixel guess, not a bound), else a miss. A side-facing point 2 mm out, off
  /// the front/back silhouette, hits through the side pair; a point in a gap that some pair sees
  /// from outside is not taken for inside.
  kHull,
  /// depth = the largest depth_k (intersection): pairs that see nothing make the point a miss.
  kAllPairs,
  /// depth = the smallest depth_k (union): everything between any pair's surfaces is inside.
  kAnyPair,
};

/// How a point is answered from a MapSet: the depth test, the rule between views, the tolerance and
/// ColliderOptions::overlapping_parts (the pinch and fold rules of the peeled layers).
struct AnswerRules {
  DepthTest test;
  ViewRule rule;
  Real tol;
  bool overlapping_parts;
};

/// Image-space collider with maps drawn by OpenGL through OSMesa; name() "is-gl".
/// Static bodies are rendered once in set_body, moving ones again in every update_body
/// (velocity maps only when body.moving; update_body of a static frame after static maps
/// renders nothing). Query per point (dressing Eq. 8/9, walking Eq. 11/12):
///   (col, row) from world (x, y); zf, zb = front and back surface z at that pixel;
///   hit when the point lies between the two surfaces within tol (depth < tol, DepthTest);
///   normal and velocity from the map whose surface is nearer (z beyond the local body centre
///   (zf + zb) / 2 takes the front map, the papers' choice by the sign of z).
/// Side-layer hits (dressing 5.4) report depth >= 0. Depth test kTangentPlane. With
/// options.views 4 or 6 the pairs along X and Y answer too, combined by ViewRule::kHull; with
/// options.layers > 1 each pair answers from the surfaces peeled along its axis (inside where the
/// line's crossings, counted by their facing, say so; depth to the nearer crossing). Throws
/// std::runtime_error when no GL context can be created or the build lacks CLOTHBENCH_WITH_GL.
std::unique_ptr<Collider> make_is_gl_collider(const ColliderOptions& options);

/// The same collider with maps from the CPU rasteriser; name() "is-cpu". In every build.
std::unique_ptr<Collider> make_is_cpu_collider(const ColliderOptions& options);

/// The depth test `options` ask for (tangent_plane: kTangentPlane, else the papers' kPapers).
DepthTest image_space_depth_test(const ColliderOptions& options);

/// The collider over an explicit renderer ("gl", "egl" or "cpu"); the MapSet stays readable for
/// pictures and tests through maps(). Where the renderer keeps its maps on its device (MapRenderer::device_maps(),
/// is-egl), they stay there and answer the queries there, the same answers by the same rules.
class ImageSpaceCollider final : public Collider {
 public:
  /// `setup_ms`: set-up already spent on the renderer (GL context, shaders) [ms].
  /// Throws std::invalid_argument for no renderer, max_speed <= 0 or bad views / layers / side_layer_mm.
  ImageSpaceCollider(std::unique_ptr<MapRenderer> renderer, const ColliderOptions& options, double setup_ms,
                     DepthTest test = DepthTest::kTangentPlane, ViewRule rule = ViewRule::kHull);
  std::string_view name() const override;
  /// The renderer's device (MapRenderer::device()).
  std::string device() const override;
  void set_body(const BodyFrame& body) override;
  void update_body(const BodyFrame& body) override;
  /// Draws the maps of `body` into a second map set, which the following update_body (of the same frame) makes
  /// current (every renderer: the OpenGL ones hold their context only while they draw).
  bool prepare_body(const BodyFrame& body) override;
  /// The maps of the next renders draw only the rows `region` spans (MapSet::limit_rows); a point outside the
  /// region may be answered as if no body were there.
  void set_query_region(const Box3& region) override { region_ = region; }
  void query(PointsView points, ContactsOut out) override;
  CollideStats stats() const override { return stats_; }
  /// The current maps (empty before set_body); a renderer's maps kept on its device are copied out for this.
  const MapSet& maps() const;

 private:
  void check_update(const BodyFrame& body) const;
  // draws `body` into `maps` (on the device: into its map set `slot`, `maps` taking only their shape)
  void draw(const BodyFrame& body, MapSet& maps, int slot);
  // one point's contact; true on a hit
  bool answer(const Vec3& p, Contact& c) const;

  std::unique_ptr<MapRenderer> renderer_;
  DeviceMaps* device_ = nullptr;  // the renderer's maps kept on its device (is-egl), which then answer queries
  int slot_ = 0;                  // device_: the map set of the current maps (next_'s is the other)
  mutable MapSet copy_;           // device_: the current maps copied out, for maps()
  mutable bool copied_ = false;
  ColliderOptions options_;
  DepthTest test_;
  ViewRule rule_;
  MapSet maps_;
  MapSet next_;                 // prepare_body's maps, made current by the next update_body
  bool prepared_ = false;       // next_ holds the maps of the next update_body's frame
  double prepared_ms_ = 0;      // the time prepare_body took (counted as update time once made current)
  std::optional<Box3> region_;  // set_query_region's
  int vertex_count_ = 0;
  CollideStats stats_;
};

}  // namespace clothbench
