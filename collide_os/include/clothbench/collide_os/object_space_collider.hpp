#pragma once
/// ObjectSpaceCollider: what the object-space colliders (fcl, embree, vdb, bbtree) share, as
/// ipc-toolkit's BroadPhase holds the state of its methods: the body and its checks, the state kept
/// per frame, the query loop and the stats. A backend implements build, refit and nearest (or its
/// own answer) over the body the base keeps.
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>

#include "clothbench/sim/collider.hpp"
#include "clothbench/sim/mesh_query.hpp"

namespace clothbench {

namespace detail {
class Coherence;
struct PointMemory;
}  // namespace detail

/// Object-space collider: each point answered from the body's geometry (a tree of boxes, a
/// distance field). Non-copyable; a backend's library handles stay inside its .cpp file.
/// - set_body: validate_body (std::invalid_argument for an empty body, a non-finite vertex or an
///   index out of range), the backend's check(), then build(); timed in stats().setup_ms.
/// - update_body: std::invalid_argument before set_body or for another topology, check(), then
///   refit(); timed in stats().update_ms, counted in stats().updates.
/// - query: NaN points, and every point before a body is set, are degenerate misses
///   (stats().degenerate); answer() answers the rest, hits counted in stats().hits, closest-point
///   searches in stats().searches; timed in stats().query_ms. Never throws.
/// Exact backends (Keeps::kPointBounds) answer the contract: hit when inside or closer than tol,
/// with the exact answer of the closest point (mesh_query.hpp, as `brute`); a miss's depth is a
/// lower bound >= tol. With options.coherent (default) each point of an array queried before keeps
/// a bound: one that cannot have come within tol since (its own motion plus the body's) is a miss
/// without a search, the others search within the distance to their last closest triangle.
/// Without it, every point searches within options.search_radius, and points inside the body's box
/// with nothing there get an unbounded search.
class ObjectSpaceCollider : public Collider {
 public:
  ~ObjectSpaceCollider() override;

  std::string_view name() const final { return name_; }
  void set_body(const BodyFrame& body) final;
  void update_body(const BodyFrame& body) final;
  void query(PointsView points, ContactsOut out) final;
  CollideStats stats() const final { return stats_; }

 protected:
  /// The body state a backend's answers read, which the base keeps current for every frame.
  enum class Keeps {
    kFrame,          ///< the frame alone (body())
    kPseudoNormals,  ///< also its pseudo-normals and bounding box (pseudo_normals(), box())
    kPointBounds,    ///< also, with options.coherent, each query point's bounds between queries;
                     ///< answers are the exact ones from nearest()
  };
  /// What a backend is, for the base.
  struct Traits {
    std::string_view name;  ///< registry name; errors say "<name> collider: ..."
    Keeps keeps = Keeps::kPointBounds;
    int threads = 1;                ///< reported in stats().threads
    bool parallel_queries = false;  ///< a query is split over `threads` workers in contiguous
                                    ///< chunks of at least 256 points (answer() is then thread-safe)
  };

  /// `options` as the registry passes them; `traits` as above.
  ObjectSpaceCollider(const ColliderOptions& options, const Traits& traits);

  /// Throws std::invalid_argument for a frame (validated) this backend cannot take; set_body and
  /// update_body call it before they change anything. Default: takes every frame.
  virtual void check(const BodyFrame& body) const;
  /// Builds the backend's structure over `body`, the collider's own copy (body(): it stays at its
  /// address, later frames are copied into it); what Keeps asks is already current.
  virtual void build(const BodyFrame& body) = 0;
  /// Fits the structure to `body`'s new positions (the topology of build); what Keeps asks is
  /// already current.
  virtual void refit(const BodyFrame& body) = 0;
  /// Exact closest point of the body to p strictly closer than `radius` [m] (infinity:
  /// unbounded); triangle = -1 when there is none. What the default answer() searches with.
  /// Default: none.
  virtual ClosestPoint nearest(const Vec3& p, Real radius) const;
  /// Contact for the finite point p [m], counting the closest-point searches it runs in
  /// `searches`. `memory`: p's bounds from the queries before (Keeps::kPointBounds with
  /// options.coherent), else null. Default: the exact answer through nearest() (see above).
  virtual Contact answer(const Vec3& p, detail::PointMemory* memory, std::int64_t& searches) const;

  /// The options the collider was made with.
  const ColliderOptions& options() const { return options_; }
  /// The current frame.
  const BodyFrame& body() const { return body_; }
  /// The current frame's pseudo-normals (Keeps::kPseudoNormals and above).
  const PseudoNormals& pseudo_normals() const { return pseudo_; }
  /// The current frame's bounding box [m] (Keeps::kPseudoNormals and above).
  const Box3& box() const { return box_; }

 private:
  // the pseudo-normals and box of body_, as keeps_ asks
  void fit_frame_state();
  // answers the points of one chunk; its hits, degenerate points and searches
  CollideStats answer_chunk(PointsView points, ContactsOut out, detail::PointMemory* memory) const;

  ColliderOptions options_;
  std::string name_;
  std::string what_;  // "<name> collider", the subject of error messages
  Keeps keeps_;
  bool parallel_queries_;
  BodyFrame body_;                                // the current frame
  PseudoNormals pseudo_;                          // points into body_.triangles
  Box3 box_;                                      // bounding box of body_.positions [m]
  std::unique_ptr<detail::Coherence> coherence_;  // per-point bounds between queries
  bool has_body_ = false;
  CollideStats stats_;
};

}  // namespace clothbench
