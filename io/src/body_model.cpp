// BodyModel: skeleton animation (linear keys, slerp rotations) through the node hierarchy, then
// linear blend skinning of the rest mesh, velocities and optional walk in place.
#include <meshoptimizer.h>

#include <algorithm>
#include <cmath>

#include "body_model_impl.hpp"
#include "clothbench/io/errors.hpp"

namespace clothbench {

namespace {

// Velocities: central difference of the continuous skeleton motion at t +- kVelocityStep (clamped to
// the clip). LBS is linear in the skinning matrices, so differencing the matrices equals the central
// difference of the skinned positions, at the cost of one extra matrix blend per vertex.
constexpr double kVelocityStep = 1e-4;  // [s]

// key segment containing t: i with times[i] <= t < times[i+1], and the blend factor
int segment(const std::vector<double>& times, double t, double& u) {
  if (times.size() == 1 || t <= times.front()) {
    u = 0;
    return 0;
  }
  if (t >= times.back()) {
    u = 0;
    return static_cast<int>(times.size()) - 1;
  }
  const auto it = std::upper_bound(times.begin(), times.end(), t);
  const int i = static_cast<int>(it - times.begin()) - 1;
  const double span = times[i + 1] - times[i];
  u = span > 0 ? (t - times[i]) / span : 0;
  return i;
}

template <class V>
V lerp_key(const std::vector<double>& times, const std::vector<V>& values, double t) {
  double u = 0;
  const int i = segment(times, t, u);
  if (u == 0) return values[i];
  return ((1 - u) * values[i] + u * values[i + 1]).eval();
}

Eigen::Quaterniond slerp_key(const std::vector<double>& times, const std::vector<Eigen::Quaterniond>& q, double t) {
  double u = 0;
  const int i = segment(times, t, u);
  if (u == 0) return q[i];
  return q[i].slerp(u, q[i + 1]);  // Eigen's slerp takes the shorter arc
}

// the node's local transform at t: animated T * R * S, each component from the rest when not keyed
Mat4d channel_local(const Channel& c, const Mat4d& rest, double t) {
  Eigen::Affine3d a(rest);
  Eigen::Vector3d pos = a.translation();
  Eigen::Matrix3d rot, scale;
  a.computeRotationScaling(&rot, &scale);
  Eigen::Quaterniond q(rot);
  Eigen::Vector3d s = scale.diagonal();
  if (!c.pos.empty()) pos = lerp_key(c.pos_t, c.pos, t);
  if (!c.rot.empty()) q = slerp_key(c.rot_t, c.rot, t);
  if (!c.scale.empty()) s = lerp_key(c.scale_t, c.scale, t);
  Mat4d m = Mat4d::Identity();
  m.topLeftCorner<3, 3>() = q.normalized().toRotationMatrix() * s.asDiagonal();
  m.topRightCorner<3, 1>() = pos;
  return m;
}

// per-thread scratch so that frame_into allocates nothing after its first call
struct Scratch {
  std::vector<Mat4d> globals, globals_lo, globals_hi;
  std::vector<Mat34f> skin, dskin;
};
Scratch& scratch() {
  thread_local Scratch s;
  return s;
}

Mat34f to34(const Mat4d& m) { return m.topRows<3>().cast<float>(); }

}  // namespace

void BodyModelImpl::node_globals(int a, double t, std::vector<Mat4d>& out) const {
  out.resize(nodes.size());
  for (std::size_t n = 0; n < nodes.size(); ++n) {
    const int ch = a >= 0 ? animations[a].node_channel[n] : -1;
    const Mat4d local = ch >= 0 ? channel_local(animations[a].channels[ch], nodes[n].local, t) : nodes[n].local;
    out[n] = nodes[n].parent >= 0 ? (out[nodes[n].parent] * local).eval() : local;
  }
}

namespace {

// skinning matrices in the DESIGN frame at t, and their time derivative (central difference)
void skin_matrices(const BodyModelImpl& m, int a, double t, Scratch& s) {
  const double duration = a >= 0 ? m.infos[a].duration_s : 0;
  const double lo = std::max(0.0, t - kVelocityStep), hi = std::min(duration, t + kVelocityStep);
  m.node_globals(a, t, s.globals);
  m.node_globals(a, lo, s.globals_lo);
  m.node_globals(a, hi, s.globals_hi);
  s.skin.resize(m.bones.size());
  s.dskin.resize(m.bones.size());
  for (std::size_t b = 0; b < m.bones.size(); ++b) {
    const auto& bone = m.bones[b];
    const Mat4d pre = bone.offset * m.denormalise;
    s.skin[b] = to34(m.normalise * s.globals[bone.node] * pre);
    if (hi > lo) {
      const Mat4d d = m.normalise * (s.globals_hi[bone.node] - s.globals_lo[bone.node]) * pre / (hi - lo);
      s.dskin[b] = to34(d);
    } else {
      s.dskin[b].setZero();
    }
  }
}

// root's horizontal displacement since t = 0 and its horizontal velocity, DESIGN frame
void root_travel(const BodyModelImpl& m, int a, double t, Scratch& s, Vec3& shift, Vec3& vel) {
  shift.setZero();
  vel.setZero();
  if (m.root_node < 0) return;
  std::vector<Mat4d>& g0 = s.globals_lo;  // reuse: lo/hi already consumed
  m.node_globals(a, 0.0, g0);
  const Eigen::Vector3d p0 = (m.normalise * g0[m.root_node]).topRightCorner<3, 1>();
  const Eigen::Vector3d pt = (m.normalise * s.globals[m.root_node]).topRightCorner<3, 1>();
  shift = Vec3(float(pt.x() - p0.x()), 0.f, float(pt.z() - p0.z()));
  const double duration = m.infos[a].duration_s;
  const double lo = std::max(0.0, t - kVelocityStep), hi = std::min(duration, t + kVelocityStep);
  if (!(hi > lo)) return;
  std::vector<Mat4d>& g1 = s.globals_hi;
  m.node_globals(a, lo, g0);
  m.node_globals(a, hi, g1);
  const Eigen::Vector3d d = (m.normalise * (g1[m.root_node] - g0[m.root_node])).topRightCorner<3, 1>() / (hi - lo);
  vel = Vec3(float(d.x()), 0.f, float(d.z()));
}

}  // namespace

void BodyModelImpl::frame_into(BodyFrame& out, int a, double t, bool in_place) const {
  Scratch& s = scratch();
  skin_matrices(*this, a, t, s);
  Vec3 shift = Vec3::Zero(), shift_vel = Vec3::Zero();
  if (in_place) root_travel(*this, a, t, s, shift, shift_vel);
  const Eigen::Index nv = rest.positions.cols();
  out.positions.resize(3, nv);
  out.velocities.resize(3, nv);
  out.normals.resize(3, nv);
  for (Eigen::Index v = 0; v < nv; ++v) {
    Mat34f skin = Mat34f::Zero(), dskin = Mat34f::Zero();
    for (int k = influence_start[v]; k < influence_start[v + 1]; ++k) {
      skin += influence_weight[k] * s.skin[influence_bone[k]];
      dskin += influence_weight[k] * s.dskin[influence_bone[k]];
    }
    const Eigen::Vector4f r(rest.positions(0, v), rest.positions(1, v), rest.positions(2, v), 1.f);
    out.positions.col(v) = skin * r - shift;
    out.velocities.col(v) = dskin * r - shift_vel;
  }
  out.triangles = rest.triangles;  // same size after the first call: no reallocation
  angle_weighted_normals_into(out.positions, out.triangles, out.normals);
  out.time_s = t;
  out.moving = true;
}

void BodyModelImpl::keep_vertices(const std::vector<char>& keep, const Tris& triangles) {
  const Eigen::Index nv = rest.positions.cols();
  std::vector<int> remap(static_cast<std::size_t>(nv), -1);
  int kept = 0;
  for (Eigen::Index v = 0; v < nv; ++v)
    if (keep[v]) remap[v] = kept++;
  Points3 pos(3, kept);
  std::vector<int> start{0}, bone;
  std::vector<float> weight;
  for (Eigen::Index v = 0; v < nv; ++v) {
    if (!keep[v]) continue;
    pos.col(remap[v]) = rest.positions.col(v);
    for (int k = influence_start[v]; k < influence_start[v + 1]; ++k) {
      bone.push_back(influence_bone[k]);
      weight.push_back(influence_weight[k]);
    }
    start.push_back(static_cast<int>(bone.size()));
  }
  Tris out(3, triangles.cols());
  for (Eigen::Index t = 0; t < triangles.cols(); ++t)
    for (int k = 0; k < 3; ++k) out(k, t) = remap[triangles(k, t)];
  rest.positions = std::move(pos);
  rest.triangles = std::move(out);
  influence_start = std::move(start);
  influence_bone = std::move(bone);
  influence_weight = std::move(weight);
}

// ---- BodyModel -------------------------------------------------------------------------------

BodyModel::BodyModel(std::unique_ptr<BodyModelImpl> impl) : impl_(std::move(impl)) {}
BodyModel::BodyModel(BodyModel&&) noexcept = default;
BodyModel& BodyModel::operator=(BodyModel&&) noexcept = default;
BodyModel::~BodyModel() = default;

const BodyFrame& BodyModel::rest() const { return impl_->rest; }
int BodyModel::dropped_parts() const { return impl_->dropped_parts; }
int BodyModel::dropped_vertices() const { return impl_->dropped_vertices; }
const std::vector<std::string>& BodyModel::notes() const { return impl_->notes; }
int BodyModel::bone_count() const { return impl_->bone_count; }
const std::vector<AnimationInfo>& BodyModel::animations() const { return impl_->infos; }
const std::string& BodyModel::path() const { return impl_->path; }

BodyModel BodyModel::simplified(int target_triangles) const {
  const BodyFrame& r = impl_->rest;
  if (target_triangles <= 0 || target_triangles >= r.triangles.cols())
    throw InputError(located(impl_->path, 0,
                             "a simplified body needs 0 < triangles < the body's " +
                                 std::to_string(r.triangles.cols()) + ", got " + std::to_string(target_triangles)));
  // edge collapses by quadric error (meshoptimizer), any error allowed: the triangle count decides
  const auto nv = static_cast<std::size_t>(r.positions.cols());
  std::vector<unsigned> indices(r.triangles.data(), r.triangles.data() + r.triangles.size());
  std::vector<unsigned> kept(indices.size());
  const std::size_t n = meshopt_simplify(kept.data(), indices.data(), indices.size(), r.positions.data(), nv,
                                         3 * sizeof(Real), 3 * static_cast<std::size_t>(target_triangles), 1.0f);
  Tris triangles(3, static_cast<Eigen::Index>(n / 3));
  std::vector<char> keep(nv, 0);
  for (std::size_t i = 0; i < n; ++i) {
    triangles.data()[i] = static_cast<int>(kept[i]);
    keep[kept[i]] = 1;
  }
  auto impl = std::make_unique<BodyModelImpl>(*impl_);
  impl->keep_vertices(keep, triangles);
  finish_static_body(impl->rest);
  return BodyModel(std::move(impl));
}

int BodyModel::animation_index(const std::string& name) const {
  std::string names;
  for (std::size_t i = 0; i < impl_->infos.size(); ++i) {
    if (impl_->infos[i].name == name) return static_cast<int>(i);
    names += (i ? ", " : "") + impl_->infos[i].name;
  }
  throw InputError(located(impl_->path, 0, "no animation named '" + name + "' (animations: " +
                                                (names.empty() ? "none" : names) + ")"));
}

BodyFrame BodyModel::frame(int animation, double t, bool walk_in_place) const {
  BodyFrame out;
  frame_into(out, animation, t, walk_in_place);
  return out;
}

void BodyModel::frame_into(BodyFrame& out, int animation, double t, bool walk_in_place) const {
  const int n = static_cast<int>(impl_->infos.size());
  if (animation < 0 || animation >= n)
    throw InputError(located(impl_->path, 0, "animation index " + std::to_string(animation) + " out of range (" +
                                                 std::to_string(n) + " animations)"));
  const double d = impl_->infos[animation].duration_s;
  if (!(t >= 0 && t <= d + 1e-9))
    throw InputError(located(impl_->path, 0, "time " + std::to_string(t) + " s is outside animation '" +
                                                 impl_->infos[animation].name + "' [0, " + std::to_string(d) + "] s"));
  impl_->frame_into(out, animation, std::min(t, d), walk_in_place);
}

}  // namespace clothbench
