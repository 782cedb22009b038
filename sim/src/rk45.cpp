// Adaptive Runge-Kutta of order 5(4), Dormand & Prince 1980 (Hairer, Norsett & Wanner, Table II.5.2): the
// state (x, v) with dx/dt = v, dv/dt = f(x, v)/m is integrated over one iteration's dt in as many sub-steps as
// the error control on positions and velocities needs (FSAL: six force evaluations per sub-step).
#include <algorithm>
#include <cmath>

#include "integrators.hpp"

namespace clothbench {

namespace {

// Dormand-Prince 5(4) tableau: stage nodes a_ij, the 5th-order weights (row 7) and the error weights b - b*
constexpr double kA[6][6] = {{1. / 5},
                             {3. / 40, 9. / 40},
                             {44. / 45, -56. / 15, 32. / 9},
                             {19372. / 6561, -25360. / 2187, 64448. / 6561, -212. / 729},
                             {9017. / 3168, -355. / 33, 46732. / 5247, 49. / 176, -5103. / 18656},
                             {35. / 384, 0, 500. / 1113, 125. / 192, -2187. / 6784, 11. / 84}};
constexpr double kE[7] = {71. / 57600, 0, -71. / 16695, 71. / 1920, -17253. / 339200, 22. / 525, -1. / 40};

class Rk45 : public Integrator {
 public:
  explicit Rk45(const IntegratorParams& p) : params_(p) {}
  const char* name() const override { return "rk45"; }
  std::unique_ptr<Integrator> clone() const override { return std::make_unique<Rk45>(*this); }

  void advance(const ForceModel& model, Real h, const Points3& x, const Points3& f, Points3& v,
               Points3& drift) override;

 private:
  // dv/dt = f/m (0 for attached vertices)
  Points3 accel(const ForceModel& model, const Points3& x, const Points3& v) {
    model.eval(x, v, f_);
    ++stats_.force_evaluations;
    return f_.array().rowwise() * model.inv_m.transpose().array();
  }
  // one sub-step of length h from (x0, v0) with kv[0] = a(x0, v0); returns the scaled error (<= 1: accept)
  Real substep(const ForceModel& model, Real h, const Points3& x0, const Points3& v0);

  IntegratorParams params_;
  Real h_ = 0;             // the last sub-step that was accepted or proposed [s]
  Points3 f_, x_, v_;      // scratch: forces, the stage state, then the 5th-order solution
  Points3 kx_[7], kv_[7];  // stage derivatives dx/dt = v, dv/dt = a
};

Real Rk45::substep(const ForceModel& model, Real h, const Points3& x0, const Points3& v0) {
  for (int s = 1; s < 7; ++s) {
    x_ = x0;
    v_ = v0;
    for (int j = 0; j < s; ++j) {
      if (kA[s - 1][j] == 0) continue;
      x_ += Real(h * kA[s - 1][j]) * kx_[j];
      v_ += Real(h * kA[s - 1][j]) * kv_[j];
    }
    kx_[s] = v_;
    kv_[s] = accel(model, x_, v_);
  }
  // stage 7 sits at the 5th-order solution (x_, v_); the embedded 4th-order one differs by h sum e_j k_j
  Points3 ex = Points3::Zero(3, x0.cols()), ev = Points3::Zero(3, x0.cols());
  for (int j = 0; j < 7; ++j) {
    if (kE[j] == 0) continue;
    ex += Real(h * kE[j]) * kx_[j];
    ev += Real(h * kE[j]) * kv_[j];
  }
  // max norm of the error scaled by the tolerances (Hairer, Norsett & Wanner II.4 with atol only)
  return std::max(ex.cwiseAbs().maxCoeff() / params_.rk_tol_x, ev.cwiseAbs().maxCoeff() / params_.rk_tol_v);
}

void Rk45::advance(const ForceModel& model, Real h, const Points3& x, const Points3& f, Points3& v, Points3& drift) {
  Points3 xs = x, vs = v;
  kx_[0] = v;
  kv_[0] = f.array().rowwise() * model.inv_m.transpose().array();
  ++stats_.force_evaluations;
  const Real h_min = h * Real(1e-6);
  Real t = 0, proposal = h_ > 0 ? std::min(h_, h) : h;
  for (bool done = false; !done;) {
    // the last sub-step ends exactly at h, without a sliver after it
    const bool last = proposal >= h - t - h_min;
    const Real step = last ? h - t : proposal;
    const Real err = substep(model, step, xs, vs);
    const bool accept = err <= 1 || step <= h_min || !std::isfinite(err);
    // step size control: h_new = h min(5, max(0.2, 0.9 err^-1/5)) (Hairer, Norsett & Wanner II.4)
    const Real grow = err > 0 ? Real(0.9) * std::pow(err, Real(-0.2)) : Real(5);
    const Real next = step * std::min(Real(5), std::max(Real(0.2), grow));
    if (!accept) {
      ++stats_.rejected;
      proposal = next;
      continue;
    }
    ++stats_.substeps;
    t += step;
    xs = x_;
    vs = v_;
    kx_[0] = kx_[6];  // FSAL: the last stage is the next sub-step's first
    kv_[0] = kv_[6];
    if (!last || next < proposal) proposal = next;  // a shortened last sub-step says little about the next
    h_ = proposal;
    done = last || !std::isfinite(err);  // diverged: the Simulator's check reports it
  }
  v = vs;
  drift = xs - x - h * vs;  // x_end = x + h v_end + drift
}

}  // namespace

std::unique_ptr<Integrator> make_rk45(const IntegratorParams& params) { return std::make_unique<Rk45>(params); }

}  // namespace clothbench
