#pragma once
/// The simulation loop of the papers: spring forces (Eq. 2), an integrator by name (explicit Euler, Eq. 3, at a
/// time step bounded by Eq. 4; implicit Euler; rk45), super-elasticity limits (dressing 4, walking 3), seaming,
/// and collision response from any Collider's contacts (dressing Eq. 12, walking Eq. 15-16).
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "clothbench/sim/body_frame.hpp"
#include "clothbench/sim/cloth.hpp"
#include "clothbench/sim/collider.hpp"
#include "clothbench/sim/integrator.hpp"
#include "clothbench/sim/layers.hpp"
#include "clothbench/sim/limiter.hpp"
#include "clothbench/sim/self_contact.hpp"

namespace clothbench {

/// Cloth material. Stiffness per spring kind is the k of Eq. 2; 0 = automatic (the papers' regime, see
/// SolverParams::regime): derived from the point masses and dt so that explicit Euler is stable at dt.
struct Material {
  Real density = 0.15f;      ///< mass per area [kg/m^2]
  Real k_structural = 60.f;  ///< [N/m]; 0 = automatic
  Real k_shear = 20.f;       ///< [N/m]; 0 = automatic (k_structural / 3)
  Real k_flexion = 10.f;     ///< [N/m]; 0 = automatic (k_structural / 6)
  /// Viscous damping per unit mass: the force -m_i c v_i (dressing section 3's -C_vd v with C_vd = m_i c)
  /// [1/s]. 12/s is the old 0.002 N s/m at the mean vertex mass (0.17 g) of the 400-vertex shirt.
  Real damping = 12.f;
  Real friction = 0.6f;      ///< C_fric of Eq. 12/15/16
  Real reflection = 0.0f;    ///< C_refl of Eq. 12/15
};


/// How panels are pulled together along seams.
enum class SeamMethod { kElastic, kAttraction };
const char* to_string(SeamMethod m);
SeamMethod parse_seam_method(const std::string& name);

/// How the point masses are set: kArea gives each vertex density x its share of the panel area (outline
/// slivers get little); kEqual gives every vertex total mass / nv ("the mass of each point", dressing Eq. 3).
enum class MassModel { kArea, kEqual };
const char* to_string(MassModel m);
MassModel parse_mass_model(const std::string& name);

/// Named presets of the solver (scenes/README.md). kStable: the defaults (equal masses, stiff springs,
/// automatic dt below Eq. 4 and Gershgorin). kPapers: the papers' clock: equal point masses, dt 5 ms, soft
/// springs derived from the mass per point and dt (Material k = 0), stretch held by the velocity limit.
enum class Regime { kStable, kPapers };
const char* to_string(Regime r);
Regime parse_regime(const std::string& name);
struct SolverParams;
/// Sets the fields the preset decides (keys given explicitly should be applied after it).
void apply_regime(Regime regime, Material& material, SolverParams& params);

/// Phases of a dressing or animation run (DESIGN.md): sew without gravity, drape, animate.
enum class Phase { kSew, kDrape, kAnimate };
const char* to_string(Phase p);

/// Solver parameters; every field has a documented default.
struct SolverParams {
  /// time step [s]; 0 = automatic: dt_fraction x min(Eq. 4 bound, spectral_dt) (explicit-euler, rk45), 10 ms
  /// (implicit-euler)
  Real dt = 0;
  std::string integrator = "explicit-euler";  ///< integrator_names(); only explicit-euler is bounded by Eq. 4
  IntegratorParams integration;               ///< tolerances of implicit-euler and rk45
  Real dt_fraction = 0.9f;               ///< automatic dt (and automatic stiffness) margin (0, 1]
  Regime regime = Regime::kStable;       ///< the preset these parameters came from (apply_regime); a label
  /// point masses: equal (dressing Eq. 3). With area masses a ring vertex snapped to the outline carries a sliver's
  /// share, and the lightest point bounds Eq. 4 and Gershgorin's step: equal ones admit a step several times longer
  MassModel masses = MassModel::kEqual;
  bool allow_unstable_dt = false;        ///< explicit-euler: accept a given dt above the Eq. 4 bound (stability studies)
  /// the strain limiter, by name (limiter_names(); limiter.hpp): walking Eq. 5 as warm-started impulses, whose one pass
  /// holds every limit on the static body where the velocity sweeps take eight (results/limiters.md)
  std::string limit = "impulses";
  Real threshold = 0.10f;                ///< elongation threshold of the limit, fraction (0.01..0.15 typical)
  Real stiff_factor = 10.f;              ///< the `stiff` limit multiplies every stiffness by this
  int limit_passes = 1;                  ///< passes of the limit over the springs per call (the most)
  /// velocity limits run once more after the collision response, each pass followed by stopping motion into the
  /// body of the vertices in contact (the response would otherwise undo the limit where the body holds the cloth).
  /// Both regimes; the walking scenes need it (the dress: impulses, 3 passes; the skirt: walking Eq. 5's sweeps, 16).
  /// results/limiters.md lists the cheapest setting per garment and clip
  bool limit_after_response = true;
  Real limit_speed = 2.f;                ///< velocity limits shorten a spring past threshold at most this fast [m/s]
  Real limit_tolerance = 0;              ///< a velocity limit pass's change that moves a point less than this over the
                                         ///< step does not make the next pass visit its springs [m] (0: any change)
  bool face_queries = false;             ///< also query quad midpoints (dressing section 6)
  bool push_out = true;                  ///< vertices found inside the body are moved to its surface (Durupinar Eq. 3)
  Real push_speed = 2.f;                 ///< push_out moves a vertex no faster than this [m/s]
  Real self_contact = 0;                 ///< cloth against itself: points nearer a triangle than this [m] are stopped (0: off)
  bool self_contact_last = false;        ///< cloth against itself answered again after the limit's second pass
  bool reaction_force = false;           ///< add the reaction force of walking Eq. 16
  Vec3 gravity = Vec3(0, -kGravity, 0);  ///< [m/s^2]
  SeamMethod seam_method = SeamMethod::kElastic;
  Real seam_stiffness = 0;       ///< elastic seam springs (rest length 0) [N/m]; 0 = as the structural springs
  Real seam_reach = 0.005f;      ///< elastic seams pull with k |d| up to this gap and no harder beyond it [m]
  Real seam_speed = 2.f;         ///< partners of an elastic seam approach each other no faster than this [m/s]
  Real attraction_speed = 0.5f;  ///< c_attraction of Durupinar Eq. 1 [m/s]
  /// seam pairs closer than this are merged [m]: above the 2 mm seam-gap limit, so a pair the body holds a little
  /// more than 2 mm apart (a sleeve's and an armhole's vertex under the arm) still merges
  Real merge_distance = 0.003f;
  Real max_speed = 50.f;         ///< divergence: any vertex faster than this [m/s]
  Real bounds_margin = 5.f;      ///< divergence: a vertex farther than this from its start box [m]
};

/// Why and where a run diverged.
struct Divergence {
  long iteration = 0;
  Phase phase = Phase::kSew;
  int vertex = -1;
  std::string reason;  ///< "NaN", "speed ...", "left the scene bounds"
};

/// Spring strain statistics over structural springs: (|p1 - p2| - l0) / l0.
struct StrainStats {
  Real max = 0;
  Real p99 = 0;
  int max_spring = -1;  ///< the spring with the largest strain (-1 when there is none)
  Real over = 0;        ///< share of the structural springs over the limits' strain (threshold + 1 %)
};

/// Where the seams are widest open: a seam pair's partners apart, or a seam vertex without a partner away
/// from the segment of partner edge it belongs on (ClothMesh::seam_loose).
struct SeamGap {
  Real gap = 0;        ///< [m]
  int vertex = -1;     ///< -1 when the mesh has no seams
  int partner = -1;    ///< the pair's other vertex, or the nearer end of that segment
  bool loose = false;  ///< `vertex` has no partner of its own
};

/// Cumulative per-phase timings [ms] and counts; CD&R and CS as in walking Table 1.
struct SimTimings {
  double cdr_ms = 0;  ///< collision detection (collider query) and response
  double cs_ms = 0;   ///< cloth simulation: forces (the reaction force of Eq. 16 included), integration, limits, seaming
  double limit_ms = 0;  ///< of cs_ms: the strain limiter (super-elasticity: dressing 4, walking 3)
  double cloth_ms = 0;  ///< of cdr_ms: cloth against cloth (itself, and the layers under it: drawn and queried)
  long limit_passes = 0;  ///< the limiter's passes over the springs (a sweep stops early once a pass changes nothing)
  long iterations = 0;
};

/// Velocity after a collision (dressing Eq. 12, walking Eq. 15): relative to the body,
/// v_res = C_fric v_t - C_refl v_n + v_object. The reflection applies only to a normal component
/// heading into the body (v_n . n < 0); a point already leaving keeps its normal component.
Vec3 collision_response(const Vec3& v, const Contact& contact, Real friction, Real reflection);


/// One cloth, one collider (not owned), one integrator.
class Simulator {
 public:
  /// Validates every parameter and throws std::invalid_argument naming the bad one.
  Simulator(ClothMesh mesh, const Material& material, const SolverParams& params);

  /// The collider to query each iteration (may be null: no collisions). Not owned.
  void set_collider(Collider* collider) { collider_ = collider; }
  /// Cloth against the dressed layers under it: the vertices from `under` on (and their quads' midpoints with
  /// face_queries) are answered as against the body (dressing Eq. 12, push_out, and held out again after the
  /// limit's second pass) against the cloth before
  /// `under`, given to `collider` as a moving body again once a point of it has moved `redraw` [m] (LayersUnder).
  /// Not owned; null: none.
  void set_layers_under(Collider* collider, Eigen::Index under, Real redraw);
  /// The layers under's draws so far (0 without).
  long layer_draws() const { return layers_ ? layers_->draws() : 0; }
  /// Sets the phase: kSew turns gravity off (and Durupinar's attraction on); kDrape/kAnimate turn
  /// gravity on. Elastic seams pull in every phase until their pairs merge.
  void set_phase(Phase phase) { phase_ = phase; }
  Phase phase() const { return phase_; }

  /// One iteration (forces, the integrator's update, limits, seaming and response). Returns false once diverged.
  bool step();

  /// Binds the mesh's `attached` vertices within `reach` of `body` to their closest triangles (Durupinar 3.2:
  /// "after the virtual human is dressed in the garment, the selected particles are attached to the closest
  /// polygon"); until then they move freely (so sewing can first bring a waistband to the body). One farther off
  /// stays free: bound, it would hold the garment in mid-air. Returns how many were bound.
  int attach(const BodyFrame& body, Real reach = std::numeric_limits<Real>::infinity());
  /// Moves attached vertices with the body (same topology as in attach()), each held at its offset from its
  /// binding point as the triangle turns, to where they were `time_before` seconds before the body's pose (first
  /// order in the body velocity), with the body's velocity.
  void follow_attachments(const BodyFrame& body, Real time_before = 0);
  /// Of each bound vertex (attach()), its offset from the body point it is bound to, in its triangle's frame: its
  /// length is the distance [m] (3 x bound).
  const Points3& attachment_offsets() const { return attach_local_; }

  const char* integrator() const { return integrator_->name(); }
  /// Force evaluations, sub-steps, CG iterations and times of the integrator so far.
  const IntegratorStats& integrator_stats() const { return integrator_->stats(); }

  /// The Eq. 4 bound 0.4 pi sqrt(m_min / K_max) [s] for the current stiffnesses.
  Real stable_dt() const;
  /// 2 / omega_max with omega_max^2 from Gershgorin's bound on M^-1 K (every spring and seam at
  /// every vertex) [s]: symplectic Euler is stable below it. Eq. 4 only looks at the stiffest single
  /// spring; a light boundary vertex with many springs can need less, so the automatic dt takes
  /// the smaller of the two.
  Real spectral_dt() const;
  Real dt() const { return dt_; }
  /// Stiffness per kind as used [N/m] (automatic ones resolved, the stiff limit's factor applied).
  Real stiffness(SpringKind kind) const { return k_kind_[static_cast<int>(kind)]; }

  const ClothMesh& mesh() const { return mesh_; }
  const Points3& positions() const { return x_; }   ///< [m] (3 x nv)
  const Points3& velocities() const { return v_; }  ///< [m/s] (3 x nv)
  Points3& positions() { return x_; }
  Points3& velocities() { return v_; }
  const Scalars& masses() const { return m_; }  ///< [kg] (nv)
  /// Quad midpoints of the current positions (3 x nq); what face queries test.
  const Points3& quad_midpoints() const { return mid_; }

  /// The widest opening along the seams, over every vertex of a sewn edge (paired or not).
  SeamGap widest_seam_gap() const;
  /// Its width [m] (0 when the mesh has no seams).
  Real seam_gap_max() const { return widest_seam_gap().gap; }
  /// Largest distance between seam pair partners [m]: what sewing waits on (a vertex without a partner
  /// follows its neighbours).
  Real seam_pair_gap_max() const;
  /// Share of seam pairs merged, 0..1.
  Real sewn_fraction() const;
  /// For a sewing that has stopped closing (bench's sew phase): when every open seam pair is within twice
  /// merge_distance, merges them all now, as every step merges those within merge_distance. Returns how many.
  int merge_stalled_seams();
  /// The vertices joined by merged seam pairs, a group each: one point of the cloth.
  const std::vector<std::vector<int>>& sewn_points() const { return merged_groups_; }
  StrainStats strain() const;
  /// Largest vertex speed [m/s] and kinetic energy [J].
  Real max_speed() const;
  Real kinetic_energy() const;

  const SimTimings& timings() const { return timings_; }
  long iteration() const { return iteration_; }
  const std::optional<Divergence>& divergence() const { return divergence_; }
  /// Contacts of the vertices at the last iteration (nv, then nq for face queries).
  const std::vector<Contact>& contacts() const { return contacts_; }

 private:
  void detect();
  ForceModel force_model() const;
  Vec3 phase_gravity() const;  ///< the gravity acting in the current phase
  void cap_seam_speeds();
  void attract_seams();
  void respond();
  void respond_at(Eigen::Index i, const Contact& c);  // one vertex's response to a contact
  // the responses of the midpoints of the quads from first_quad on (their contacts in order) to their vertices
  void respond_faces(Eigen::Index first_quad, const Contact* contacts);
  void respond_to_layers();
  // no vertex from `first` on in contact (contacts[i - first]) keeps a velocity into what it touches (relative to it)
  void hold_out(Eigen::Index first, const Contact* contacts);
  void integrate_positions();
  int merge_seams(Real within);  // the pairs closer than `within` merged; how many
  void group_merged_pairs();
  bool check_divergence();

  ClothMesh mesh_;
  Material material_;
  SolverParams params_;
  void set_stiffness();

  Real k_kind_[kSpringKinds] = {};  // stiffness per spring kind [N/m]
  Scalars k_;          // stiffness per spring [N/m] (ns)
  Scalars seam_k_;     // elastic seam stiffness per seam pair [N/m] (np)
  Scalars m_;          // mass per vertex [kg] (nv)
  Scalars inv_m_;      // 1/m, 0 for attached vertices (nv)
  Points3 x_, v_, f_;  // positions [m], velocities [m/s], forces [N] (3 x nv)
  Points3 drift_;      // the integrator's position change besides dt v (3 x nv, or empty when none)
  IntegratorPtr integrator_;
  LimiterPtr limiter_;
  /// The limiter's view of the state for one call.
  LimitState limit_state();
  Points3 mid_;        // quad midpoints [m] (3 x nq)
  std::vector<Contact> contacts_;
  std::vector<std::uint8_t> merged_;  // per seam pair
  std::vector<int> attach_vertex_;    // the bound vertices (attach())
  std::vector<int> attach_tri_;       // per bound vertex
  Points3 attach_bary_;               // (3 x nb)
  Points3 attach_local_;  // bound vertex minus its binding point, in its triangle's frame [m] (3 x nb)
  std::vector<std::vector<int>> merged_groups_;  // vertices joined by merged pairs: one point each
  SelfContacts self_;                            // cloth against itself (SolverParams::self_contact)
  std::optional<LayersUnder> layers_;            // cloth against the layers under it (set_layers_under)
  Box3 start_box_;
  Collider* collider_ = nullptr;
  Phase phase_ = Phase::kDrape;
  Real dt_ = 0;
  long iteration_ = 0;
  SimTimings timings_;
  std::optional<Divergence> divergence_;
};

}  // namespace clothbench
