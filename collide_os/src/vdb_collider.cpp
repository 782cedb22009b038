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
#include "triangle_tree.hpp"

namespace clothbench {

namespace {

using Mesh = openvdb::tools::QuadAndTriangleDataAdapter<openvdb::Vec3d, openvdb::Vec3I>;
using FieldAccessor = openvdb::FloatGrid::ConstAccessor;
using IndexAccessor = openvdb::Int32Grid::ConstAccessor;

// voxels the trilinear samples of one answer reach beyond the point's depth: the gradient's
// +-1 voxel step plus a cell diagonal (sqrt 3) of the trilinear stencil, rounded up
constexpr int kStencilVoxels = 3;
// how deep inside [m] the field is kept (interior band, on top of kStencilVoxels): cloth the
// response pushes out rarely gets this deep (the accuracy limit is 5 mm); deeper points take the
// exact fallback (closest triangle on a box tree). A deeper band costs more voxels to build, a thinner one more
// fallbacks; the voxelisation and the exterior band dominate a build either way
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
  Real h = 0;                               // voxel edge [m]
  int threads = 1;                          // TBB threads of the field's build
  openvdb::math::Transform::Ptr transform;  // world = index * voxel_size; voxel centres at integers
  int exterior_voxels = 0;                  // band widths [voxels]
  int interior_voxels = 0;
  std::vector<openvdb::Vec3d> points;       // body vertices in index space
  std::vector<openvdb::Vec3I> triangles;    // body triangles (set_body's topology)
  openvdb::FloatGrid::Ptr sdf;              // signed distance [m], < 0 inside
  openvdb::Int32Grid::Ptr closest;          // closest triangle of each band voxel
  std::optional<FieldAccessor> field;       // reads sdf (queries run on one thread)
  std::optional<IndexAccessor> index;       // reads closest
  detail::TriangleTree tree;                // exact closest points for the deep points
  Box3 reach;                               // body box grown by the exterior band, as built [m]
  Points3 built;                            // body positions the field was built from [m]
  Vec3 shift = Vec3::Zero();                // translation of the body since (a rigid move) [m]
  bool warned = false;
  double uncaptured = 0;

  explicit Impl(const ColliderOptions& o) : h(o.voxel_size), threads(std::max(1, o.threads)) {
    if (!(h > 0) || !std::isfinite(h))
      throw std::invalid_argument("vdb collider: voxel_size must be positive and finite, got " + std::to_string(h));
    transform = openvdb::math::Transform::createLinearTransform(double(h));
    // every point within tol outside, and its stencil, lies in the exterior band
    exterior_voxels = int(std::ceil(o.tol / h)) + kStencilVoxels;
    interior_voxels = int(std::ceil(kInteriorDepth / h)) + kStencilVoxels;
  }

  // index space of the field as built: points move back by the body's translation since
  openvdb::Vec3d to_index(const Vec3& p) const {
    const Vec3 q = p - shift;
    return openvdb::Vec3d(q.x(), q.y(), q.z()) / double(h);
  }

  // the body's translation since the build when it moved rigidly by one (every vertex within a
  // thousandth of a voxel of it: the field is then still exact to that), else nothing
  std::optional<Vec3> translation(const Points3& positions) const {
    const Vec3 by = positions.col(0) - built.col(0);
    if (((positions - built).colwise() - by).cwiseAbs().maxCoeff() > 1e-3f * h) return std::nullopt;
    return by;
  }

  void check_size(const BodyFrame& b) const {
    const double voxels = surface_area(b) * double(exterior_voxels + interior_voxels) / (double(h) * double(h));
    if (voxels > kMaxBandVoxels)
      throw std::invalid_argument("vdb collider: voxel_size " + std::to_string(h) + " m needs about " +
                                  std::to_string(voxels) + " narrow-band voxels for this body (limit " +
                                  std::to_string(kMaxBandVoxels) + "); use a coarser voxel_size");
  }

  // the field and its closest-triangle grid for `body` (bounding box `box`), on `threads` TBB threads
  void build(const BodyFrame& body, const Box3& box) {
    built = body.positions;
    shift.setZero();
    points.resize(std::size_t(body.vertex_count()));
    for (int v = 0; v < body.vertex_count(); ++v) points[std::size_t(v)] = to_index(body.positions.col(v));
    const Mesh mesh(points, triangles);
    auto grid_index = openvdb::Int32Grid::create();
    field.reset();
    index.reset();
    tbb::task_arena arena(threads);
    arena.execute([&] {
      sdf = openvdb::tools::meshToVolume<openvdb::FloatGrid>(mesh, *transform, float(exterior_voxels),
                                                             float(interior_voxels), 0, grid_index.get());
    });
    closest = grid_index;
    field.emplace(sdf->getConstAccessor());
    index.emplace(closest->getConstAccessor());
    const Vec3 grow = Vec3::Constant(Real(exterior_voxels) * h);
    reach = {box.min - grow, box.max + grow};
    measure_uncaptured(body);
  }

  void measure_uncaptured(const BodyFrame& body) {
    const std::vector<double> area = vertex_areas(body);
    double missed = 0, total = 0;
    for (int v = 0; v < body.vertex_count(); ++v) {
      total += area[std::size_t(v)];
      if (!captures_surface(*field, points[std::size_t(v)], h)) missed += area[std::size_t(v)];
    }
    uncaptured = total > 0 ? missed / total : 0.0;
  }

  void warn_uncaptured() {
    if (uncaptured <= 0 || warned) return;
    warned = true;
    std::cerr << "vdb collider: warning: at voxel_size " << 1e3 * h << " mm the signed distance field misses "
              << 100.0 * uncaptured << " % of the body surface (parts, or gaps between parts, thinner than about a "
              << "voxel; surfaces inside other parts): answers near them may be off by more than a voxel. A smaller "
              << "voxel_size captures thin parts.\n";
  }

  // velocity at the closest point of the nearest of the triangles closest to the corners of x's
  // voxel cell (one voxel's triangle alone is often a neighbour of the point's closest one)
  Vec3 velocity(const BodyFrame& body, const Vec3& p, const openvdb::Vec3d& x) const {
    const openvdb::Coord c0(openvdb::Coord::floor(x));
    const auto& tri = body.triangles;
    ClosestPoint best;
    best.dist2 = std::numeric_limits<Real>::infinity();
    for (int k = 0; k < 8; ++k) {
      const int t = index->getValue(c0.offsetBy(k & 1, (k >> 1) & 1, (k >> 2) & 1));
      if (t < 0 || t >= body.triangle_count() || t == best.triangle) continue;
      const ClosestPoint cp = closest_point_on_triangle(p, body.positions.col(tri(0, t)), body.positions.col(tri(1, t)),
                                                        body.positions.col(tri(2, t)));
      if (cp.dist2 < best.dist2) best = cp, best.triangle = t;
    }
    if (best.triangle < 0) return Vec3::Zero();
    const int t = best.triangle;
    return best.bary(0) * body.velocities.col(tri(0, t)) + best.bary(1) * body.velocities.col(tri(1, t)) +
           best.bary(2) * body.velocities.col(tri(2, t));
  }
};

VdbCollider::VdbCollider(const ColliderOptions& options)
    : ObjectSpaceCollider(options, {"vdb", Keeps::kPseudoNormals, std::max(1, options.threads)}),
      impl_(std::make_unique<Impl>(options)) {}

VdbCollider::~VdbCollider() = default;

void VdbCollider::check(const BodyFrame& body) const { impl_->check_size(body); }

void VdbCollider::build(const BodyFrame& body) {
  Impl& s = *impl_;
  s.triangles.resize(std::size_t(body.triangle_count()));
  for (int t = 0; t < body.triangle_count(); ++t)
    s.triangles[std::size_t(t)] =
        openvdb::Vec3I(openvdb::Index32(body.triangles(0, t)), openvdb::Index32(body.triangles(1, t)),
                       openvdb::Index32(body.triangles(2, t)));
  s.build(body, box());
  s.tree.build(body);
  s.warned = false;
  s.warn_uncaptured();
}

void VdbCollider::refit(const BodyFrame& body) {
  Impl& s = *impl_;
  // a rigidly translated body (the moving sphere scenes) keeps its field, shifted; anything else
  // (a skinned walking body) is voxelised again
  if (const std::optional<Vec3> by = s.translation(body.positions))
    s.shift = *by;
  else
    s.build(body, box());
  s.tree.refit();
  s.warn_uncaptured();
}

Contact VdbCollider::answer(const Vec3& p, detail::PointMemory* memory, std::int64_t& searches) const {
  (void)memory;
  const Impl& s = *impl_;
  const Real h = s.h, tol = options().tol;
  Contact far;
  far.depth = Real(s.exterior_voxels) * h;
  // beyond the box grown by the band the distance exceeds the band (and index coordinates stay small)
  const Vec3 q = p - s.shift;
  if ((q.array() < s.reach.min.array()).any() || (q.array() > s.reach.max.array()).any()) return far;
  const openvdb::Vec3d x = s.to_index(p);
  using Sampler = openvdb::tools::BoxSampler;
  const Real d = Sampler::sample(*s.field, x);
  // outside: within the band the field's value, beyond it the band width (both lower bounds up
  // to the interpolation error)
  if (d >= tol) {
    far.depth = d;
    return far;
  }
  // the exact answer (closest triangle found on the box tree): for points deeper inside than the
  // interior band, where the stencil would read the band's constant, and on a flat field (a
  // medial point, e.g. the centre of a sphere), which has no direction
  const auto exact = [&] {
    ++searches;
    return contact_from_closest(body(), pseudo_normals(), p, s.tree.closest(p), tol);
  };
  if (d < -Real(s.interior_voxels - kStencilVoxels) * h) return exact();
  const auto diff = [&](const openvdb::Vec3d& e) {
    return Real(Sampler::sample(*s.field, x + e) - Sampler::sample(*s.field, x - e));
  };
  const Vec3 gradient(diff({1, 0, 0}), diff({0, 1, 0}), diff({0, 0, 1}));  // |.| about 2 h [m]
  if (!(gradient.norm() > 1e-3f * h)) return exact();
  Contact c;
  c.hit = true;
  c.depth = d;
  c.normal = gradient.normalized();
  if (body().moving) c.body_velocity = s.velocity(body(), p, x);
  return c;
}

double VdbCollider::uncaptured_share() const { return impl_->uncaptured; }

std::int64_t VdbCollider::deep_points() const { return stats().searches; }

std::unique_ptr<Collider> make_vdb_collider(const ColliderOptions& options) {
  return std::make_unique<VdbCollider>(options);
}

}  // namespace clothbench
