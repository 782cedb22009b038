#pragma once
/// Strain limiters: methods that keep a mass-spring cloth's springs from stretching past (1 + threshold) of their
/// rest length (dressing section 4, walking section 3, and methods beyond the papers). A family registered by name
/// (`solver.limit`), one file per member in sim/src/limiters/; the Simulator calls its limiter where the limit acts
/// in the step and the limiter keeps its own state.
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "clothbench/sim/clone_ptr.hpp"
#include "clothbench/sim/cloth.hpp"
#include "clothbench/sim/collider.hpp"

namespace clothbench {

/// What a limiter acts on in one call: views of the Simulator's arrays, valid for the call.
struct LimitState {
  const ClothMesh& mesh;
  Points3& x;                             ///< positions [m] (3 x nv): the step's start (velocity stage), its end (position stage)
  Points3& v;                             ///< velocities that move the points over the step [m/s] (3 x nv)
  const Scalars& m;                       ///< masses [kg] (nv)
  const Scalars& inv_m;                   ///< 1/m, 0 for attached vertices (nv)
  const std::vector<Contact>& contacts;   ///< this step's, vertices first (empty without a collider)
  const std::vector<std::vector<int>>& merged;  ///< sewn points: the vertices of each group move as one point
  Vec3 gravity;                           ///< the gravity acting in the phase [m/s^2] (zero while sewing)
  Real dt;                                ///< the step [s]
};

/// Settings every limiter reads (SolverParams carries them; scenes/README.md documents the keys).
struct LimiterParams {
  Real threshold = 0.10f;    ///< a spring may stretch to (1 + threshold) l0
  int passes = 1;            ///< passes over the springs per call (the most: sweeps stop once a pass changes nothing)
  Real speed = 2.f;          ///< a spring already past the threshold shortens at most this fast [m/s]
  Real tolerance = 0;        ///< a velocity change that moves a point less than this over the step wakes no spring [m]
  Real stiff_factor = 10.f;  ///< `stiff`: every stiffness multiplied by this
};

/// One strain limiter, with its state between steps (sweep orders, tethers).
class Limiter {
 public:
  virtual ~Limiter() = default;
  virtual std::unique_ptr<Limiter> clone() const = 0;
  /// The velocity stage, after the forces and before the positions move; with `contacts_hold` it is called again
  /// after the collision response, each pass then followed by stopping the motion into the body of the vertices in
  /// contact (SolverParams::limit_after_response).
  virtual void limit_velocities(LimitState& state, bool contacts_hold);
  /// The position stage, after the positions have moved over the step.
  virtual void limit_positions(LimitState& state);
  /// What every spring stiffness is multiplied by (dressing 4.1; 1 for the other methods).
  virtual Real stiffness_factor() const { return 1; }
  /// Passes over the springs run so far.
  long passes() const { return passes_; }

 protected:
  long passes_ = 0;
};

/// A registered limiter: its name, what it implements, and whether it is one of the papers' methods.
struct LimiterInfo {
  const char* name;
  const char* source;  ///< the paper and section (or the later paper) it follows
  bool papers;         ///< a method of the three papers (the others are later work)
  std::unique_ptr<Limiter> (*make)(const LimiterParams&);
};

/// Every registered limiter, in a fixed order: the papers' methods first.
const std::vector<LimiterInfo>& limiter_registry();
/// The registered names.
std::vector<std::string> limiter_names();
/// Throws std::invalid_argument naming the accepted values unless `name` is registered.
void check_limiter(const std::string& name);
/// A new limiter by name (check_limiter's error otherwise).
std::unique_ptr<Limiter> make_limiter(const std::string& name, const LimiterParams& params);
/// The Simulator's limiter, copied by clone().
using LimiterPtr = ClonePtr<Limiter>;

/// The velocity limits' rules for one over-stretched spring: its ends' velocity components va, vb along the unit
/// vector from its first end to its second [m/s], their masses wa, wb [kg], and `target`, the relative velocity
/// vb - va it may keep [m/s] (the Simulator passes the one that ends the step at exactly the threshold length).
/// walking Eq. 5: both components to their (mass-weighted) mean, keeping `target` between them (the papers' points
/// all have one mass; the weighted mean keeps momentum).
std::pair<Real, Real> average_stretch(Real va, Real vb, Real wa = 1, Real wb = 1, Real target = 0);
/// walking Eq. 6's rules: a spring about perpendicular to the directional vector (|cos_alpha| < 0.3) averages
/// (Eq. 5); on the others the rear point catches up with the front one (cos_alpha > 0: the rear point is the first
/// end). Unless `literal`, catching up that would add kinetic energy to the pair averages instead (our guard:
/// taken literally the rule diverged on a cloth draped over a sphere).
std::pair<Real, Real> directional_stretch(Real va, Real vb, Real cos_alpha, Real wa = 1, Real wb = 1, Real target = 0,
                                          bool literal = false);

}  // namespace clothbench
