// `impulses`: walking Eq. 5 on the structural springs (the ones strain is judged on, and that carry the weight) as
// accumulated impulses, the body's contacts in the same solve (sequential impulses, Catto 2005, "Iterative dynamics
// with temporal coherence"). A pass corrects each spring's impulse in turn, clamped so that a spring only ever pulls
// its ends together: walking Eq. 5's correction, the stretching components to their mass-weighted mean keeping the
// relative velocity that ends the step at (1 + threshold) l0. A vertex in contact gets an accumulated impulse along
// the contact normal that only pushes out, so the limit and the body share one solve: a limit that pulled a spring
// lying on the body into it, undone by the response afterwards, would be found again at every pass and every step.
// With face queries a quad whose midpoint is in contact gets one too, shared by its four corners (the midpoint's
// velocity is theirs averaged, dressing section 6): else the call after the response pulls corners back in.
// A step starts from half the impulses the last step's first call ended with (kWarm). The shortening of a spring
// already past max_len (at `speed` at most, as the sweeps do) moves the positions over the step and is taken out of
// the velocities afterwards (split impulses, after Catto): kept, the next step would correct the same excess again.
// Measured (results/limiters.md): in our stable regime one or two passes hold every limit where the sweeps need eight;
// at the papers' clock (dt 5 ms, soft springs) it misses or diverges.
#include <algorithm>
#include <cmath>
#include <vector>

#include "../merged_points.hpp"
#include "limiters.hpp"
#include "stretch_rules.hpp"

namespace clothbench {

namespace {

// the share of the last step's impulses a step starts from: at full weight the accumulated impulse acts on stiff
// springs as an integral controller acts on a plant with a delay, and a strip held taut between two fronts in the
// stable regime diverged at tight thresholds (Limiters.ImpulsesHoldATautStripInTheStableRegime)
constexpr Real kWarm = 0.5f;

class Impulses final : public Limiter {
 public:
  explicit Impulses(const LimiterParams& params) : params_(params) {}
  std::unique_ptr<Limiter> clone() const override { return std::make_unique<Impulses>(*this); }
  void limit_velocities(LimitState& state, bool contacts_hold) override;
  void limit_positions(LimitState& state) override;

 private:
  struct Link {
    int a, b;          // the spring's ends
    Real max_len;      // (1 + threshold) l0
    Real impulse = 0;  // accumulated in the call under way [kg m/s]
    Real excess = 0;   // accumulated in the call under way, shortening a spring past max_len [kg m/s]
    Real warm = 0;     // what the step's first call ended with: the next step starts from it
  };
  struct Touch {
    int i;          // a vertex in contact, or with face queries a quad whose midpoint is (contacts[nv + quad])
    Real w;         // the velocity change a unit impulse along the normal gives it: its point's, or the quad's
    Real push = 0;  // the body's accumulated impulse on it along the contact normal [kg m/s]
  };

  void build(const ClothMesh& mesh);
  void gather_points(const LimitState& s);
  void gather_touches(const LimitState& s);
  void warm_start(LimitState& s);
  Real pass_springs(LimitState& s);
  Real pass_touches(LimitState& s);
  Real pass_face_touches(LimitState& s);
  Real face_inverse_mass(const ClothMesh& mesh, int q) const;
  void keep_warm();
  std::size_t point(int i) const { return static_cast<std::size_t>(point_[static_cast<std::size_t>(i)]); }
  Real w(int i) const { return w_[static_cast<std::size_t>(i)]; }

  LimiterParams params_;
  std::vector<Link> links_;
  std::vector<Touch> touches_;       // this step's vertices
  std::vector<Touch> face_touches_;  // this step's quads
  std::vector<Real> push_warm_;  // per vertex, then quad: the body's impulse at the end of the last step's first call
  std::vector<int> point_;       // per vertex: the vertex whose velocity it moves with (its sewn group's first)
  Points3 shortening_;           // per vertex: the velocity the shortening gave its point this step [m/s]
  std::vector<Real> w_;          // per vertex: the inverse mass of its point (a sewn group's: 1 / the members' sum)
};

void Impulses::build(const ClothMesh& mesh) {
  const Real factor = 1 + params_.threshold;
  for (Eigen::Index s = 0; s < mesh.springs.cols(); ++s)
    if (mesh.kind[static_cast<std::size_t>(s)] == SpringKind::kStructural)
      links_.push_back({mesh.springs(0, s), mesh.springs(1, s), factor * mesh.rest_length[s]});
}

void Impulses::gather_points(const LimitState& s) {
  // a sewn point is one point to the limit: its members share one velocity and the sum of their masses
  const auto nv = static_cast<std::size_t>(s.x.cols());
  point_ = sewn_point_of(nv, s.merged);
  w_.resize(nv);
  for (std::size_t i = 0; i < nv; ++i) w_[i] = s.inv_m[static_cast<Eigen::Index>(i)];
  for (const auto& group : s.merged) {
    Real m = 0;
    bool attached = false;
    for (int i : group) m += s.m[i], attached = attached || s.inv_m[i] == 0;
    for (int i : group) w_[static_cast<std::size_t>(i)] = attached ? 0 : 1 / m;
  }
}

void Impulses::gather_touches(const LimitState& s) {
  touches_.clear(), face_touches_.clear();
  if (s.contacts.empty()) return;
  push_warm_.resize(s.contacts.size(), 0);
  const Eigen::Index nv = s.x.cols();
  for (Eigen::Index i = 0; i < nv; ++i)
    if (s.contacts[static_cast<std::size_t>(i)].hit && w(static_cast<int>(i)) > 0)
      touches_.push_back({static_cast<int>(i), w(static_cast<int>(i))});
  for (std::size_t c = static_cast<std::size_t>(nv); c < s.contacts.size(); ++c) {
    const int q = static_cast<int>(c) - static_cast<int>(nv);
    const Real wq = face_inverse_mass(s.mesh, q);
    if (s.contacts[c].hit && wq > 0) face_touches_.push_back({q, wq});
  }
}

Real Impulses::face_inverse_mass(const ClothMesh& mesh, int q) const {
  return quad_midpoint_inverse_mass(
      mesh.quads, q, [&](int i) { return point(i); }, [&](int i) { return w(i); });
}

void Impulses::warm_start(LimitState& s) {
  // the last step's impulses, along the springs and the contact normals as they are now
  for (Touch& t : touches_) {
    t.push = kWarm * push_warm_[static_cast<std::size_t>(t.i)];
    s.v.col(point(t.i)) += t.push * t.w * s.contacts[static_cast<std::size_t>(t.i)].normal;
  }
  const auto nv = static_cast<std::size_t>(s.x.cols());
  for (Touch& t : face_touches_) {
    t.push = kWarm * push_warm_[nv + static_cast<std::size_t>(t.i)];
    for (int k = 0; k < 4; ++k) {
      const int i = s.mesh.quads(k, t.i);
      s.v.col(point(i)) += Real(0.25) * t.push * w(i) * s.contacts[nv + static_cast<std::size_t>(t.i)].normal;
    }
  }
  for (Link& l : links_) {
    l.impulse = kWarm * l.warm, l.excess = 0;
    if (l.impulse == 0) continue;
    const Vec3 d = s.x.col(l.b) - s.x.col(l.a);
    const Real len = d.norm();
    if (point(l.a) == point(l.b) || !(len > 0)) {
      l.impulse = 0;
      continue;
    }
    s.v.col(point(l.a)) += l.impulse * w(l.a) * d / len;
    s.v.col(point(l.b)) -= l.impulse * w(l.b) * d / len;
  }
}

Real Impulses::pass_springs(LimitState& s) {
  // one Gauss-Seidel pass of walking Eq. 5 on the accumulated impulses; returns the largest velocity change [m/s]
  const Real dt = s.dt;
  Real largest = 0;
  for (Link& l : links_) {
    const std::size_t pa = point(l.a), pb = point(l.b);
    const Vec3 d = s.x.col(l.b) - s.x.col(l.a);
    const Vec3 dv = s.v.col(static_cast<Eigen::Index>(pb)) - s.v.col(static_cast<Eigen::Index>(pa));
    const Vec3 d_end = d + dt * dv;  // the length this step would give (Eq. 3 position update)
    const Real len_end2 = d_end.squaredNorm();
    if (l.impulse == 0 && l.excess == 0 && !(len_end2 > l.max_len * l.max_len))
      continue;  // most springs: no square root
    const Real wa = w(l.a), wb = w(l.b), len_end = std::sqrt(len_end2);
    if (pa == pb || !(wa + wb > 0) || !(len_end > 0)) continue;
    // the end-of-step line, pointing as the spring points now: ends that would pass each other within the step
    // (a short spring at a large dt) approach along it, and are no stretch to hold
    const Vec3 u = (d_end.dot(d) < 0 ? -d_end : d_end) / len_end;
    // stretching stops at max_len (the warm-started impulse); a spring already past it also shortens at `speed` at
    // most (the excess: an impulse of this call only)
    const Real d2 = d.squaredNorm();
    const Real allowed = d2 > l.max_len * l.max_len
                             ? stretch_rules::allowed_length(std::sqrt(d2), l.max_len, params_.speed * dt)
                             : l.max_len;
    const Real target = (allowed - d.dot(u)) / dt;
    const Real rel = dv.dot(u);
    // Eq. 5 keeps `target` between the ends; clamped, the accumulated impulses never push them apart
    const Real next = std::max(Real(0), l.impulse + (rel - std::max(target, Real(0))) / (wa + wb));
    const Real change = next - l.impulse;
    l.impulse = next;
    const Real excess = std::max(Real(0), l.excess + (rel - change * (wa + wb) - target) / (wa + wb));
    const Real shorten = excess - l.excess;
    l.excess = excess;
    if (change == 0 && shorten == 0) continue;
    const Vec3 total = (change + shorten) * u;
    s.v.col(static_cast<Eigen::Index>(pa)) += wa * total;
    s.v.col(static_cast<Eigen::Index>(pb)) -= wb * total;
    // the shortening moves the positions over this step only (limit_positions takes it out of the velocities)
    shortening_.col(static_cast<Eigen::Index>(pa)) += shorten * wa * u;
    shortening_.col(static_cast<Eigen::Index>(pb)) -= shorten * wb * u;
    largest = std::max(largest, std::abs(change + shorten) * (wa + wb));
  }
  return largest;
}

Real Impulses::pass_touches(LimitState& s) {
  // the body stops the motion into it of the vertices in contact, relative to it (an impulse that only pushes out)
  Real largest = 0;
  for (Touch& t : touches_) {
    const Contact& c = s.contacts[static_cast<std::size_t>(t.i)];
    const auto p = static_cast<Eigen::Index>(point(t.i));
    const Real next = std::max(Real(0), t.push - (s.v.col(p) - c.body_velocity).dot(c.normal) / t.w);
    const Real change = next - t.push;
    if (change == 0) continue;
    t.push = next;
    s.v.col(p) += change * t.w * c.normal;
    largest = std::max(largest, std::abs(change) * t.w);
  }
  return largest;
}

Real Impulses::pass_face_touches(LimitState& s) {
  // the body stops the motion into it of the quad midpoints in contact: dressing section 6's midpoint, one impulse
  // that only pushes out, a quarter to each corner
  const auto nv = static_cast<std::size_t>(s.x.cols());
  Real largest = 0;
  for (Touch& t : face_touches_) {
    const Contact& c = s.contacts[nv + static_cast<std::size_t>(t.i)];
    Vec3 mid = Vec3::Zero();
    for (int k = 0; k < 4; ++k) mid += Real(0.25) * s.v.col(point(s.mesh.quads(k, t.i)));
    const Real next = std::max(Real(0), t.push - (mid - c.body_velocity).dot(c.normal) / t.w);
    const Real change = next - t.push;
    if (change == 0) continue;
    t.push = next;
    for (int k = 0; k < 4; ++k) {
      const int i = s.mesh.quads(k, t.i);
      s.v.col(point(i)) += Real(0.25) * change * w(i) * c.normal;
    }
    largest = std::max(largest, std::abs(change) * t.w);
  }
  return largest;
}

void Impulses::keep_warm() {
  for (Link& l : links_) l.warm = l.impulse;
  std::fill(push_warm_.begin(), push_warm_.end(), Real(0));
  for (const Touch& t : touches_) push_warm_[static_cast<std::size_t>(t.i)] = t.push;
  const std::size_t nv = point_.size();
  for (const Touch& t : face_touches_) push_warm_[nv + static_cast<std::size_t>(t.i)] = t.push;
}

void Impulses::limit_velocities(LimitState& s, bool contacts_hold) {
  if (links_.empty()) build(s.mesh);
  move_as_one(s.merged, s.m, s.inv_m, s.v, nullptr, [](int, Real) {});
  gather_points(s);
  // the step's first call starts from the last step's impulses; the call after the response goes on from there,
  // and what it adds (the response's share) is not carried into the next step
  if (!contacts_hold) gather_touches(s), warm_start(s), shortening_.setZero(3, s.x.cols());
  for (int k = 0; k < params_.passes; ++k) {
    const Real largest = std::max({pass_springs(s), pass_touches(s), pass_face_touches(s)});
    ++passes_;
    if (!(largest * s.dt > params_.tolerance)) break;
  }
  for (const auto& group : s.merged)
    for (int i : group) s.v.col(i) = s.v.col(group.front());
  if (!contacts_hold) keep_warm();
}

void Impulses::limit_positions(LimitState& s) {
  // the shortening of springs past max_len moved the positions over the step; the velocities do not keep it (split
  // impulses, after Catto: kept, the next step's warm start would correct the same excess again)
  if (shortening_.cols() != s.v.cols()) return;
  for (Eigen::Index i = 0; i < s.v.cols(); ++i)
    s.v.col(i) -= shortening_.col(static_cast<Eigen::Index>(point(static_cast<int>(i))));
}

}  // namespace

std::unique_ptr<Limiter> make_impulses_limit(const LimiterParams& params) { return std::make_unique<Impulses>(params); }

}  // namespace clothbench
