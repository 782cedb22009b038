#pragma once
// The velocity limits' Gauss-Seidel sweep (dressing 4.3, walking 3.2), shared by the members that modify velocities
// spring by spring; each member gives the rule for one over-stretched spring (Derived::split, CRTP: inlined into
// the per-spring step). Our reading: a spring whose next length (Eq. 3) would pass (1 + threshold) l0 keeps the
// relative velocity along its end-of-step line that ends the step at exactly that length; one already past it is
// shortened at `speed` at most. A pass sweeps the springs from the held vertices (attached or in contact) out.
// sim/src only.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "../merged_points.hpp"
#include "clothbench/sim/limiter.hpp"
#include "stretch_rules.hpp"

namespace clothbench {

template <class Derived>
class VelocitySweep : public Limiter {
 public:
  explicit VelocitySweep(const LimiterParams& params) : params_(params) {}
  std::unique_ptr<Limiter> clone() const override {
    return std::make_unique<Derived>(static_cast<const Derived&>(*this));
  }
  void limit_velocities(LimitState& state, bool contacts_hold) override { sweep(state, contacts_hold); }

 protected:
  struct SweptSpring {
    int a, b;      // the spring's ends
    Real max_len;  // (1 + threshold) l0
  };

  void sweep(LimitState& state, bool contacts_hold) { begin(state), passes(contacts_hold); }
  // the call's arrays, the adjacency (once) and the held points: attached ones and those the body holds (in contact)
  void begin(LimitState& state);
  // the passes over the springs, swept from the held points
  void passes(bool contacts_hold);
  // f(j, e) for every neighbour j of vertex i over a spring (e < springs) or a seam pair (e = springs + pair)
  template <class F>
  void for_each_neighbour(int i, F&& f) const {
    for (int k = adj_start_[static_cast<std::size_t>(i)]; k < adj_start_[static_cast<std::size_t>(i) + 1]; ++k)
      f(adj_[static_cast<std::size_t>(k)], static_cast<std::size_t>(adj_edge_[static_cast<std::size_t>(k)]));
  }
  // the relative velocity along the spring that the rule keeps (the one that ends the step at `allowed`)
  Real target(Real rate) const { return rate; }
  bool in_contact(int i) const { return !s_->contacts.empty() && s_->contacts[static_cast<std::size_t>(i)].hit; }
  // hops from vertex i to the nearest held vertex over the springs and seam pairs (-1: out of reach of any)
  int level(int i) const { return order_level_[static_cast<std::size_t>(i)]; }
  void mark_changed(int i, Real change);
  // a sewn point is one point to the limit: a merged group's mass is its members', it is held in place when one
  // of them is attached, and a velocity change goes to every member (averaging them after each change would give
  // each spring at a seam only a share of its change, and leave it stretched where two pull apart)
  Real mass(int i) const {
    const int g = group_of_[static_cast<std::size_t>(i)];
    return g < 0 ? m_[i] : group_m_[static_cast<std::size_t>(g)];
  }
  // marks i held (with the rest of its group); false if it already was
  bool hold(int i) {
    if (held_[static_cast<std::size_t>(i)]) return false;
    const int g = group_of_[static_cast<std::size_t>(i)];
    if (g < 0)
      held_[static_cast<std::size_t>(i)] = 1;
    else
      for (int j : s_->merged[static_cast<std::size_t>(g)]) held_[static_cast<std::size_t>(j)] = 1;
    return true;
  }
  bool fixed(int i) const {
    const int g = group_of_[static_cast<std::size_t>(i)];
    return g < 0 ? inv_m_[i] == 0 : group_m_[static_cast<std::size_t>(g)] == 0;
  }

  // a point's position and velocity in the call under way
  Eigen::Map<const Vec3> x(int i) const { return Eigen::Map<const Vec3>(x_ + 3 * static_cast<std::ptrdiff_t>(i)); }
  Eigen::Map<Vec3> v(int i) const { return Eigen::Map<Vec3>(v_ + 3 * static_cast<std::ptrdiff_t>(i)); }

  LimiterParams params_;
  LimitState* s_ = nullptr;  // the call under way
  // its arrays, read in every spring's step: positions, velocities (3 x nv), masses, inverse masses (nv), the step
  const Real* x_ = nullptr;
  Real* v_ = nullptr;
  const Real* m_ = nullptr;
  const Real* inv_m_ = nullptr;
  Real dt_ = 0;
  std::vector<std::uint8_t> held_;  // per vertex: attached or in contact (and, directional, following one)

 private:
  void build_adjacency();
  void order_springs_from_held();
  void limit_spring(const SweptSpring& e);
  void stop_inward_contacts();
  Real face_inverse_mass(Eigen::Index q) const;
  void set_visit_bits(int i, std::size_t after);
  void group_sewn_points();
  void change(int i, const Vec3& dv, Real size);  // v += dv for i and the rest of its group

  std::vector<int> adj_start_, adj_;      // vertex -> neighbours over springs and seam pairs (CSR)
  std::vector<int> adj_edge_;             // beside adj_: its spring (index < springs) or seam pair (springs + index)
  std::vector<SweptSpring> sweep_;        // springs nearest held vertices first
  std::vector<std::uint8_t> order_held_;  // the held vertices sweep_ was computed for
  std::vector<int> order_level_, order_queue_, order_spring_level_;  // its work space (hops from held vertices)
  std::vector<int> changed_in_pass_;       // per vertex: the last pass (1-based) that changed its velocity
  std::vector<int> sweep_position_;        // per spring: its position in sweep_
  std::vector<std::uint64_t> visit_bits_;  // sweep positions the pass visits (after a pass that changed few points)
  Eigen::Index marked_ = 0;                // the points the pass under way changed (each once)
  bool visiting_bits_ = false;             // the pass visits visit_bits_ (else it scans every spring)
  std::size_t sweep_at_ = 0;               // the position in sweep_ under way (while visiting_bits_)
  int pass_ = 0;                           // the pass under way (0: none)
  long changes_ = 0;                       // velocity changes in that pass
  std::vector<int> group_of_;              // per vertex: its merged group (state.merged), or -1
  std::vector<Real> group_m_;              // per group: its members' mass (0: one of them is attached)
};

template <class Derived>
void VelocitySweep<Derived>::begin(LimitState& state) {
  s_ = &state;
  x_ = state.x.data(), v_ = state.v.data(), m_ = state.m.data(), inv_m_ = state.inv_m.data(), dt_ = state.dt;
  const Eigen::Index nv = state.x.cols();
  if (adj_start_.empty()) build_adjacency();
  held_.resize(static_cast<std::size_t>(nv));
  const Contact* contacts = state.contacts.empty() ? nullptr : state.contacts.data();
  std::uint8_t* held = held_.data();
  for (Eigen::Index i = 0; i < nv; ++i) held[i] = inv_m_[i] == 0 || (contacts && contacts[i].hit);
  // with face queries the corners of a quad whose midpoint is in contact are held by the body as well
  for (std::size_t c = static_cast<std::size_t>(nv); c < state.contacts.size(); ++c)
    if (contacts[c].hit)
      for (int k = 0; k < 4; ++k) held[state.mesh.quads(k, static_cast<Eigen::Index>(c) - nv)] = 1;
  group_sewn_points();
}

template <class Derived>
void VelocitySweep<Derived>::group_sewn_points() {
  const auto& groups = s_->merged;
  group_of_.assign(static_cast<std::size_t>(s_->x.cols()), -1);
  group_m_.assign(groups.size(), 0);
  for (std::size_t g = 0; g < groups.size(); ++g) {
    bool attached = false, held = false;
    for (int i : groups[g]) {
      group_of_[static_cast<std::size_t>(i)] = static_cast<int>(g);
      group_m_[g] += m_[i];
      attached = attached || inv_m_[i] == 0;
      held = held || held_[static_cast<std::size_t>(i)];
    }
    if (attached) group_m_[g] = 0;
    if (held)  // the body holds the sewn point where it holds one of its members
      for (int i : groups[g]) held_[static_cast<std::size_t>(i)] = 1;
  }
  // the members start with one velocity (the group's)
  move_as_one(groups, s_->m, s_->inv_m, s_->v, nullptr, [](int, Real) {});
}

template <class Derived>
void VelocitySweep<Derived>::change(int i, const Vec3& dv, Real size) {
  const int g = group_of_[static_cast<std::size_t>(i)];
  if (g < 0) {
    v(i) += dv, mark_changed(i, size);
    return;
  }
  for (int j : s_->merged[static_cast<std::size_t>(g)]) v(j) += dv, mark_changed(j, size);
}

template <class Derived>
void VelocitySweep<Derived>::passes(bool contacts_hold) {
  LimitState& state = *s_;
  const Eigen::Index nv = state.x.cols();
  order_springs_from_held();
  // a pass visits only the springs with an end whose velocity changed in the last pass or in this one (the
  // others would find what they found before), and the passes stop once one changes nothing. After a pass that
  // changed few points, the springs to visit are bits by sweep position, set from the points changed (mark_changed
  // sets those after the spring under way as they change); after one that changed many, a scan of all springs
  changed_in_pass_.assign(static_cast<std::size_t>(nv), 0);
  const std::size_t words = (sweep_.size() + 63) / 64;
  bool scan = true;  // the first pass visits every spring
  const auto changed = [&](int i, Real change) { mark_changed(i, change); };
  for (pass_ = 1; pass_ <= params_.passes; ++pass_) {
    changes_ = 0;
    marked_ = 0;
    visiting_bits_ = !scan;
    if (scan) {
      const int* last_changed = changed_in_pass_.data();
      const int since = pass_ - 1;
      const auto was_changed = [&](int v) { return last_changed[v] >= since; };
      for (const SweptSpring& e : sweep_)
        if (since == 0 || was_changed(e.a) || was_changed(e.b)) limit_spring(e);
    } else {
      for (std::size_t w = 0; w < words; ++w)
        while (const std::uint64_t bits = visit_bits_[w]) {
          visit_bits_[w] = bits & (bits - 1);  // mark_changed sets only bits after this one
          sweep_at_ = 64 * w + static_cast<std::size_t>(__builtin_ctzll(bits));
          limit_spring(sweep_[sweep_at_]);
        }
    }
    visiting_bits_ = false;
    move_as_one(state.merged, state.m, state.inv_m, state.v, nullptr, changed);  // a sewn point is one point
    if (contacts_hold) stop_inward_contacts();
    ++passes_;
    if (changes_ == 0) break;
    // the next pass: a scan when an eighth of the points or more changed (cheaper than setting their springs' bits)
    scan = 8 * marked_ > nv;
    if (scan) continue;
    visit_bits_.assign(words, 0);
    for (Eigen::Index i = 0; i < nv; ++i)
      if (changed_in_pass_[static_cast<std::size_t>(i)] == pass_) set_visit_bits(static_cast<int>(i), 0);
  }
  pass_ = 0;
  s_ = nullptr;
}

template <class Derived>
void VelocitySweep<Derived>::build_adjacency() {
  // every spring and seam pair, both ways, as compressed rows
  const ClothMesh& mesh = s_->mesh;
  const Eigen::Index nv = mesh.positions.cols();
  std::vector<std::pair<int, int>> edges;
  for (Eigen::Index s = 0; s < mesh.springs.cols(); ++s) edges.emplace_back(mesh.springs(0, s), mesh.springs(1, s));
  for (Eigen::Index p = 0; p < mesh.seam_pairs.cols(); ++p)
    edges.emplace_back(mesh.seam_pairs(0, p), mesh.seam_pairs(1, p));
  adj_start_.assign(static_cast<std::size_t>(nv + 1), 0);
  for (const auto& [a, b] : edges)
    ++adj_start_[static_cast<std::size_t>(a + 1)], ++adj_start_[static_cast<std::size_t>(b + 1)];
  for (std::size_t i = 1; i < adj_start_.size(); ++i) adj_start_[i] += adj_start_[i - 1];
  adj_.resize(static_cast<std::size_t>(adj_start_.back()));
  adj_edge_.resize(adj_.size());
  std::vector<int> fill(adj_start_.begin(), adj_start_.end() - 1);
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const auto [a, b] = edges[e];
    const auto at_a = static_cast<std::size_t>(fill[static_cast<std::size_t>(a)]++);
    const auto at_b = static_cast<std::size_t>(fill[static_cast<std::size_t>(b)]++);
    adj_[at_a] = b, adj_[at_b] = a;
    adj_edge_[at_a] = adj_edge_[at_b] = static_cast<int>(e);
  }
}

template <class Derived>
void VelocitySweep<Derived>::set_visit_bits(int i, std::size_t after) {
  for (int k = adj_start_[static_cast<std::size_t>(i)]; k < adj_start_[static_cast<std::size_t>(i) + 1]; ++k) {
    const auto e = static_cast<std::size_t>(adj_edge_[static_cast<std::size_t>(k)]);
    if (e >= sweep_position_.size()) continue;  // a seam pair
    const auto s = static_cast<std::size_t>(sweep_position_[e]);
    if (s >= after) visit_bits_[s / 64] |= std::uint64_t(1) << (s % 64);
  }
}

template <class Derived>
void VelocitySweep<Derived>::mark_changed(int i, Real change) {
  // a velocity change that moves the point less than the tolerance over the step wakes no spring: the passes
  // converge to within it instead of chasing rounding-sized changes around the cloth
  if (pass_ == 0 || !(change * dt_ > params_.tolerance)) return;
  ++changes_;
  // its springs after the one under way are visited in this pass (bits only: a scan finds them), all of them in
  // the next (once per pass is enough: the bits a first change set after it are still set)
  int& last = changed_in_pass_[static_cast<std::size_t>(i)];
  if (last == pass_) return;
  last = pass_;
  ++marked_;
  if (visiting_bits_) set_visit_bits(i, sweep_at_ + 1);
}

template <class Derived>
void VelocitySweep<Derived>::order_springs_from_held() {
  // a Gauss-Seidel sweep converges in one pass along a chain swept from its support: springs in order of
  // their nearer end's hops from a held vertex (breadth first; springs out of reach of any keep their order last)
  // the order depends only on which vertices are held: kept while that set stays (the second call of a step,
  // a cloth resting on the body)
  const ClothMesh& mesh = s_->mesh;
  if (held_ == order_held_ && sweep_.size() == static_cast<std::size_t>(mesh.springs.cols())) return;
  order_held_ = held_;
  const std::size_t nv = held_.size(), ns = static_cast<std::size_t>(mesh.springs.cols());
  auto& level = order_level_;
  auto& queue = order_queue_;
  level.assign(nv, -1);
  queue.clear();
  for (std::size_t i = 0; i < nv; ++i)
    if (held_[i]) level[i] = 0, queue.push_back(static_cast<int>(i));
  for (std::size_t q = 0; q < queue.size(); ++q) {
    const auto i = static_cast<std::size_t>(queue[q]);
    for (int k = adj_start_[i]; k < adj_start_[i + 1]; ++k) {
      const int j = adj_[static_cast<std::size_t>(k)];
      if (level[static_cast<std::size_t>(j)] < 0) level[static_cast<std::size_t>(j)] = level[i] + 1, queue.push_back(j);
    }
  }
  // a spring's level: its nearer end's (a spring out of reach of every held vertex goes last)
  const int unreached = queue.empty() ? 0 : level[static_cast<std::size_t>(queue.back())] + 1;
  auto& spring_level = order_spring_level_;
  spring_level.resize(ns);
  std::vector<int> count(static_cast<std::size_t>(unreached) + 2, 0);
  for (std::size_t s = 0; s < ns; ++s) {
    const int a = level[static_cast<std::size_t>(mesh.springs(0, s))],
              b = level[static_cast<std::size_t>(mesh.springs(1, s))];
    spring_level[s] = a < 0 || b < 0 ? unreached : std::min(a, b);
    ++count[static_cast<std::size_t>(spring_level[s]) + 1];
  }
  for (std::size_t i = 1; i < count.size(); ++i) count[i] += count[i - 1];
  // packed in sweep order: the passes read them one after the other
  const Real max_len_factor = 1 + params_.threshold;
  sweep_.resize(ns);
  sweep_position_.resize(ns);
  for (std::size_t s = 0; s < ns; ++s) {
    const auto i = static_cast<Eigen::Index>(s);
    const int at = count[static_cast<std::size_t>(spring_level[s])]++;
    sweep_position_[s] = at;
    sweep_[static_cast<std::size_t>(at)] = {mesh.springs(0, i), mesh.springs(1, i),
                                            max_len_factor * mesh.rest_length[i]};
  }
}

template <class Derived>
void VelocitySweep<Derived>::stop_inward_contacts() {
  // a vertex in contact may slide along the body or leave it, never move into it relative to it
  Points3& v = s_->v;
  for (Eigen::Index i = 0; i < v.cols(); ++i) {
    const Contact& c = s_->contacts[static_cast<std::size_t>(i)];
    if (!c.hit || s_->inv_m[i] == 0) continue;
    const Real stopped = stop_into_body(v.col(i), c);
    if (stopped > 0) mark_changed(static_cast<int>(i), stopped);
  }
  // with face queries, a quad whose midpoint is in contact (contacts[nv + quad], dressing section 6) likewise: the
  // impulse that stops its midpoint's motion into the body, a quarter to each corner
  const ClothMesh& mesh = s_->mesh;
  for (std::size_t c = static_cast<std::size_t>(v.cols()); c < s_->contacts.size(); ++c) {
    const Contact& contact = s_->contacts[c];
    const auto q = static_cast<Eigen::Index>(c) - v.cols();
    if (!contact.hit) continue;
    Vec3 mid = Vec3::Zero();
    for (int k = 0; k < 4; ++k) mid += Real(0.25) * v.col(mesh.quads(k, q));
    const Real vn = (mid - contact.body_velocity).dot(contact.normal), w = face_inverse_mass(q);
    if (!(vn < 0) || !(w > 0)) continue;
    for (int k = 0; k < 4; ++k) {
      const int i = mesh.quads(k, q);
      if (!fixed(i)) change(i, (Real(-0.25) * vn / (w * mass(i))) * contact.normal, Real(-0.25) * vn / (w * mass(i)));
    }
  }
}

template <class Derived>
Real VelocitySweep<Derived>::face_inverse_mass(Eigen::Index q) const {
  const auto point = [&](int i) {
    const int g = group_of_[static_cast<std::size_t>(i)];
    return g < 0 ? i : -1 - g;
  };
  return quad_midpoint_inverse_mass(s_->mesh.quads, q, point, [&](int i) { return fixed(i) ? 0 : 1 / mass(i); });
}

template <class Derived>
void VelocitySweep<Derived>::limit_spring(const SweptSpring& e) {
  const int a = e.a, b = e.b;
  // the length this step would give (Eq. 3 position update): no spring may end it over-elongated
  const Vec3 d = x(b) - x(a);  // p12 = p2 - p1
  const Vec3 dv = v(b) - v(a);
  const Real max_len = e.max_len;
  // split along the spring's line as it would end the step (the papers' line p1p2 when it does not turn):
  // keeping the relative velocity along it that ends the step at the allowed length is then the nearest
  // allowed motion, however fast the spring turns, so passes over all springs converge
  const Vec3 d_end = d + dt_ * dv;
  const Real len_end2 = d_end.squaredNorm();
  if (!(len_end2 > max_len * max_len)) return;  // most springs: no square root
  const Real len_end = std::sqrt(len_end2), len = d.norm();
  if (!(len > 0)) return;
  const Vec3 u = d_end / len_end;
  const Real va = v(a).dot(u), vb = v(b).dot(u);
  // a spring already past max_len (pinched between two moving body parts, dragged by the response,
  // stretched when a seam merged) keeps its length but for `speed` dt: shortening it by all of the
  // excess in one step takes excess/dt (12 mm at dt 0.16 ms is 80 m/s), a speed that outlives the step
  const Real allowed = stretch_rules::allowed_length(len, max_len, params_.speed * dt_);
  const Real target = static_cast<const Derived*>(this)->target((allowed - d.dot(u)) / dt_);
  if (vb - va <= target) return;  // only further elongation is forbidden: a spring may shorten
  const bool fixed_a = fixed(a), fixed_b = fixed(b);
  const int g = group_of_[static_cast<std::size_t>(a)];
  if ((fixed_a && fixed_b) || (g >= 0 && g == group_of_[static_cast<std::size_t>(b)])) return;
  auto [na, nb] = static_cast<Derived*>(this)->split(a, b, u, va, vb, target);
  // an attached end keeps its velocity and the free end follows it
  if (fixed_a) na = va, nb = va + target;
  if (fixed_b) nb = vb, na = vb - target;
  if (na != va) change(a, (na - va) * u, std::abs(na - va));
  if (nb != vb) change(b, (nb - vb) * u, std::abs(nb - vb));
}

}  // namespace clothbench
