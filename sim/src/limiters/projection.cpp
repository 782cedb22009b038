// `projection`: fast projection (Goldenthal, Harmon, Fattal, Bercovier, Grinspun 2007, Algorithm 1) of the
// end-of-step positions p = x + dt v (dressing Eq. 3) onto the structural springs' limit. Each iteration linearises
// the active constraints C_k(p) = |p_b - p_a| - allowed_k and solves (J W J^T) dl = C (Goldenthal Eq. 8) with a
// sparse LDL^T factorisation, then p -= W J^T dl (W: inverse masses): a Newton step on the constraints, so a few
// iterations hold the whole cloth where a Gauss-Seidel sweep needs a pass per spring between the cloth's supports.
// The velocities become (p - x) / dt. Only structural springs are constrained: they are what the strain measures,
// a flexion spring is bounded by the two it spans (triangle inequality), and with the shear springs a stretched
// sheet would have more constraints than its points have freedoms (J W J^T singular).
// After the response (contacts_hold), a point in contact may not end the step deeper than the body's motion takes
// its surface: C_c(p) = n . (p - x - dt v_body) >= 0, a row of the same system while the projection would move it
// inward, dropped once it would hold the point down (the body pushes, never pulls).
// A sewn group of vertices is one point: its vertices keep their offsets and share one displacement.
#include <Eigen/OrderingMethods>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "../merged_points.hpp"
#include "limiters.hpp"
#include "stretch_rules.hpp"

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
    order_springs();
    for (std::size_t k = 0; k < structural_.size(); ++k) allowed_[k] = allowed(structural_[k]);
    move_as_one(s.merged, s.m, s.inv_m, s.v, nullptr, [](int, Real) {});  // the response moved them apart
    p_ = s.x + s.dt * s.v;
    const Points3 start = p_;
    released_.assign(w_.size(), 0);
    for (int it = 0; it < params_.passes; ++it) {
      ++passes_;
      if (!find_active(contacts_hold)) break;
      solve();
    }
    s.v += (p_ - start) / s.dt;
    s_ = nullptr;
  }

 private:
  // a tenth of the accuracy limit's 1 % margin: the iterations stop once no spring is longer than it may be by more
  static constexpr Real kTolerance = 1e-3f;
  // how far a point may end inside the body's moved surface before its contact row acts [m]
  static constexpr Real kContactTolerance = 1e-5f;
  // Levenberg-Marquardt damping of the system's diagonal (relative): nearly dependent springs share a correction
  // instead of trading large opposite ones
  static constexpr double kDamping = 1e-2;

  struct Spring {
    int va, vb;  // its vertices
    int a, b;    // their points
    int index;   // in the mesh
  };
  struct Incidence {
    int row;   // the active spring's row
    int sign;  // -1 at its first end, +1 at its second
  };

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
  }

  // the length a spring may end the step with, as the velocity sweeps allow it
  Real allowed(const Spring& e) const {
    const Real len = (s_->x.col(e.vb) - s_->x.col(e.va)).norm();
    return stretch_rules::allowed_length(len, (1 + params_.threshold) * s_->mesh.rest_length[e.index],
                                         params_.speed * s_->dt);
  }

  // how far point i ends the step outside the body's moved surface (< 0: inside) [m]
  Real clearance(int i) const {
    const Contact& c = s_->contacts[static_cast<std::size_t>(i)];
    return (p_.col(i) - s_->x.col(i) - s_->dt * c.body_velocity).dot(c.normal);
  }

  // the active rows: the points in contact that would end inside the body's moved surface (with contacts_hold),
  // then the springs at or within the tolerance of their allowed length; false when no spring is longer than it
  // may be by more than the tolerance and no point is inside by more than its tolerance
  bool find_active(bool contacts_hold) {
    active_contacts_.clear();
    active_.clear();
    bool over = false;
    if (contacts_hold)
      for (std::size_t i = 0; i < w_.size(); ++i) {
        if (rep_[i] != static_cast<int>(i) || w_[i] == 0 || released_[i] || !s_->contacts[i].hit) continue;
        const Real gap = clearance(static_cast<int>(i));
        if (gap > kContactTolerance) continue;
        over |= gap < -kContactTolerance;
        active_contacts_.push_back(static_cast<int>(i));
      }
    for (const int ki : order_) {
      const auto k = static_cast<std::size_t>(ki);
      const Spring& e = structural_[k];
      const Real tol = kTolerance * s_->mesh.rest_length[e.index];
      const Real len = (p_.col(e.vb) - p_.col(e.va)).norm();
      if (len < allowed_[k] - tol || !(len > 0)) continue;
      over |= len > allowed_[k] + tol;
      active_.push_back(ki);
    }
    return over;
  }

  // a fill-reducing order of the structural springs (approximate minimum degree over springs sharing a point), found
  // again only when the springs change (sewing, attaching): each iteration's system takes its springs in this order
  // instead of ordering its own (its contact rows go first: each couples only to springs that already share its
  // point, so eliminating it first fills nothing)
  void order_springs() {
    std::vector<int> key;
    for (const Spring& e : structural_) key.insert(key.end(), {e.va, e.vb, e.a, e.b});
    if (key == order_key_) return;
    order_key_ = std::move(key);
    const auto ns = static_cast<Eigen::Index>(structural_.size());
    std::vector<int> all(structural_.size());
    for (std::size_t k = 0; k < all.size(); ++k) all[k] = static_cast<int>(k);
    incidence(all, 0);
    triplets_.clear();
    for (std::size_t i = 0; i + 1 < incident_start_.size(); ++i)
      for (int k = incident_start_[i]; k < incident_start_[i + 1]; ++k)
        for (int l = incident_start_[i]; l < incident_start_[i + 1]; ++l)
          triplets_.emplace_back(incident_[static_cast<std::size_t>(k)].row, incident_[static_cast<std::size_t>(l)].row,
                                 1.0);
    Eigen::SparseMatrix<double> pattern(ns, ns);
    pattern.setFromTriplets(triplets_.begin(), triplets_.end());
    Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> order;
    Eigen::AMDOrdering<int>()(pattern, order);
    order_.assign(order.indices().data(), order.indices().data() + ns);
  }

  // the springs `springs` incident on each point as compressed rows (incident_start_, incident_), their rows
  // numbered from `first`
  void incidence(const std::vector<int>& springs, int first) {
    incident_start_.assign(w_.size() + 1, 0);
    for (const int k : springs) {
      const Spring& e = structural_[static_cast<std::size_t>(k)];
      ++incident_start_[static_cast<std::size_t>(e.a) + 1], ++incident_start_[static_cast<std::size_t>(e.b) + 1];
    }
    for (std::size_t i = 1; i < incident_start_.size(); ++i) incident_start_[i] += incident_start_[i - 1];
    incident_.resize(static_cast<std::size_t>(incident_start_.back()));
    fill_ = incident_start_;
    for (std::size_t r = 0; r < springs.size(); ++r) {
      const Spring& e = structural_[static_cast<std::size_t>(springs[r])];
      const int row = first + static_cast<int>(r);
      incident_[static_cast<std::size_t>(fill_[static_cast<std::size_t>(e.a)]++)] = {row, -1};
      incident_[static_cast<std::size_t>(fill_[static_cast<std::size_t>(e.b)]++)] = {row, +1};
    }
  }

  // the lower triangle of J W J^T: for two springs k and l sharing point i, s_ki s_li w_i u_k . u_l (s = -1 at a
  // spring's first end, +1 at its second); for the contact c of point i and a spring k of it, s_ki w_i n . u_k; a
  // contact's diagonal w_i
  void assemble(const std::vector<Vec3>& dirs, int nc) {
    triplets_.clear();
    for (int c = 0; c < nc; ++c) triplets_.emplace_back(c, c, w_[static_cast<std::size_t>(active_contacts_[static_cast<std::size_t>(c)])]);
    for (std::size_t i = 0; i + 1 < incident_start_.size(); ++i)
      for (int k = incident_start_[i]; k < incident_start_[i + 1]; ++k) {
        const Incidence& ik = incident_[static_cast<std::size_t>(k)];
        const Vec3& uk = dirs[static_cast<std::size_t>(ik.row)];
        for (int l = incident_start_[i]; l < incident_start_[i + 1]; ++l) {
          const Incidence& il = incident_[static_cast<std::size_t>(l)];
          if (il.row <= ik.row)
            triplets_.emplace_back(ik.row, il.row,
                                   w_[i] * double(ik.sign * il.sign) * double(uk.dot(dirs[static_cast<std::size_t>(il.row)])));
        }
      }
    for (int c = 0; c < nc; ++c) {
      const auto i = static_cast<std::size_t>(active_contacts_[static_cast<std::size_t>(c)]);
      for (int k = incident_start_[i]; k < incident_start_[i + 1]; ++k) {
        const Incidence& ik = incident_[static_cast<std::size_t>(k)];
        triplets_.emplace_back(ik.row, c, w_[i] * double(ik.sign) * double(dirs[static_cast<std::size_t>(ik.row)].dot(dirs[static_cast<std::size_t>(c)])));
      }
    }
  }

  // one Newton step: (J W J^T) dl = C over the active rows (contacts, then springs), p -= W J^T dl
  void solve() {
    const int nc = static_cast<int>(active_contacts_.size()), ns = static_cast<int>(active_.size());
    const Eigen::Index n = nc + ns;
    // each row's direction at p (a contact's: the body normal) and its violation
    dirs_.resize(static_cast<std::size_t>(n));
    Eigen::VectorXd c(n);
    for (int r = 0; r < nc; ++r) {
      const int i = active_contacts_[static_cast<std::size_t>(r)];
      dirs_[static_cast<std::size_t>(r)] = s_->contacts[static_cast<std::size_t>(i)].normal;
      c[r] = double(clearance(i));
    }
    for (int r = 0; r < ns; ++r) {
      const auto k = static_cast<std::size_t>(active_[static_cast<std::size_t>(r)]);
      const Spring& e = structural_[k];
      const Vec3 d = p_.col(e.vb) - p_.col(e.va);
      const Real len = d.norm();
      dirs_[static_cast<std::size_t>(nc + r)] = d / len;
      c[nc + r] = double(len) - double(allowed_[k]);
    }
    incidence(active_, nc);
    assemble(dirs_, nc);
    Eigen::SparseMatrix<double> a(n, n);
    a.setFromTriplets(triplets_.begin(), triplets_.end());
    // a spring neither of whose ends can move keeps its length: a unit diagonal and no violation
    const double tiny = 1e-12 * *std::max_element(w_.begin(), w_.end());
    for (Eigen::Index r = 0; r < n; ++r) {
      double& d = a.coeffRef(r, r);
      if (d <= tiny) d = 1, c[r] = 0;
      d *= 1 + kDamping;
    }
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower, Eigen::NaturalOrdering<int>> ldlt(a);
    if (ldlt.info() != Eigen::Success) return;
    const Eigen::VectorXd dl = ldlt.solve(c);
    if (!dl.allFinite()) return;
    move(dl, c, nc);
  }

  // p -= W J^T dl; a contact whose row would hold its point down lets it go from now on
  void move(const Eigen::VectorXd& dl, const Eigen::VectorXd& c, int nc) {
    dp_.setZero(3, p_.cols());
    for (int r = 0; r < nc; ++r) {
      const int i = active_contacts_[static_cast<std::size_t>(r)];
      if (dl[r] > 0) released_[static_cast<std::size_t>(i)] = 1;
      dp_.col(i) -= Real(w_[static_cast<std::size_t>(i)] * dl[r]) * dirs_[static_cast<std::size_t>(r)];
    }
    for (std::size_t r = 0; r < active_.size(); ++r) {
      const Spring& e = structural_[static_cast<std::size_t>(active_[r])];
      const Vec3 l = Real(dl[nc + static_cast<Eigen::Index>(r)]) * dirs_[static_cast<std::size_t>(nc) + r];
      dp_.col(e.a) += Real(w_[static_cast<std::size_t>(e.a)]) * l;
      dp_.col(e.b) -= Real(w_[static_cast<std::size_t>(e.b)]) * l;
    }
    // a point (each of its vertices) moves no farther than the largest violation: where the linearisation is poor
    // (nearly dependent rows) the step would otherwise be as large as its pivot is small
    const Real most = Real(c.cwiseAbs().maxCoeff());
    for (Eigen::Index i = 0; i < p_.cols(); ++i) {
      const Eigen::Index r = rep_[static_cast<std::size_t>(i)];
      const Real len = dp_.col(r).norm();
      p_.col(i) += (len > most ? most / len : Real(1)) * dp_.col(r);
    }
  }

  LimiterParams params_;
  LimitState* s_ = nullptr;
  std::vector<int> rep_;                    // per vertex: its point
  std::vector<double> w_;                   // per point: its inverse mass (0: attached)
  std::vector<std::uint8_t> released_;      // per point: its contact row held it down in this call
  std::vector<Spring> structural_;          // the structural springs between two points, one free
  std::vector<Real> allowed_;               // beside structural_: the length each may end the step with
  std::vector<int> order_;                  // structural_ in a fill-reducing order
  std::vector<int> order_key_;              // the springs order_ was found for
  std::vector<int> active_contacts_;        // the iteration's contact rows (points)
  std::vector<int> active_;                 // its spring rows (indices into structural_, in order_)
  std::vector<Vec3> dirs_;                  // per row: its direction at p
  std::vector<int> incident_start_, fill_;  // per point: where its springs start in incident_ (and a work copy)
  std::vector<Incidence> incident_;         // the spring rows of each point
  std::vector<Eigen::Triplet<double>> triplets_;
  Points3 dp_;                              // an iteration's moves
  Points3 p_;                               // the end-of-step positions being projected
};

}  // namespace

std::unique_ptr<Limiter> make_projection_limit(const LimiterParams& params) {
  return std::make_unique<Projection>(params);
}

}  // namespace clothbench
