// Implicit Euler after Baraff & Witkin 1998 (section 4): one linearised backward-Euler step per iteration,
// solved with Eigen's ConjugateGradient (block-Jacobi preconditioned) on a 3n x 3n sparse matrix whose pattern is
// built once.
// Spring Jacobians in their positive-definite variant (the compressive part of the transverse term is clamped,
// Choi & Ko 2002), so the matrix is symmetric positive definite. Attached vertices are constraints of
// Baraff & Witkin 5.3's S filter with S = 0, applied as zero rows and columns with a unit diagonal (their
// velocity change is 0). A vertex the body holds (in contact, not moving away) is filtered with
// S = I - n n^T: the solve ends its velocity along the normal at the body's, so its neighbours hang from it
// instead of falling with it; one whose constraint force pulled it into the body is released at the next
// step (5.3's release). Friction and the rest of the contact stay with the shared response after the solve.
// Sewn (merged) partners, which the Simulator moves as one point, stay coupled in the Jacobian by a stiff
// zero-length spring with no force: solved apart, each would take only its own panel's pull and their
// mean would stretch the springs beside the seam (2,300 % on the shirt at 10 ms before this).
#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCore>
#include <algorithm>
#include <cstdint>

#include "clothbench/sim/timer.hpp"
#include "integrators.hpp"

namespace clothbench {

namespace {

using Mat3 = Eigen::Matrix<Real, 3, 3>;
using SpMat = Eigen::SparseMatrix<Real>;
using Vec = Eigen::Matrix<Real, Eigen::Dynamic, 1>;

// -df_a/dx_a of a spring of stiffness k and rest length l0 along d = x_a - x_b (dressing Eq. 2), positive
// semi-definite: k (u u^T + max(0, 1 - l0/|d|) (I - u u^T)) (Baraff & Witkin 1998 Eq. 16 with the
// compressive part dropped)
Mat3 spring_stiffness(const Vec3& d, Real k, Real l0) {
  const Real len = d.norm();
  if (!(len > 0)) return k * Mat3::Identity();
  const Vec3 u = d / len;
  const Mat3 uu = u * u.transpose();
  return k * (uu + std::max(Real(0), 1 - l0 / len) * (Mat3::Identity() - uu));
}

// -df_a/dx_a of an elastic seam as the zero-length spring it is within reach: k I. Beyond reach the force
// (k reach u) has no stiffness along u, and a light outline vertex would take all of h k reach / m in one
// step; the zero-length spring's Jacobian there too keeps that pull implicit (a stiffer Jacobian than the
// exact one, Baraff & Witkin 1998 section 5.2's licence: the step stays first order and is more damped)
Mat3 seam_stiffness(Real k) { return k * Mat3::Identity(); }

// a merged pair's coupling, times its seam's stiffness: stiff enough that the pair's velocity changes agree
// (the shirt's largest strain: 65 % at 1x, 47 % at 10x, 44 % at 100x), soft enough for CG's conditioning
constexpr Real kMergedCoupling = 10;

// Block-Jacobi preconditioner for CG (Eigen's preconditioner interface): the inverses of the 3 x 3 diagonal
// blocks, one per vertex. The filter of held vertices (S A S + I - S) makes those blocks anisotropic, which a
// scalar (diagonal) Jacobi does not see
class BlockJacobi {
 public:
  using StorageIndex = int;
  enum { ColsAtCompileTime = Eigen::Dynamic, MaxColsAtCompileTime = Eigen::Dynamic };
  BlockJacobi() = default;
  template <typename M>
  explicit BlockJacobi(const M& m) {
    compute(m);
  }
  template <typename M>
  BlockJacobi& analyzePattern(const M&) {
    return *this;
  }
  template <typename M>
  BlockJacobi& factorize(const M& m) {
    return compute(m);
  }
  template <typename M>
  BlockJacobi& compute(const M& m) {
    const Eigen::Index n = m.cols() / 3;
    inverse_.resize(static_cast<std::size_t>(n));
    for (Eigen::Index i = 0; i < n; ++i) {
      Mat3 b;
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) b(r, c) = m.coeff(3 * i + r, 3 * i + c);
      inverse_[static_cast<std::size_t>(i)] = b.inverse();
    }
    return *this;
  }
  template <typename Rhs>
  Vec solve(const Rhs& b) const {
    Vec x(b.size());
    for (std::size_t i = 0; i < inverse_.size(); ++i)
      x.segment<3>(3 * Eigen::Index(i)) = inverse_[i] * b.template segment<3>(3 * Eigen::Index(i));
    return x;
  }
  Eigen::ComputationInfo info() const { return Eigen::Success; }

 private:
  std::vector<Mat3> inverse_;
};

class ImplicitEuler : public Integrator {
 public:
  explicit ImplicitEuler(const IntegratorParams& p) : params_(p) {}
  const char* name() const override { return "implicit-euler"; }
  std::unique_ptr<Integrator> clone() const override { return std::make_unique<ImplicitEuler>(*this); }
  // a fixed 10 ms (the step): not bounded by Eq. 4
  Real automatic_dt(Real) const override { return Real(0.01); }

  void advance(const ForceModel& model, Real h, const Points3&, const Points3& f, Points3& v, Points3&) override;

 private:
  // one 3x3 block's offset within each of its three columns (the columns of a block column share their rows)
  int block(int row, int column) const {
    const int* inner = a_.innerIndexPtr();
    const int* begin = inner + a_.outerIndexPtr()[3 * column];
    return static_cast<int>(std::lower_bound(begin, inner + a_.outerIndexPtr()[3 * column + 1], 3 * row) - begin);
  }
  void build_pattern(const ForceModel& model);
  void add_block(int column, int offset, const Mat3& b);  // offset: block() of the block's row
  void add_pair(const ForceModel& model, int a, int b, const Mat3& k, const Points3& v, Real h, const int* off);
  void assemble(const ForceModel& model, Real h, const Points3& x, const Points3& f, const Points3& v);
  bool hold_contacts(const ForceModel& model, const Points3& v);
  void filter();
  void solve(const SpMat& a, const Vec& b);
  void note_pulled();

  IntegratorParams params_;
  SpMat a_;                      // M (1 + h c) + h^2 K, filtered (3n x 3n)
  std::vector<int> spring_off_;  // per spring: offsets of blocks aa, bb, ab, ba
  std::vector<int> seam_off_;    // per seam pair: the same
  std::vector<int> diag_off_;    // per vertex
  Vec b_, dv_;                   // right-hand side h (f0 + h df/dx v0), velocity change
  std::vector<Vec3> normal_;     // per vertex: the body's normal where the body holds it, else zero
  std::vector<std::uint8_t> pulled_;  // per vertex: its constraint pulled it into the body last step
  Vec z_;                        // the held vertices' velocity change along their normal
  std::vector<Real> unfiltered_;  // a_'s values before the filter (the constraint forces need them)
};

void ImplicitEuler::build_pattern(const ForceModel& model) {
  const Eigen::Index nv = model.m.size();
  std::vector<Eigen::Triplet<Real>> t;
  const auto pair_blocks = [&](int a, int b) {
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) t.emplace_back(3 * a + r, 3 * b + c, 0), t.emplace_back(3 * b + r, 3 * a + c, 0);
  };
  for (Eigen::Index i = 0; i < nv; ++i)
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) t.emplace_back(3 * i + r, 3 * i + c, 0);
  for (Eigen::Index s = 0; s < model.mesh.springs.cols(); ++s)
    pair_blocks(model.mesh.springs(0, s), model.mesh.springs(1, s));
  for (Eigen::Index p = 0; p < model.mesh.seam_pairs.cols(); ++p)
    pair_blocks(model.mesh.seam_pairs(0, p), model.mesh.seam_pairs(1, p));
  a_.resize(3 * nv, 3 * nv);
  a_.setFromTriplets(t.begin(), t.end());
  a_.makeCompressed();
  diag_off_.resize(static_cast<std::size_t>(nv));
  for (Eigen::Index i = 0; i < nv; ++i) diag_off_[static_cast<std::size_t>(i)] = block(int(i), int(i));
  const auto offsets = [&](const Pairs& pairs, std::vector<int>& off) {
    off.resize(static_cast<std::size_t>(4 * pairs.cols()));
    for (Eigen::Index s = 0; s < pairs.cols(); ++s) {
      const int a = pairs(0, s), b = pairs(1, s);
      const int o[4] = {block(a, a), block(b, b), block(a, b), block(b, a)};
      std::copy(o, o + 4, off.begin() + 4 * s);
    }
  };
  offsets(model.mesh.springs, spring_off_);
  offsets(model.mesh.seam_pairs, seam_off_);
  dv_ = Vec::Zero(3 * nv);
}

void ImplicitEuler::add_block(int column, int offset, const Mat3& b) {
  Real* val = a_.valuePtr();
  const int* outer = a_.outerIndexPtr();
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r) val[outer[3 * column + c] + offset + r] += b(r, c);
}

void ImplicitEuler::add_pair(const ForceModel& model, int a, int b, const Mat3& k, const Points3& v, Real h,
                             const int* off) {
  // Baraff & Witkin 1998 Eq. 16: h^2 K in the matrix, -h^2 K v0 in the right-hand side (df/dx = -K); a row or
  // column of an attached vertex stays zero (S filter)
  const bool free_a = model.inv_m[a] > 0, free_b = model.inv_m[b] > 0;
  const Mat3 hk = h * h * k;
  const Vec3 kv = hk * (v.col(a) - v.col(b));
  if (free_a) add_block(a, off[0], hk), b_.segment<3>(3 * a) -= kv;
  if (free_b) add_block(b, off[1], hk), b_.segment<3>(3 * b) += kv;
  if (free_a && free_b) add_block(b, off[2], -hk), add_block(a, off[3], -hk);
}

void ImplicitEuler::assemble(const ForceModel& model, Real h, const Points3& x, const Points3& f, const Points3& v) {
  const Eigen::Index nv = x.cols();
  if (a_.rows() != 3 * nv) build_pattern(model);
  std::fill(a_.valuePtr(), a_.valuePtr() + a_.nonZeros(), Real(0));
  // Baraff & Witkin 1998 Eq. 16: (M - h df/dv - h^2 df/dx) dv = h (f0 + h df/dx v0), df/dv = -c M
  b_ = h * Eigen::Map<const Vec>(f.data(), 3 * nv);
  for (Eigen::Index i = 0; i < nv; ++i) {
    const bool free = model.inv_m[i] > 0;
    const Real diag = free ? model.m[i] * (1 + h * model.damping) : Real(1);
    add_block(int(i), diag_off_[static_cast<std::size_t>(i)], diag * Mat3::Identity());
    if (!free) b_.segment<3>(3 * i).setZero();
  }
  const ClothMesh& mesh = model.mesh;
  for (Eigen::Index s = 0; s < mesh.springs.cols(); ++s) {
    const int a = mesh.springs(0, s), b = mesh.springs(1, s);
    const Mat3 k = spring_stiffness(x.col(a) - x.col(b), model.k[s], mesh.rest_length[s]);
    add_pair(model, a, b, k, v, h, &spring_off_[static_cast<std::size_t>(4 * s)]);
  }
  for (Eigen::Index p = 0; model.elastic_seams && p < mesh.seam_pairs.cols(); ++p) {
    const bool merged = model.merged[static_cast<std::size_t>(p)];
    const int a = mesh.seam_pairs(0, p), b = mesh.seam_pairs(1, p);
    const Mat3 k = seam_stiffness(merged ? kMergedCoupling * model.seam_k[p] : model.seam_k[p]);
    add_pair(model, a, b, k, v, h, &seam_off_[static_cast<std::size_t>(4 * p)]);
  }
}

bool ImplicitEuler::hold_contacts(const ForceModel& model, const Points3& v) {
  // Baraff & Witkin 1998 section 5.3: a vertex in contact that is not leaving the body (nor was released
  // last step) ends the step with the body's velocity along the normal; its tangential motion stays free
  const Eigen::Index nv = v.cols();
  normal_.assign(static_cast<std::size_t>(nv), Vec3::Zero());
  pulled_.resize(static_cast<std::size_t>(nv), 0);
  z_.setZero(3 * nv);
  bool any = false;
  for (Eigen::Index i = 0; i < nv && static_cast<std::size_t>(i) < model.contacts.size(); ++i) {
    const Contact& c = model.contacts[static_cast<std::size_t>(i)];
    const Real vn = (v.col(i) - c.body_velocity).dot(c.normal);
    if (!c.hit || !(model.inv_m[i] > 0) || vn > 0 || pulled_[static_cast<std::size_t>(i)]) continue;
    normal_[static_cast<std::size_t>(i)] = c.normal;
    z_.segment<3>(3 * i) = -vn * c.normal;
    any = true;
  }
  return any;
}

void ImplicitEuler::filter() {
  // A becomes S A S + (I - S), block by block (the pattern is dense 3 x 3 blocks)
  unfiltered_.assign(a_.valuePtr(), a_.valuePtr() + a_.nonZeros());
  Real* val = a_.valuePtr();
  const int* outer = a_.outerIndexPtr();
  const int* inner = a_.innerIndexPtr();
  const auto s_of = [&](Eigen::Index i) {
    const Vec3& n = normal_[static_cast<std::size_t>(i)];
    return Mat3(Mat3::Identity() - n * n.transpose());
  };
  for (Eigen::Index j = 0; j < a_.cols() / 3; ++j) {
    const bool held_j = !normal_[static_cast<std::size_t>(j)].isZero();
    for (int k = outer[3 * j]; k < outer[3 * j + 1]; k += 3) {
      const Eigen::Index i = inner[k] / 3;
      if (!held_j && normal_[static_cast<std::size_t>(i)].isZero()) continue;
      const int off = k - outer[3 * j];
      Mat3 b;
      for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) b(r, c) = val[outer[3 * j + c] + off + r];
      b = s_of(i) * b * s_of(j);
      if (i == j) b += Mat3::Identity() - s_of(i);
      for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) val[outer[3 * j + c] + off + r] = b(r, c);
    }
  }
}

void ImplicitEuler::note_pulled() {
  // the constraint's impulse h f_c = A dv - b (A unfiltered): a held vertex the body would have to pull is
  // released at the next step
  const Eigen::Map<const SpMat> a(a_.rows(), a_.cols(), a_.nonZeros(), a_.outerIndexPtr(), a_.innerIndexPtr(),
                                  unfiltered_.data());
  const Vec impulse = a * dv_ - b_;
  for (std::size_t i = 0; i < normal_.size(); ++i)
    pulled_[i] = !normal_[i].isZero() && impulse.segment<3>(3 * Eigen::Index(i)).dot(normal_[i]) < 0;
}

void ImplicitEuler::solve(const SpMat& a, const Vec& b) {
  Eigen::ConjugateGradient<SpMat, Eigen::Lower | Eigen::Upper, BlockJacobi> cg;
  cg.setTolerance(params_.cg_tolerance);
  cg.setMaxIterations(params_.cg_max_iterations);
  cg.compute(a);
  dv_ = cg.solveWithGuess(b, dv_);  // warm start: the last step's velocity change
  stats_.cg_iterations += cg.iterations();
  stats_.cg_unconverged += cg.info() != Eigen::Success;
}

void ImplicitEuler::advance(const ForceModel& model, Real h, const Points3& x, const Points3& f, Points3& v, Points3&) {
  Stopwatch watch;
  assemble(model, h, x, f, v);
  const bool held = hold_contacts(model, v);
  Vec b = b_;
  if (held) {
    // Baraff & Witkin 1998 section 5.3: (S A S + I - S) y = S (b - A z), dv = y + z
    b -= a_ * z_;
    filter();
    for (std::size_t i = 0; i < normal_.size(); ++i) {
      const Vec3 n = normal_[i];
      b.segment<3>(3 * Eigen::Index(i)) -= n * n.dot(b.segment<3>(3 * Eigen::Index(i)));
    }
    dv_ -= z_;
  }
  stats_.assemble_ms += watch.ms();
  watch.restart();
  solve(a_, b);
  if (held) dv_ += z_, note_pulled();
  else std::fill(pulled_.begin(), pulled_.end(), 0);
  stats_.solve_ms += watch.ms();
  ++stats_.force_evaluations;
  ++stats_.substeps;
  v += Eigen::Map<const Points3>(dv_.data(), 3, x.cols());
}

}  // namespace

std::unique_ptr<Integrator> make_implicit_euler(const IntegratorParams& params) {
  return std::make_unique<ImplicitEuler>(params);
}

}  // namespace clothbench
