// `projection`: fast projection (Goldenthal, Harmon, Fattal, Bercovier, Grinspun 2007, Algorithm 1) of the
// end-of-step positions p = x + dt v (dressing Eq. 3) onto the structural springs' limit. Each iteration linearises
// the active constraints C_k(p) = |p_b - p_a| - allowed_k and solves (J W J^T) dl = C (Goldenthal Eq. 8) with a
// sparse LDL^T factorisation, then p -= W J^T dl (W: inverse masses): a Newton step on the constraints, so a few
// iterations hold the whole cloth where a Gauss-Seidel sweep needs a pass per spring between the cloth's supports.
// The velocities become (p - x) / dt. Only structural springs are constrained: they are what the strain measures,
// a flexion spring is bounded by the two it spans (triangle inequality), and with the shear springs a stretched
// sheet would have more constraints than its points have freedoms (J W J^T singular).
// After the response (contacts_hold), a vertex in contact may not move into the body: one pressed onto it, or one
// the projection would move into it, moves along the surface only (W = w (I - n n^T)), and the iteration repeats.
// A sewn group of vertices is one point: its vertices keep their offsets and share one displacement.
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "../merged_points.hpp"
#include "limiters.hpp"

namespace clothbench {

namespace {

class Projection final : public Limiter {
 public:
  explicit Projection(const LimiterParams& params) : params_(params) {}
  std::unique_ptr<Limiter> clone() const override { return std::make_unique<Projection>(*this); }

  void limit_velocities(LimitState& s, bool contacts_hold) override {
    s_ = &s;
    points();
    if (structural_.empty()) return;
    for (std::size_t k = 0; k < structural_.size(); ++k) allowed_[k] = allowed(structural_[k]);
    move_as_one(s.merged, s.m, s.inv_m, s.v, nullptr, [](int, Real) {});  // the response moved them apart
    p_ = s.x + s.dt * s.v;
    const Points3 start = p_;
    if (contacts_hold) lock_pressed_contacts();
    for (int it = 0; it < params_.passes; ++it) {
      ++passes_;
      if (!find_active()) break;
      solve();
      if (contacts_hold) lock_inward_contacts();
    }
    s.v += (p_ - start) / s.dt;
    s_ = nullptr;
  }

 private:
  // a tenth of the accuracy limit's 1 % margin: the iterations stop once no spring is longer than it may be by more
  static constexpr Real kTolerance = 1e-3f;
  // Levenberg-Marquardt damping of the system's diagonal (relative): nearly dependent springs share a correction
  // instead of trading large opposite ones
  static constexpr double kDamping = 1e-2;

  // each vertex's point (the first vertex of its sewn group, or itself), each point's inverse mass (0 when any of
  // its vertices is attached), and the structural springs between two points, one of them free
  void points() {
    const LimitState& s = *s_;
    const Eigen::Index nv = s.x.cols();
    rep_.resize(static_cast<std::size_t>(nv));
    for (Eigen::Index i = 0; i < nv; ++i) rep_[static_cast<std::size_t>(i)] = static_cast<int>(i);
    for (const auto& g : s.merged)
      for (int i : g) rep_[static_cast<std::size_t>(i)] = *std::min_element(g.begin(), g.end());
    std::vector<double> mass(static_cast<std::size_t>(nv), 0.0);
    std::vector<std::uint8_t> attached(static_cast<std::size_t>(nv), 0);
    for (Eigen::Index i = 0; i < nv; ++i) {
      const auto r = static_cast<std::size_t>(rep_[static_cast<std::size_t>(i)]);
      mass[r] += s.m[i];
      attached[r] |= s.inv_m[i] == 0;
    }
    w_.assign(static_cast<std::size_t>(nv), 0.0);
    for (std::size_t i = 0; i < w_.size(); ++i)
      if (mass[i] > 0 && !attached[i]) w_[i] = 1.0 / mass[i];
    const ClothMesh& mesh = s.mesh;
    structural_.clear();
    for (Eigen::Index k = 0; k < mesh.springs.cols(); ++k) {
      const int va = mesh.springs(0, k), vb = mesh.springs(1, k);
      const int a = rep_[static_cast<std::size_t>(va)], b = rep_[static_cast<std::size_t>(vb)];
      if (mesh.kind[static_cast<std::size_t>(k)] == SpringKind::kStructural && a != b &&
          (w_[static_cast<std::size_t>(a)] > 0 || w_[static_cast<std::size_t>(b)] > 0))
        structural_.push_back({va, vb, a, b, static_cast<int>(k)});
    }
    allowed_.resize(structural_.size());
    locked_.assign(static_cast<std::size_t>(nv), 0);
  }

  struct Spring {
    int va, vb;  // its vertices
    int a, b;    // their points
    int index;   // in the mesh
  };

  // the length a spring may end the step with: (1 + threshold) l0, or, one already longer, its length shortened by
  // `speed` dt at most (as the velocity sweeps do: all of the excess in one step would be a speed that outlives it)
  Real allowed(const Spring& e) const {
    const Real max_len = (1 + params_.threshold) * s_->mesh.rest_length[e.index];
    const Real len = (s_->x.col(e.vb) - s_->x.col(e.va)).norm();
    return std::max(max_len, len) - std::max(std::min(len - max_len, params_.speed * s_->dt), Real(0));
  }

  // the springs at or within the tolerance of their allowed length, with their directions and violations; false
  // when none is longer than it may be by more than the tolerance
  bool find_active() {
    active_.clear();
    bool over = false;
    for (std::size_t k = 0; k < structural_.size(); ++k) {
      const Spring& e = structural_[k];
      const Real tol = kTolerance * s_->mesh.rest_length[e.index];
      const Real len = (p_.col(e.vb) - p_.col(e.va)).norm();
      if (len < allowed_[k] - tol || !(len > 0)) continue;
      over |= len > allowed_[k] + tol;
      active_.push_back(static_cast<int>(k));
    }
    return over;
  }

  // what point i's inverse mass does to direction d: w d, or w (I - n n^T) d for a contact held on the surface
  Vec3 weigh(int i, const Vec3& d) const {
    const double w = w_[static_cast<std::size_t>(i)];
    if (!locked_[static_cast<std::size_t>(i)]) return Real(w) * d;
    const Vec3& n = s_->contacts[static_cast<std::size_t>(i)].normal;
    return Real(w) * (d - n.dot(d) * n);
  }

  // one Newton step: (J W J^T) dl = C over the active springs, p -= W J^T dl
  void solve() {
    const std::size_t na = active_.size();
    u_.resize(na);
    Eigen::VectorXd c(static_cast<Eigen::Index>(na));
    incident_.assign(p_.cols(), {});
    for (std::size_t r = 0; r < na; ++r) {
      const Spring& e = structural_[static_cast<std::size_t>(active_[r])];
      const Vec3 d = p_.col(e.vb) - p_.col(e.va);
      const Real len = d.norm();
      u_[r] = d / len;
      c[static_cast<Eigen::Index>(r)] = double(len) - double(allowed_[static_cast<std::size_t>(active_[r])]);
      incident_[static_cast<std::size_t>(e.a)].push_back({static_cast<int>(r), -1});
      incident_[static_cast<std::size_t>(e.b)].push_back({static_cast<int>(r), +1});
    }
    // (J W J^T)_kl = sum over the points i the springs k and l share of s_ki s_li u_k^T W_i u_l (s = -1 at a spring's
    // first end, +1 at its second)
    triplets_.clear();
    for (Eigen::Index i = 0; i < p_.cols(); ++i)
      for (const Incidence& k : incident_[static_cast<std::size_t>(i)]) {
        const Vec3 wu = weigh(static_cast<int>(i), u_[static_cast<std::size_t>(k.row)]);
        for (const Incidence& l : incident_[static_cast<std::size_t>(i)])
          triplets_.emplace_back(k.row, l.row, double(k.sign * l.sign) * double(wu.dot(u_[static_cast<std::size_t>(l.row)])));
      }
    // a spring neither of whose ends can move along it keeps its length: a unit diagonal and no violation
    Eigen::SparseMatrix<double> a(static_cast<Eigen::Index>(na), static_cast<Eigen::Index>(na));
    a.setFromTriplets(triplets_.begin(), triplets_.end());
    const double tiny = 1e-12 * *std::max_element(w_.begin(), w_.end());
    for (Eigen::Index r = 0; r < a.rows(); ++r) {
      double& d = a.coeffRef(r, r);
      if (d <= tiny) d = 1, c[r] = 0;
      d *= 1 + kDamping;
    }
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(a);
    if (ldlt.info() != Eigen::Success) return;
    const Eigen::VectorXd dl = ldlt.solve(c);
    if (!dl.allFinite()) return;
    dp_.setZero(3, p_.cols());
    for (std::size_t r = 0; r < na; ++r) {
      const Spring& e = structural_[static_cast<std::size_t>(active_[r])];
      const Real l = Real(dl[static_cast<Eigen::Index>(r)]);
      dp_.col(e.a) += weigh(e.a, l * u_[r]);
      dp_.col(e.b) -= weigh(e.b, l * u_[r]);
    }
    // a point (each of its vertices) moves no farther than the largest violation: where the linearisation is poor (a contact that may only
    // slide, a spring across the motion it allows) the step would otherwise be as large as its pivot is small
    const Real most = Real(c.cwiseAbs().maxCoeff());
    for (Eigen::Index i = 0; i < p_.cols(); ++i) {
      const Eigen::Index r = rep_[static_cast<std::size_t>(i)];
      const Real n = dp_.col(r).norm();
      p_.col(i) += (n > most ? most / n : Real(1)) * dp_.col(r);
    }
  }

  // the points in contact that the body presses (relative velocity into it or along it) move along it only
  void lock_pressed_contacts() {
    for (std::size_t i = 0; i < locked_.size(); ++i) {
      if (rep_[i] != static_cast<int>(i) || w_[i] == 0 || s_->contacts.empty() || !s_->contacts[i].hit) continue;
      const Contact& c = s_->contacts[i];
      const Real vn = (s_->v.col(static_cast<Eigen::Index>(i)) - c.body_velocity).dot(c.normal);
      locked_[i] = vn <= 0;
    }
  }

  // a point in contact that the step moved into the body: back onto its motion along it, and held there
  void lock_inward_contacts() {
    const Real dt = s_->dt;
    dp_.setZero(3, p_.cols());
    for (std::size_t i = 0; i < locked_.size(); ++i) {
      if (locked_[i] || rep_[i] != static_cast<int>(i) || w_[i] == 0 || !s_->contacts[i].hit) continue;
      const Contact& c = s_->contacts[i];
      const auto col = static_cast<Eigen::Index>(i);
      const Real into = (p_.col(col) - s_->x.col(col) - dt * c.body_velocity).dot(c.normal);
      if (into < 0) dp_.col(col) = -into * c.normal, locked_[i] = 1;
    }
    for (Eigen::Index i = 0; i < p_.cols(); ++i) p_.col(i) += dp_.col(rep_[static_cast<std::size_t>(i)]);
  }

  struct Incidence {
    int row;   // the active spring
    int sign;  // -1 at its first end, +1 at its second
  };

  LimiterParams params_;
  LimitState* s_ = nullptr;
  std::vector<int> rep_;                 // per vertex: its point
  std::vector<double> w_;                // per point: its inverse mass (0: attached)
  std::vector<std::uint8_t> locked_;     // per point: a contact held on the body's surface
  std::vector<Spring> structural_;       // the structural springs between two points, one free
  std::vector<Real> allowed_;            // beside structural_: the length each may end the step with
  std::vector<int> active_;              // the iteration's active springs (indices into structural_)
  std::vector<Vec3> u_;                  // beside active_: their directions at p
  std::vector<std::vector<Incidence>> incident_;  // per point: its active springs
  std::vector<Eigen::Triplet<double>> triplets_;
  Points3 dp_;                           // an iteration's moves
  Points3 p_;                            // the end-of-step positions being projected
};

}  // namespace

std::unique_ptr<Limiter> make_projection_limit(const LimiterParams& params) {
  return std::make_unique<Projection>(params);
}

}  // namespace clothbench
