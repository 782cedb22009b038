#include "clothbench/collide_os/vdb_collider.hpp"

#include <openvdb/openvdb.h>
#include <openvdb/tools/Interpolation.h>
#include <openvdb/tools/MeshToVolume.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "clothbench/sim/mesh_query.hpp"
#include "clothbench/sim/timer.hpp"
#include "object_space.hpp"
#include "triangle_tree.hpp"

namespace clothbench {

namespace {

using Mesh = openvdb::tools::QuadAndTriangleDataAdapter<openvdb::Vec3d, openvdb::Vec3I>;

// voxels the trilinear samples of one answer reach beyond the point's depth: the gradient's
// +-1 voxel step plus a cell diagonal (sqrt 3) of the trilinear stencil, rounded up
constexpr int kStencilVoxels = 3;
// how deep inside [m] the field is kept (interior band, on top of kStencilVoxels): cloth the
// response pushes out rarely gets this deep (the accuracy limit is 5 mm); deeper points take the
// exact fallback (closest triangle on a box tree). On the walking body at 2 mm voxels a 2 cm band cost 3.1 s per
// build, 1 cm about 2.6 s, 3 voxels 1.9 s: the voxelisation and the exterior band dominate
constexpr Real kInteriorDepth = 0.01f;
// refuse bodies whose narrow band would need more voxels than this (about 1 GB of grids)
constexpr double kMaxBandVoxels = 1e8;

// surface area of a frame [m^2]
double surface_area(const BodyFrame& b) {
  double area = 0;
  for (int t = 0; t < b.triangle_count(); ++t) {
    const Vec3 a = b.positions.col(b.triangles(0, t));
    area += 0.5 * double((b.positions.col(b.triangles(1, t)) - a).cross(b.positions.col(b.triangles(2, t)) - a).norm());
  }
  return area;
}

// vertex areas: a third of every adjacent triangle's area [m^2]
std::vector<double> vertex_areas(const BodyFrame& b) {
  std::vector<double> w(std::size_t(b.vertex_count()), 0.0);
  for (int t = 0; t < b.triangle_count(); ++t) {
    const Vec3 a = b.positions.col(b.triangles(0, t));
    const double third =
        double((b.positions.col(b.triangles(1, t)) - a).cross(b.positions.col(b.triangles(2, t)) - a).norm()) / 6.0;
    for (int k = 0; k < 3; ++k) w[std::size_t(b.triangles(k, t))] += third;
  }
  return w;
}

// true when the field represents the surface through x (index space, a body vertex): it changes
// sign (or is zero) on the corners of x's voxel cell and its trilinear value at x is within half a
// voxel of zero. Fails where the body is thinner than about a voxel (all corners outside), and
// at gaps thinner than a voxel or surfaces inside another part of the body (all corners inside)
bool captures_surface(const openvdb::FloatGrid::ConstAccessor& acc, const openvdb::Vec3d& x, Real voxel) {
  const openvdb::Coord c0(openvdb::Coord::floor(x));
  float lo = std::numeric_limits<float>::infinity(), hi = -lo;
  for (int k = 0; k < 8; ++k) {
    const float v = acc.getValue(c0.offsetBy(k & 1, (k >> 1) & 1, (k >> 2) & 1));
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  return lo <= 0 && hi >= 0 && std::abs(openvdb::tools::BoxSampler::sample(acc, x)) <= 0.5f * voxel;
}

}  // namespace

struct VdbCollider::Impl {
  ColliderOptions options;
  openvdb::math::Transform::Ptr transform;  // world = index * voxel_size; voxel centres at integers
  int exterior_voxels = 0;                  // band widths [voxels]
  int interior_voxels = 0;
  std::vector<openvdb::Vec3d> points;       // body vertices in index space
  std::vector<openvdb::Vec3I> triangles;    // body triangles (set_body's topology)
  openvdb::FloatGrid::Ptr sdf;              // signed distance [m], < 0 inside
  openvdb::Int32Grid::Ptr closest;          // closest triangle of each band voxel
  BodyFrame body;                           // the current frame (fallback and velocities)
  PseudoNormals pseudo;                     // the sign of the exact answers, per frame
  detail::TriangleTree tree;                // exact closest points for the deep points
  Box3 reach;                               // body box grown by the exterior band, as built [m]
  Points3 built;                            // body positions the field was built from [m]
  Vec3 shift = Vec3::Zero();                // translation of the body since (a rigid move) [m]
  bool has_body = false;
  bool warned = false;
  double uncaptured = 0;
  std::int64_t deep = 0;
  CollideStats stats;

  explicit Impl(const ColliderOptions& o) : options(o) {
    const Real h = o.voxel_size;
    if (!(h > 0) || !std::isfinite(h))
      throw std::invalid_argument("vdb collider: voxel_size must be positive and finite, got " + std::to_string(h));
    transform = openvdb::math::Transform::createLinearTransform(double(h));
    // every point within tol outside, and its stencil, lies in the exterior band
    exterior_voxels = int(std::ceil(o.tol / h)) + kStencilVoxels;
    interior_voxels = int(std::ceil(kInteriorDepth / h)) + kStencilVoxels;
    stats.threads = std::max(1, o.threads);
  }

  Real h() const { return options.voxel_size; }
  // index space of the field as built: points move back by the body's translation since
  openvdb::Vec3d to_index(const Vec3& p) const {
    const Vec3 q = p - shift;
    return openvdb::Vec3d(q.x(), q.y(), q.z()) / double(h());
  }

  // the body's translation since the build when it moved rigidly by one (every vertex within a
  // thousandth of a voxel of it: the field is then still exact to that), else nothing
  std::optional<Vec3> translation(const Points3& positions) const {
    const Vec3 by = positions.col(0) - built.col(0);
    if (((positions - built).colwise() - by).cwiseAbs().maxCoeff() > 1e-3f * h()) return std::nullopt;
    return by;
  }

  void check_size(const BodyFrame& b) const {
    const double voxels = surface_area(b) * double(exterior_voxels + interior_voxels) / (double(h()) * double(h()));
    if (voxels > kMaxBandVoxels)
      throw std::invalid_argument("vdb collider: voxel_size " + std::to_string(h()) + " m needs about " +
                                  std::to_string(voxels) + " narrow-band voxels for this body (limit " +
                                  std::to_string(kMaxBandVoxels) + "); use a coarser voxel_size");
  }

  // the field and its closest-triangle grid for `body`, on options.threads TBB threads
  void build() {
    built = body.positions;
    shift.setZero();
    points.resize(std::size_t(body.vertex_count()));
    for (int v = 0; v < body.vertex_count(); ++v) points[std::size_t(v)] = to_index(body.positions.col(v));
    const Mesh mesh(points, triangles);
    auto index = openvdb::Int32Grid::create();
    tbb::task_arena arena(stats.threads);
    arena.execute([&] {
      sdf = openvdb::tools::meshToVolume<openvdb::FloatGrid>(mesh, *transform, float(exterior_voxels),
                                                             float(interior_voxels), 0, index.get());
    });
    closest = index;
    pseudo = PseudoNormals(body);
    const Box3 box = bounding_box(body.positions);
    const Vec3 grow = Vec3::Constant(Real(exterior_voxels) * h());
    reach = {box.min - grow, box.max + grow};
    measure_uncaptured();
  }

  void measure_uncaptured() {
    const std::vector<double> area = vertex_areas(body);
    const auto acc = sdf->getConstAccessor();
    double missed = 0, total = 0;
    for (int v = 0; v < body.vertex_count(); ++v) {
      total += area[std::size_t(v)];
      if (!captures_surface(acc, points[std::size_t(v)], h())) missed += area[std::size_t(v)];
    }
    uncaptured = total > 0 ? missed / total : 0.0;
  }

  void warn_uncaptured() {
    if (uncaptured <= 0 || warned) return;
    warned = true;
    std::cerr << "vdb collider: warning: at voxel_size " << 1e3 * h() << " mm the signed distance field misses "
              << 100.0 * uncaptured << " % of the body surface (parts, or gaps between parts, thinner than about a "
              << "voxel; surfaces inside other parts): answers near them may be off by more than a voxel. A smaller "
              << "voxel_size captures thin parts.\n";
  }

  // the exact answer (closest triangle found on the box tree): the fallback for points deeper
  // than the interior band
  Contact exact(const Vec3& p) {
    ++deep;
    ++stats.searches;
    return contact_from_closest(body, pseudo, p, tree.closest(p), options.tol);
  }

  // velocity at the closest point of the nearest of the triangles closest to the corners of x's
  // voxel cell (one voxel's triangle alone is often a neighbour of the point's closest one)
  Vec3 velocity(const openvdb::Int32Grid::ConstAccessor& acc, const Vec3& p, const openvdb::Vec3d& x) const {
    const openvdb::Coord c0(openvdb::Coord::floor(x));
    const auto& tri = body.triangles;
    ClosestPoint best;
    best.dist2 = std::numeric_limits<Real>::infinity();
    for (int k = 0; k < 8; ++k) {
      const int t = acc.getValue(c0.offsetBy(k & 1, (k >> 1) & 1, (k >> 2) & 1));
      if (t < 0 || t >= body.triangle_count() || t == best.triangle) continue;
      const ClosestPoint cp = closest_point_on_triangle(p, body.positions.col(tri(0, t)),
                                                        body.positions.col(tri(1, t)), body.positions.col(tri(2, t)));
      if (cp.dist2 < best.dist2) best = cp, best.triangle = t;
    }
    if (best.triangle < 0) return Vec3::Zero();
    const int t = best.triangle;
    return best.bary(0) * body.velocities.col(tri(0, t)) + best.bary(1) * body.velocities.col(tri(1, t)) +
           best.bary(2) * body.velocities.col(tri(2, t));
  }

  Contact answer(const openvdb::FloatGrid::ConstAccessor& field, const openvdb::Int32Grid::ConstAccessor& index,
                 const Vec3& p) {
    Contact far;
    far.depth = Real(exterior_voxels) * h();
    // beyond the box grown by the band the distance exceeds the band (and index coordinates stay small)
    const Vec3 q = p - shift;
    if ((q.array() < reach.min.array()).any() || (q.array() > reach.max.array()).any()) return far;
    const openvdb::Vec3d x = to_index(p);
    using Sampler = openvdb::tools::BoxSampler;
    const Real d = Sampler::sample(field, x);
    // outside: within the band the field's value, beyond it the band width (both lower bounds up
    // to the interpolation error)
    if (d >= options.tol) {
      far.depth = d;
      return far;
    }
    // inside beyond the interior band the stencil would read the band's constant: exact answer
    if (d < -Real(interior_voxels - kStencilVoxels) * h()) return exact(p);
    const auto diff = [&](const openvdb::Vec3d& e) { return Real(Sampler::sample(field, x + e) - Sampler::sample(field, x - e)); };
    const Vec3 gradient(diff({1, 0, 0}), diff({0, 1, 0}), diff({0, 0, 1}));  // |.| about 2 h [m]
    // a flat field (a medial point, e.g. the centre of a sphere) has no direction: exact answer
    if (!(gradient.norm() > 1e-3f * h())) return exact(p);
    Contact c;
    c.hit = true;
    c.depth = d;
    c.normal = gradient.normalized();
    if (body.moving) c.body_velocity = velocity(index, p, x);
    return c;
  }
};

VdbCollider::VdbCollider(const ColliderOptions& options) : impl_(std::make_unique<Impl>(options)) {}

VdbCollider::~VdbCollider() = default;

void VdbCollider::set_body(const BodyFrame& body) {
  Stopwatch sw;
  validate_body(body, "vdb collider");
  Impl& s = *impl_;
  s.check_size(body);
  s.has_body = false;
  s.body = body;
  s.triangles.resize(std::size_t(body.triangle_count()));
  for (int t = 0; t < body.triangle_count(); ++t)
    s.triangles[std::size_t(t)] = openvdb::Vec3I(openvdb::Index32(body.triangles(0, t)),
                                                 openvdb::Index32(body.triangles(1, t)),
                                                 openvdb::Index32(body.triangles(2, t)));
  s.build();
  s.tree.build(s.body);
  s.has_body = true;
  s.warned = false;
  s.warn_uncaptured();
  s.stats.setup_ms += sw.ms();
}

void VdbCollider::update_body(const BodyFrame& body) {
  Stopwatch sw;
  Impl& s = *impl_;
  detail::check_update(s.body, s.has_body, body, "vdb collider");
  s.check_size(body);
  detail::adopt_frame(s.body, body);
  // a rigidly translated body (the moving sphere scenes) keeps its field, shifted; anything else
  // (a skinned walking body) is voxelised again
  if (const std::optional<Vec3> by = s.translation(body.positions)) {
    s.shift = *by;
    s.pseudo = PseudoNormals(s.body);
  } else {
    s.build();
  }
  s.tree.refit();
  s.warn_uncaptured();
  s.stats.update_ms += sw.ms();
  ++s.stats.updates;
}

void VdbCollider::query(PointsView points, ContactsOut out) {
  Impl& s = *impl_;
  std::optional<openvdb::FloatGrid::ConstAccessor> field;
  std::optional<openvdb::Int32Grid::ConstAccessor> index;
  if (s.has_body) field.emplace(s.sdf->getConstAccessor()), index.emplace(s.closest->getConstAccessor());
  detail::answer_points(points, out, s.has_body, s.stats,
                        [&](std::size_t, const Vec3& p) { return s.answer(*field, *index, p); });
}

CollideStats VdbCollider::stats() const { return impl_->stats; }

double VdbCollider::uncaptured_share() const { return impl_->uncaptured; }

std::int64_t VdbCollider::deep_points() const { return impl_->deep; }

std::unique_ptr<Collider> make_vdb_collider(const ColliderOptions& options) {
  return std::make_unique<VdbCollider>(options);
}

}  // namespace clothbench
