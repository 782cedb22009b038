// Projective implicit Euler after Liu, Bargteil, O'Brien & Kavan 2013 ("Fast Simulation of Mass-Spring
// Systems"): backward Euler's step as the minimum of (1/2h^2)|x - y|_M^2 + E(x) (Liu Eq. 5, y = x + h v +
// h^2 M^-1 f_ext), each spring's energy written as (k/2)|x_a - x_b - d|^2 over an auxiliary vector d of the
// spring's rest length (Liu Eq. 8). Alternating the local step (d from the current x, Liu Eq. 12) and the
// global one ((M/h^2 + L) x = M y / h^2 + J d, Liu Eq. 10) descends that energy; the matrix depends only on
// h, masses and stiffnesses, so it is factored once (sparse Cholesky) and each iteration is one local pass and
// three back-substitutions. Elastic seams are zero-length springs (d = 0) within seam_reach and, beyond it, a
// spring whose d = (|x_a - x_b| - reach) u gives exactly the capped pull k reach u; merged pairs keep d = 0.
// Gravity and damping are external forces (evaluated at the step's start), the reaction force of walking Eq. 16
// taken on them. Attached vertices move with their velocity: their columns go to the right-hand side. Contacts,
// friction and the strain limit stay with the Simulator's shared passes after the step.
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <memory>
#include <stdexcept>

#include "clothbench/sim/timer.hpp"
#include "integrators.hpp"

namespace clothbench {

namespace {

using SpMat = Eigen::SparseMatrix<double>;
using Points3d = Eigen::Matrix<double, 3, Eigen::Dynamic>;  // one column per free vertex

// a merged pair's coupling in the matrix, times its seam's stiffness: the Simulator moves merged partners as one
// point, so the solve keeps them together (solved apart, each takes only its own panel's pull and their mean
// stretches the springs beside the seam)
constexpr double kMergedCoupling = 100;

// P A P^T = L L^T (Eigen's simplicial Cholesky, AMD ordering), solved for the three axes at once: one pass over
// L per triangle with the right-hand side interleaved (x, y, z of a vertex together), where Eigen's solve
// passes over L once per axis
class Factor {
 public:
  explicit Factor(const SpMat& a) {
    Eigen::SimplicialLLT<SpMat> llt(a);
    if (llt.info() != Eigen::Success)
      throw std::runtime_error("projective: the system matrix M/h^2 + L is not positive definite");
    l_ = llt.matrixL();
    l_.makeCompressed();
    perm_ = llt.permutationP().indices();
  }
  // x = A^-1 b, b and x one column per row of A (y: scratch)
  void solve(const Points3d& b, Points3d& x, Points3d& y) const {
    const Eigen::Index n = l_.cols();
    y.resize(3, n);
    for (Eigen::Index i = 0; i < n; ++i) y.col(perm_[i]) = b.col(i);
    const int* outer = l_.outerIndexPtr();
    const int* inner = l_.innerIndexPtr();
    const double* val = l_.valuePtr();
    for (Eigen::Index j = 0; j < n; ++j) {  // L z = P b (the diagonal first in each column)
      y.col(j) /= val[outer[j]];
      const Eigen::Vector3d yj = y.col(j);
      for (int k = outer[j] + 1; k < outer[j + 1]; ++k) y.col(inner[k]) -= val[k] * yj;
    }
    for (Eigen::Index j = n - 1; j >= 0; --j) {  // L^T w = z
      Eigen::Vector3d sum = y.col(j);
      for (int k = outer[j] + 1; k < outer[j + 1]; ++k) sum -= val[k] * y.col(inner[k]);
      y.col(j) = sum / val[outer[j]];
    }
    x.resize(3, n);
    for (Eigen::Index i = 0; i < n; ++i) x.col(i) = y.col(perm_[i]);
  }

 private:
  SpMat l_;
  Eigen::VectorXi perm_;
};

class Projective : public Integrator {
 public:
  explicit Projective(const IntegratorParams& p) : params_(p) {}
  const char* name() const override { return "projective"; }
  bool needs_forces() const override { return false; }  // its own: external ones here, springs in the solve
  std::unique_ptr<Integrator> clone() const override { return std::make_unique<Projective>(*this); }
  // the papers' clock (walking section 5: 5 ms steps); backward Euler is not bounded by Eq. 4
  Real automatic_dt(Real) const override { return Real(0.005); }
  void advance(const ForceModel& model, Real h, const Points3& x, const Points3&, Points3& v, Points3&) override;

 private:
  struct Link {  // a spring or a seam pair, as the solve sees it
    int a, b;
    double k;   // the spring's or the seam's stiffness
    double w;   // its weight in the matrix (weight())
    Real rest;  // a spring's rest length (a seam's is zero)
    int seam;   // seam pair index, or -1 for a spring
  };
  bool stale(const ForceModel& model, Real h) const;
  void factor(const ForceModel& model, Real h);
  double weight(const ForceModel& model, const Link& l) const;
  Vec3 target(const ForceModel& model, const Link& l, const Vec3& d) const;

  IntegratorParams params_;
  std::vector<Link> links_;
  std::vector<int> free_;  // per vertex: its row among the free vertices, or -1 when attached
  Eigen::Index n_free_ = 0;
  Real h_ = 0;                              // the step the matrix was factored for
  bool elastic_ = false;                    // and whether the seams were elastic
  std::vector<std::uint8_t> merged_;        // and which seam pairs were merged
  std::shared_ptr<const Factor> factor_;    // shared by clones until one of them factors again
  Points3d inertia_, rhs_, sol_, scratch_;  // M y / h^2, Liu Eq. 10's right-hand side, its solution (free vertices)
};

bool Projective::stale(const ForceModel& model, Real h) const {
  if (h != h_ || model.elastic_seams != elastic_ || free_.size() != static_cast<std::size_t>(model.m.size()) ||
      merged_ != model.merged)
    return true;
  for (std::size_t i = 0; i < free_.size(); ++i)
    if ((free_[i] >= 0) != (model.inv_m[Eigen::Index(i)] > 0)) return true;
  return false;
}

void Projective::factor(const ForceModel& model, Real h) {
  const Eigen::Index nv = model.m.size();
  free_.assign(static_cast<std::size_t>(nv), -1);
  n_free_ = 0;
  for (Eigen::Index i = 0; i < nv; ++i)
    if (model.inv_m[i] > 0) free_[static_cast<std::size_t>(i)] = int(n_free_++);
  links_.clear();
  const ClothMesh& mesh = model.mesh;
  for (Eigen::Index s = 0; s < mesh.springs.cols(); ++s)
    links_.push_back({mesh.springs(0, s), mesh.springs(1, s), double(model.k[s]), 0, mesh.rest_length[s], -1});
  for (Eigen::Index p = 0; p < mesh.seam_pairs.cols(); ++p)
    links_.push_back({mesh.seam_pairs(0, p), mesh.seam_pairs(1, p), double(model.seam_k[p]), 0, 0, int(p)});
  // Liu Eq. 10's matrix M / h^2 + L, L = sum_s k_s A_s A_s^T over the free vertices (one copy per axis)
  std::vector<Eigen::Triplet<double>> t;
  for (Eigen::Index i = 0; i < nv; ++i)
    if (free_[std::size_t(i)] >= 0)
      t.emplace_back(free_[std::size_t(i)], free_[std::size_t(i)], model.m[i] / (double(h) * h));
  for (Link& l : links_) {
    const int a = free_[std::size_t(l.a)], b = free_[std::size_t(l.b)];
    const double w = l.w = weight(model, l);
    if (a >= 0) t.emplace_back(a, a, w);
    if (b >= 0) t.emplace_back(b, b, w);
    if (a >= 0 && b >= 0) t.emplace_back(a, b, -w), t.emplace_back(b, a, -w);
  }
  SpMat a(n_free_, n_free_);
  a.setFromTriplets(t.begin(), t.end());
  factor_ = std::make_shared<Factor>(a);
  h_ = h;
  elastic_ = model.elastic_seams;
  merged_ = model.merged;
}

double Projective::weight(const ForceModel& model, const Link& l) const {
  if (l.seam < 0) return l.k;
  if (model.merged[std::size_t(l.seam)]) return kMergedCoupling * l.k;
  return model.elastic_seams ? l.k : 0;
}

Vec3 Projective::target(const ForceModel& model, const Link& l, const Vec3& d) const {
  // Liu Eq. 12: the d closest to x_a - x_b with the spring's rest length; a seam: zero length within reach,
  // the gap less the reach beyond it (the force k (x_a - x_b - d) is then the capped k reach u)
  const Real len = d.norm();
  if (!(len > 0)) return Vec3::Zero();
  if (l.seam < 0) return d * (l.rest / len);
  if (model.merged[std::size_t(l.seam)] || !model.elastic_seams || len <= model.seam_reach) return Vec3::Zero();
  return d * ((len - model.seam_reach) / len);
}

void Projective::advance(const ForceModel& model, Real h, const Points3& x, const Points3&, Points3& v, Points3&) {
  Stopwatch watch;
  if (stale(model, h)) factor(model, h);
  const Eigen::Index nv = x.cols();
  // Liu Eq. 5's inertial target y = x + h v + h^2 M^-1 f_ext, f_ext gravity and damping with walking Eq. 16 taken
  // on them alone: on all of f it would cancel the springs' pull into the body at the step's start, which the
  // solve then replaces by their pull at its end
  Points3 f_ext;
  model.external(v, f_ext);
  model.react(f_ext);
  Points3 q = x + h * v;
  inertia_.resize(3, n_free_);
  for (Eigen::Index i = 0; i < nv; ++i) {
    const int r = free_[std::size_t(i)];
    if (r < 0) continue;
    q.col(i) += (h * h * model.inv_m[i]) * f_ext.col(i);
    inertia_.col(r) = (model.m[i] / (double(h) * h)) * q.col(i).cast<double>();
  }
  stats_.assemble_ms += watch.ms();
  for (int it = 0; it < params_.projective_iterations; ++it) {
    watch.restart();
    // local step (Liu Eq. 12), then the right-hand side of Liu Eq. 10: M y / h^2 + J d, attached ends moved over
    rhs_ = inertia_;
    for (const Link& l : links_) {
      if (!(l.w > 0)) continue;
      const Eigen::Vector3d wd = l.w * target(model, l, q.col(l.a) - q.col(l.b)).cast<double>();
      const int a = free_[std::size_t(l.a)], b = free_[std::size_t(l.b)];
      if (a >= 0) rhs_.col(a) += wd + (b < 0 ? l.w : 0.0) * q.col(l.b).cast<double>();
      if (b >= 0) rhs_.col(b) += -wd + (a < 0 ? l.w : 0.0) * q.col(l.a).cast<double>();
    }
    stats_.assemble_ms += watch.ms();
    watch.restart();
    factor_->solve(rhs_, sol_, scratch_);
    for (Eigen::Index i = 0; i < nv; ++i)
      if (free_[std::size_t(i)] >= 0) q.col(i) = sol_.col(free_[std::size_t(i)]).cast<Real>();
    stats_.solve_ms += watch.ms();
    ++stats_.cg_iterations;
  }
  // the end-of-step velocity (x_end = x + h v_end: no drift); attached vertices keep theirs
  for (Eigen::Index i = 0; i < nv; ++i)
    if (free_[std::size_t(i)] >= 0) v.col(i) = (q.col(i) - x.col(i)) / h;
  ++stats_.force_evaluations;
  ++stats_.substeps;
}

}  // namespace

std::unique_ptr<Integrator> make_projective(const IntegratorParams& params) {
  return std::make_unique<Projective>(params);
}

}  // namespace clothbench
