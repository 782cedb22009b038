#pragma once
/// Time integrators, a comparison axis (Durupinar section 3: "Explicit Euler, adaptive 5th order Runge-Kutta,
/// or Implicit Euler"). The Simulator asks its integrator for the velocity and position update of one
/// iteration; limits, seaming, collision response, merging and divergence checks stay around it, shared.
#include <memory>
#include <string>
#include <vector>

#include "clothbench/sim/clone_ptr.hpp"
#include "clothbench/sim/cloth.hpp"
#include "clothbench/sim/collider.hpp"

namespace clothbench {

/// The forces of one iteration as a function of the state: gravity, damping -m c v, springs (dressing Eq. 2),
/// elastic seams and the reaction force of walking Eq. 16. A view of the Simulator's arrays (valid for one step).
struct ForceModel {
  const ClothMesh& mesh;
  const Scalars& k;                         ///< stiffness per spring [N/m] (ns)
  const Scalars& seam_k;                    ///< stiffness per seam pair [N/m] (np)
  const std::vector<std::uint8_t>& merged;  ///< per seam pair: merged pairs pull no more
  const Scalars& m;                         ///< [kg] (nv)
  const Scalars& inv_m;                     ///< 1/m, 0 for attached vertices (nv)
  const std::vector<Contact>& contacts;     ///< this iteration's (reaction force)
  Vec3 gravity;                             ///< [m/s^2] (zero while sewing)
  Real damping = 0;                         ///< per unit mass [1/s]
  bool elastic_seams = false;
  Real seam_reach = 0;    ///< [m]
  bool reaction = false;  ///< walking Eq. 16
  Real friction = 0;      ///< C_fric of Eq. 16

  /// f(x, v) [N] (3 x nv): external(), the springs and seams, then react().
  void eval(const Points3& x, const Points3& v, Points3& f) const;
  /// Gravity and damping alone [N] (3 x nv).
  void external(const Points3& v, Points3& f) const;
  /// Walking Eq. 16 on f where the body holds a point that f pushes into it (when `reaction`).
  void react(Points3& f) const;
};

/// Cumulative counts and times of an integrator [ms].
struct IntegratorStats {
  long force_evaluations = 0;  ///< f(x, v) evaluations
  long substeps = 0;           ///< accepted sub-steps (rk45), or steps
  long rejected = 0;           ///< rejected sub-steps (rk45)
  long cg_iterations = 0;      ///< conjugate-gradient iterations as Eigen counts them (the converging one not), or
                               ///< projective's local/global iterations
  long cg_unconverged = 0;     ///< solves that stopped at the iteration cap (implicit-euler)
  double assemble_ms = 0;      ///< Jacobian and right-hand side (implicit-euler), local steps (projective)
  double solve_ms = 0;         ///< CG (implicit-euler), back-substitutions (projective)
};

/// Settings of the integrators (SolverParams carries them; scenes/README.md documents the keys).
struct IntegratorParams {
  Real cg_tolerance = 1e-3f;  ///< implicit-euler: CG stops at |r| <= tolerance |b| (Eigen's relative residual)
  int cg_max_iterations = 100;
  Real rk_tol_x = 1e-5f;  ///< rk45: error per sub-step on positions [m]
  Real rk_tol_v = 1e-3f;  ///< rk45: error per sub-step on velocities [m/s]
  int projective_iterations = 2;  ///< projective: local/global iterations per step
};

/// One iteration's update of velocities and positions: on return v holds the end-of-step velocities and
/// `drift` what the positions move besides h v (x_end = x + h v + drift; zero for the Euler steps, where
/// x_end = x + h v_end). The Simulator limits and responds on the step's mean velocity v + drift / h (so they
/// see the whole displacement), moves x by h times it, then subtracts drift / h again.
class Integrator {
 public:
  virtual ~Integrator() = default;
  virtual const char* name() const = 0;
  virtual std::unique_ptr<Integrator> clone() const = 0;
  /// The step used when dt is automatic, given the explicit one (dt_fraction x min(Eq. 4, Gershgorin)) [s].
  virtual Real automatic_dt(Real explicit_dt) const { return explicit_dt; }
  /// Whether advance reads `f` (the Simulator skips evaluating it otherwise).
  virtual bool needs_forces() const { return true; }
  /// Whether a given dt must respect dressing Eq. 4 (explicit Euler only).
  virtual bool bounded_by_eq4() const { return false; }
  /// f: the forces at (x, v), already evaluated. Attached vertices (1/m = 0) keep their velocity.
  virtual void advance(const ForceModel& model, Real h, const Points3& x, const Points3& f, Points3& v,
                       Points3& drift) = 0;
  const IntegratorStats& stats() const { return stats_; }

 protected:
  IntegratorStats stats_;
};

/// The registered names: "explicit-euler", "implicit-euler", "rk45", "projective".
std::vector<std::string> integrator_names();
/// Throws std::invalid_argument naming the accepted values unless `name` is registered.
void check_integrator(const std::string& name);
/// A new integrator by name (check_integrator's error otherwise).
std::unique_ptr<Integrator> make_integrator(const std::string& name, const IntegratorParams& params);

/// The Simulator's integrator, copied by clone().
using IntegratorPtr = ClonePtr<Integrator>;

}  // namespace clothbench
