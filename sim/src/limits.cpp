// Super-elasticity limits (dressing section 4, walking section 3): velocity, directional and
// position (Provot) corrections of over-stretched springs.
// Our reading of the velocity limits: a spring whose next length (Eq. 3) would pass (1 + threshold) l0
// keeps the relative velocity along its end-of-step line that ends the step at exactly that length; one
// already past it is shortened at limit_speed at most. A pass sweeps the springs from the held vertices out. Directional: springs
// perpendicular to v_dir average (Eq. 5); on the others the rear point catches up with the front one,
// except that a held rear point (attached, in contact, or already following one) makes the front follow
// it, and catching up that would add kinetic energy to the pair averages instead; directional-literal keeps the
// rules as stated (walking Eq. 6 and the two rules after it).
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <tuple>

#include "clothbench/sim/simulator.hpp"

namespace clothbench {

const char* to_string(Limit limit) {
  switch (limit) {
    case Limit::kNone: return "none";
    case Limit::kStiff: return "stiff";
    case Limit::kPosition: return "position";
    case Limit::kVelocity: return "velocity";
    case Limit::kVelocityZero: return "velocity-zero";
    case Limit::kDirectional: return "directional";
    case Limit::kDirectionalLiteral: return "directional-literal";
  }
  return "?";
}

Limit parse_limit(const std::string& name) {
  for (Limit l : {Limit::kNone, Limit::kStiff, Limit::kPosition, Limit::kVelocity, Limit::kVelocityZero,
                  Limit::kDirectional, Limit::kDirectionalLiteral})
    if (name == to_string(l)) return l;
  throw std::invalid_argument("limit: unknown method '" + name +
                              "' (none, stiff, position, velocity, velocity-zero, directional, directional-literal)");
}

namespace {

// limit_stretch_velocity's rules, inlined into the velocity limit's per-spring step
inline std::pair<Real, Real> stretch_velocity(Limit limit, Real va, Real vb, Real cos_alpha, Real wa, Real wb,
                                              Real target) {
  // walking Eq. 5 averages, keeping the relative velocity `target`; with unequal masses the mass-weighted
  // mean keeps momentum (the papers' points all have one mass, where both are the same)
  const Real mean = (wa * va + wb * vb) / (wa + wb);
  const std::pair<Real, Real> average{mean - target * wb / (wa + wb), mean + target * wa / (wa + wb)};
  switch (limit) {
    case Limit::kVelocityZero: return {0, 0};  // dressing 4.3
    case Limit::kVelocity: return average;     // walking Eq. 5
    case Limit::kDirectional:
    case Limit::kDirectionalLiteral: {
      // walking Eq. 6 rules: perpendicular springs average, others: the rear point catches up with the front
      if (std::abs(cos_alpha) < 0.3f) return average;
      const std::pair<Real, Real> catch_up =
          cos_alpha > 0 ? std::pair<Real, Real>{vb - target, vb} : std::pair<Real, Real>{va, va + target};
      if (limit == Limit::kDirectionalLiteral) return catch_up;
      // our guard: catching up must not add kinetic energy to the pair (it does not keep momentum, and
      // taken literally it diverges on a cloth draped over a sphere); where it would, Eq. 5 instead
      const auto energy = [&](Real a, Real b) { return wa * a * a + wb * b * b; };
      return energy(catch_up.first, catch_up.second) > energy(va, vb) ? average : catch_up;
    }
    default: return {va, vb};
  }
}

}  // namespace

std::pair<Real, Real> limit_stretch_velocity(Limit limit, Real va, Real vb, Real cos_alpha, Real wa, Real wb,
                                             Real target) {
  return stretch_velocity(limit, va, vb, cos_alpha, wa, wb, target);
}

void Simulator::limit_velocities(bool contacts_stop_inward) {
  const Limit l = params_.limit;
  if (l != Limit::kVelocity && l != Limit::kVelocityZero && l != Limit::kDirectional &&
      l != Limit::kDirectionalLiteral)
    return;
  const Vec3 v_grav = phase_gravity() * dt_;  // walking Eq. 6: v_grav = g dt (zero while sewing: no gravity acts)
  // held points cannot catch up: attached ones and those the body holds (in contact)
  held_.assign(static_cast<std::size_t>(x_.cols()), 0);
  for (Eigen::Index i = 0; i < x_.cols(); ++i)
    held_[i] = inv_m_[i] == 0 || (!contacts_.empty() && contacts_[static_cast<std::size_t>(i)].hit);
  order_springs_from_held();
  // a pass visits only the springs with an end whose velocity changed in the last pass or in this one (the
  // others would find what they found before), and the passes stop once one changes nothing. After a pass that
  // changed few points, the springs to visit are bits by sweep position, set from the points changed (mark_changed
  // sets those after the spring under way as they change); after one that changed many, a scan of all springs
  changed_in_pass_.assign(static_cast<std::size_t>(x_.cols()), 0);
  const std::size_t words = (sweep_.size() + 63) / 64;
  bool scan = true;  // the first pass visits every spring
  for (pass_ = 1; pass_ <= params_.limit_passes; ++pass_) {
    changes_ = 0;
    marked_ = 0;
    visiting_bits_ = !scan;
    if (scan) {
      const auto was_changed = [&](int v) { return changed_in_pass_[static_cast<std::size_t>(v)] >= pass_ - 1; };
      for (const SweptSpring& e : sweep_)
        if (pass_ == 1 || was_changed(e.a) || was_changed(e.b)) limit_spring(l, v_grav, e);
    } else {
      for (std::size_t w = 0; w < words; ++w)
        while (const std::uint64_t bits = visit_bits_[w]) {
          visit_bits_[w] = bits & (bits - 1);  // mark_changed sets only bits after this one
          sweep_at_ = 64 * w + static_cast<std::size_t>(__builtin_ctzll(bits));
          limit_spring(l, v_grav, sweep_[sweep_at_]);
        }
    }
    visiting_bits_ = false;
    move_merged_as_one(false);  // a sewn point is one point to the limit too
    if (contacts_stop_inward) stop_inward_contacts();
    ++timings_.limit_passes;
    if (changes_ == 0) break;
    // the next pass: a scan when an eighth of the points or more changed (cheaper than setting their springs' bits)
    scan = 8 * marked_ > x_.cols();
    if (scan) continue;
    visit_bits_.assign(words, 0);
    for (Eigen::Index i = 0; i < x_.cols(); ++i)
      if (changed_in_pass_[static_cast<std::size_t>(i)] == pass_) set_visit_bits(static_cast<int>(i), 0);
  }
  pass_ = 0;
}

void Simulator::set_visit_bits(int i, std::size_t after) {
  for (int k = adj_start_[static_cast<std::size_t>(i)]; k < adj_start_[static_cast<std::size_t>(i) + 1]; ++k) {
    const auto e = static_cast<std::size_t>(adj_edge_[static_cast<std::size_t>(k)]);
    if (e >= sweep_position_.size()) continue;  // a seam pair
    const auto s = static_cast<std::size_t>(sweep_position_[e]);
    if (s >= after) visit_bits_[s / 64] |= std::uint64_t(1) << (s % 64);
  }
}

void Simulator::mark_changed(int i, Real change) {
  // a velocity change that moves the point less than limit_tolerance over the step wakes no spring: the passes
  // converge to within it instead of chasing rounding-sized changes around the cloth
  if (pass_ == 0 || !(change * dt_ > params_.limit_tolerance)) return;
  ++changes_;
  // its springs after the one under way are visited in this pass (bits only: a scan finds them), all of them in
  // the next (once per pass is enough: the bits a first change set after it are still set)
  int& last = changed_in_pass_[static_cast<std::size_t>(i)];
  if (last == pass_) return;
  last = pass_;
  ++marked_;
  if (visiting_bits_) set_visit_bits(i, sweep_at_ + 1);
}

void Simulator::order_springs_from_held() {
  // a Gauss-Seidel sweep converges in one pass along a chain swept from its support: springs in order of
  // their nearer end's hops from a held vertex (breadth first; springs out of reach of any keep their order last)
  // the order depends only on which vertices are held: kept while that set stays (the second call of a step,
  // a cloth resting on the body)
  if (held_ == order_held_ && sweep_.size() == static_cast<std::size_t>(mesh_.springs.cols())) return;
  order_held_ = held_;
  const std::size_t nv = held_.size(), ns = static_cast<std::size_t>(mesh_.springs.cols());
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
    const int a = level[static_cast<std::size_t>(mesh_.springs(0, s))], b = level[static_cast<std::size_t>(mesh_.springs(1, s))];
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
    sweep_[static_cast<std::size_t>(at)] = {mesh_.springs(0, i), mesh_.springs(1, i),
                                            max_len_factor * mesh_.rest_length[i]};
  }
}

void Simulator::stop_inward_contacts() {
  // a vertex in contact may slide along the body or leave it, never move into it relative to it
  for (Eigen::Index i = 0; i < x_.cols(); ++i) {
    const Contact& c = contacts_[static_cast<std::size_t>(i)];
    if (!c.hit || inv_m_[i] == 0) continue;
    const Real vn = (v_.col(i) - c.body_velocity).dot(c.normal);
    if (vn < 0) v_.col(i) -= vn * c.normal, mark_changed(static_cast<int>(i), -vn);
  }
}

void Simulator::limit_spring(Limit l, const Vec3& v_grav, const SweptSpring& e) {
  const int a = e.a, b = e.b;
  // the length this step would give (Eq. 3 position update): no spring may end it over-elongated
  const Vec3 d = x_.col(b) - x_.col(a);  // p12 = p2 - p1
  const Vec3 dv = v_.col(b) - v_.col(a);
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
  const Real va = v_.col(a).dot(u), vb = v_.col(b).dot(u);
  // a spring already past max_len (pinched between two moving body parts, dragged by the response,
  // stretched when a seam merged) keeps its length but for limit_speed dt: shortening it by all of the
  // excess in one step takes excess/dt (12 mm at dt 0.16 ms is 80 m/s), a speed that outlives the step
  const Real allowed = std::max(max_len, len) - std::max(std::min(len - max_len, params_.limit_speed * dt_), Real(0));
  const Real target = l == Limit::kVelocityZero ? Real(0) : (allowed - d.dot(u)) / dt_;
  if (vb - va <= target) return;  // only further elongation is forbidden: a spring may shorten
  if (inv_m_[a] == 0 && inv_m_[b] == 0) return;
  Real na = va, nb = vb;
  if (l == Limit::kDirectional || l == Limit::kDirectionalLiteral) {
    // walking Eq. 6: v_dir = v_grav + v_object; the rules after it pick averaging or the rear point
    const Vec3 v_dir = v_grav + spring_object_velocity(a, b);
    const Real cos_a = v_dir.norm() > 0 ? u.dot(v_dir.normalized()) : Real(0);
    const int rear = cos_a > 0 ? a : b;
    if (l == Limit::kDirectional && std::abs(cos_a) >= 0.3f && held_[static_cast<std::size_t>(rear)]) {
      // a held rear point cannot catch up: the front follows it and is held in turn (our reading)
      na = rear == a ? va : vb - target;
      nb = na + target;
      const int front = rear == a ? b : a;
      if (!held_[static_cast<std::size_t>(front)])
        held_[static_cast<std::size_t>(front)] = 1, mark_changed(front, std::numeric_limits<Real>::infinity());
    } else {
      std::tie(na, nb) = stretch_velocity(l, va, vb, cos_a, m_[a], m_[b], target);
    }
  } else {
    std::tie(na, nb) = stretch_velocity(l, va, vb, 0, m_[a], m_[b], target);
  }
  // an attached end keeps its velocity and the free end follows it
  if (inv_m_[a] == 0) na = va, nb = va + target;
  if (inv_m_[b] == 0) nb = vb, na = vb - target;
  if (na != va) v_.col(a) += (na - va) * u, mark_changed(a, std::abs(na - va));
  if (nb != vb) v_.col(b) += (nb - vb) * u, mark_changed(b, std::abs(nb - vb));
}

Vec3 Simulator::spring_object_velocity(int a, int b) const {
  // the velocity of the object the spring's ends collide with (zero when neither does)
  const Contact& ca = contacts_[static_cast<std::size_t>(a)];
  const Contact& cb = contacts_[static_cast<std::size_t>(b)];
  if (ca.hit && cb.hit) return 0.5f * (ca.body_velocity + cb.body_velocity);
  if (ca.hit) return ca.body_velocity;
  if (cb.hit) return cb.body_velocity;
  return Vec3::Zero();
}

void Simulator::limit_positions() {
  if (params_.limit != Limit::kPosition) return;
  // Provot 1995: move the ends of springs stretched past (1 + threshold) l0 back to that length
  const Real max_len_factor = 1 + params_.threshold;
  for (int pass = 0; pass < params_.limit_passes; ++pass)
    for (Eigen::Index s = 0; s < mesh_.springs.cols(); ++s) {
      const int a = mesh_.springs(0, s), b = mesh_.springs(1, s);
      const Vec3 d = x_.col(b) - x_.col(a);
      const Real len = d.norm(), max_len = max_len_factor * mesh_.rest_length[s];
      const Real wa = inv_m_[a] > 0 ? Real(1) : Real(0), wb = inv_m_[b] > 0 ? Real(1) : Real(0);
      if (!(len > max_len) || wa + wb == 0) continue;
      // the velocities follow the moved positions, so Eq. 3 does not push them out again
      const Vec3 corr = (len - max_len) / len * d / (wa + wb);
      x_.col(a) += wa * corr;
      x_.col(b) -= wb * corr;
      v_.col(a) += (wa / dt_) * corr;
      v_.col(b) -= (wb / dt_) * corr;
    }
}

}  // namespace clothbench
