#include "clothbench/sim/simulator.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "clothbench/sim/mesh_query.hpp"
#include "clothbench/sim/param_fields.hpp"
#include "clothbench/sim/timer.hpp"
#include "merged_points.hpp"

namespace clothbench {

const char* to_string(SeamMethod m) { return m == SeamMethod::kElastic ? "elastic" : "attraction"; }

SeamMethod parse_seam_method(const std::string& name) {
  if (name == "elastic") return SeamMethod::kElastic;
  if (name == "attraction") return SeamMethod::kAttraction;
  throw std::invalid_argument("seam_method: unknown method '" + name + "' (elastic, attraction)");
}

const char* to_string(MassModel m) { return m == MassModel::kArea ? "area" : "equal"; }

MassModel parse_mass_model(const std::string& name) {
  if (name == "area") return MassModel::kArea;
  if (name == "equal") return MassModel::kEqual;
  throw std::invalid_argument("masses: unknown model '" + name + "' (area, equal)");
}

const char* to_string(Regime r) { return r == Regime::kStable ? "stable" : "papers"; }

Regime parse_regime(const std::string& name) {
  if (name == "stable") return Regime::kStable;
  if (name == "papers") return Regime::kPapers;
  throw std::invalid_argument("regime: unknown preset '" + name + "' (stable, papers)");
}

void apply_regime(Regime regime, Material& material, SolverParams& params) {
  const Material stable_material;
  const SolverParams stable;
  params.regime = regime;
  const bool papers = regime == Regime::kPapers;
  // the papers' clock: equal point masses (dressing Eq. 3), dt 5 ms, springs soft enough for it (automatic)
  params.masses = papers ? MassModel::kEqual : stable.masses;
  params.dt = papers ? Real(0.005) : stable.dt;
  // velocity modification carries the stretch: the walking paper's directional limit (Eq. 6), passes over the
  // springs after the forces and again after the response (with the contacts), held points first: 32 passes
  // (four left 1 % of the 1,800-vertex shirt's springs past threshold + 1 %, sixteen 0.2 %; results/integrators.md)
  params.limit = papers ? "directional" : stable.limit;
  params.limit_passes = papers ? 32 : stable.limit_passes;
  params.seam_stiffness = stable.seam_stiffness;
  params.limit_after_response = papers || stable.limit_after_response;
  // soft seams close slowly over their last millimetres: pairs within 5 mm are sewn (2 mm stable)
  params.merge_distance = papers ? Real(0.005) : stable.merge_distance;
  // soft seams pull k |d| up to a 5 cm gap (5 mm with the stable regime's stiff ones): about the stable pull
  params.seam_reach = papers ? Real(0.05) : stable.seam_reach;
  material.k_structural = papers ? Real(0) : stable_material.k_structural;
  material.k_shear = papers ? Real(0) : stable_material.k_shear;
  material.k_flexion = papers ? Real(0) : stable_material.k_flexion;
}

const char* to_string(Phase p) {
  switch (p) {
    case Phase::kSew: return "sew";
    case Phase::kDrape: return "drape";
    case Phase::kAnimate: return "animate";
  }
  return "?";
}

Vec3 collision_response(const Vec3& v, const Contact& c, Real friction, Real reflection) {
  // dressing Eq. 12 / walking Eq. 15, on the velocity relative to the body
  const Vec3 rel = v - c.body_velocity;
  const Real vn_len = rel.dot(c.normal);
  const Vec3 vn = vn_len * c.normal;
  const Vec3 vt = rel - vn;
  const Vec3 vn_res = vn_len < 0 ? Vec3(-reflection * vn) : vn;
  return friction * vt + vn_res + c.body_velocity;
}

namespace {

// throws naming the parameter unless lo < value < hi (or <= when inclusive)
void require(bool ok, const char* name, const std::string& rule, double value) {
  if (!ok || !std::isfinite(value))
    throw std::invalid_argument(std::string(name) + " = " + std::to_string(value) + ": must be " + rule);
}

// the rows' bounds (param_fields.hpp), and what no single row says
void validate(const Material& m, const SolverParams& p) {
  fields::check_fields(m);
  fields::check_fields(p);
  const bool auto_k = m.k_structural == 0 || m.k_shear == 0 || m.k_flexion == 0;
  require(!auto_k || p.dt > 0, "dt", "given (> 0 s) when a stiffness is automatic (0)", p.dt);
}

// the orthonormal frame of body triangle t (its first edge, its normal, and their cross product, as columns): an
// attached vertex's offset turns with it
Eigen::Matrix3f triangle_frame(const BodyFrame& body, int t) {
  const Vec3 p0 = body.positions.col(body.triangles(0, t));
  const Vec3 e1 = body.positions.col(body.triangles(1, t)) - p0, e2 = body.positions.col(body.triangles(2, t)) - p0;
  Eigen::Matrix3f frame;
  frame.col(0) = e1.normalized();
  frame.col(1) = e1.cross(e2).normalized();
  frame.col(2) = frame.col(0).cross(frame.col(1));
  return frame;
}

// column i of a 3 x n matrix as a fixed-size vector reference
inline Eigen::Ref<Vec3> col(Points3& m, Eigen::Index i) { return m.col(i); }

// Gershgorin's row sums of M^-1 K: a spring of stiffness k between a and b adds k / m_a + k / sqrt(m_a m_b)
// to row a and the mirrored terms to row b
void add_gershgorin(Scalars& row, const Scalars& m, int a, int b, Real k) {
  const Real cross = k / std::sqrt(m[a] * m[b]);
  row[a] += k / m[a] + cross;
  row[b] += k / m[b] + cross;
}

}  // namespace

Simulator::Simulator(ClothMesh mesh, const Material& material, const SolverParams& params)
    : mesh_(std::move(mesh)), material_(material), params_(params) {
  mesh_.validate("cloth");
  validate(material_, params_);
  integrator_ = IntegratorPtr(make_integrator(params_.integrator, params_.integration));
  limiter_ = LimiterPtr(make_limiter(params_.limit, {params_.threshold, params_.limit_passes, params_.limit_speed,
                                                     params_.limit_tolerance, params_.stiff_factor}));
  const Eigen::Index nv = mesh_.positions.cols();
  m_ = mesh_.vertex_area * material_.density;
  // dressing Eq. 3: "m is the mass of each point", one mass for all
  if (params_.masses == MassModel::kEqual) m_.setConstant(m_.sum() / Real(std::max<Eigen::Index>(nv, 1)));
  set_stiffness();
  inv_m_ = m_.cwiseInverse();
  x_ = mesh_.positions;
  v_ = Points3::Zero(3, nv);
  f_ = Points3::Zero(3, nv);
  mid_.resize(3, mesh_.quads.cols());
  merged_.assign(static_cast<std::size_t>(mesh_.seam_pairs.cols()), 0);
  start_box_ = bounding_box(x_);
  // time step: given (explicit Euler's checked against Eq. 4), or the integrator's automatic one
  const Real bound = stable_dt();
  if (params_.dt == 0) {
    dt_ = integrator_->automatic_dt(params_.dt_fraction * std::min(bound, spectral_dt()));
  } else if (params_.dt > bound && integrator_->bounded_by_eq4() && !params_.allow_unstable_dt) {
    throw std::invalid_argument("dt = " + std::to_string(params_.dt) + " s exceeds the stability bound " +
                                std::to_string(bound) +
                                " s of dressing Eq. 4 (0.4 pi sqrt(m/K)); set allow_unstable_dt to run it anyway");
  } else {
    dt_ = params_.dt;
  }
}

void Simulator::set_stiffness() {
  // stiffness per spring from its kind (Eq. 2); kStiff raises all of them
  const Real factor = limiter_->stiffness_factor();
  const Real given[kSpringKinds] = {material_.k_structural, material_.k_shear, material_.k_flexion};
  const Real ratio[kSpringKinds] = {1, Real(1) / 3, Real(1) / 6};  // automatic ones keep the defaults' 60:20:10
  const bool seam_auto = params_.seam_stiffness == 0;
  const bool elastic = params_.seam_method == SeamMethod::kElastic;
  Real k_auto = 0;  // automatic structural stiffness [N/m]
  if (given[0] == 0 || given[1] == 0 || given[2] == 0) {
    // the largest K for which Gershgorin's bound (every spring and seam at every vertex) and Eq. 4 both admit
    // dt / dt_fraction: each vertex row is fixed + K x scaled; the automatic seams follow k_structural
    const Eigen::Index nv = m_.size();
    Scalars fixed = Scalars::Zero(nv), scaled = Scalars::Zero(nv);
    const auto add = [&](int a, int b, Real k, bool automatic) {
      add_gershgorin(automatic ? scaled : fixed, m_, a, b, k);
    };
    for (Eigen::Index s = 0; s < mesh_.springs.cols(); ++s) {
      const int kind = static_cast<int>(mesh_.kind[s]);
      add(mesh_.springs(0, s), mesh_.springs(1, s), given[kind] == 0 ? ratio[kind] : given[kind], given[kind] == 0);
    }
    if (elastic)
      for (Eigen::Index p = 0; p < mesh_.seam_pairs.cols(); ++p) {
        const bool automatic = seam_auto && given[0] == 0;
        add(mesh_.seam_pairs(0, p), mesh_.seam_pairs(1, p),
            seam_auto ? (automatic ? Real(1) : given[0]) : params_.seam_stiffness, automatic);
      }
    const Real omega = 2 * params_.dt_fraction / params_.dt;  // Gershgorin: dt <= 2 / omega_max
    k_auto = std::numeric_limits<Real>::max();
    for (Eigen::Index v = 0; v < nv; ++v)
      if (scaled[v] > 0) k_auto = std::min(k_auto, (omega * omega - fixed[v]) / scaled[v]);
    // dressing Eq. 4 at dt / dt_fraction for the stiffest automatic spring (ratio 1)
    const Real eq4 = Real(0.4 * M_PI) * params_.dt_fraction / params_.dt;
    if (nv) k_auto = std::min(k_auto, eq4 * eq4 * m_.minCoeff());
    if (!(k_auto > 0) || k_auto == std::numeric_limits<Real>::max())
      throw std::invalid_argument(
          "automatic stiffness: the given stiffnesses alone exceed the stability bound of dt = " +
          std::to_string(params_.dt) + " s; give a smaller dt or softer springs");
  }
  for (int kind = 0; kind < kSpringKinds; ++kind)
    k_kind_[kind] = factor * (given[kind] == 0 ? ratio[kind] * k_auto : given[kind]);
  k_.resize(mesh_.springs.cols());
  for (Eigen::Index s = 0; s < k_.size(); ++s) k_[s] = k_kind_[static_cast<int>(mesh_.kind[s])];
  // elastic seams: a zero-length spring per pair, given, or as stiff as the structural springs (the
  // cloth's own scale at any resolution; a sliver vertex on an outline is no more at risk from it
  // than from its grid springs, and seam_reach and seam_speed bound the pull from afar)
  seam_k_ = Scalars::Constant(mesh_.seam_pairs.cols(), seam_auto ? k_kind_[0] : params_.seam_stiffness);
}

Real Simulator::stable_dt() const {
  // dressing Eq. 4: dt <= 0.4 pi sqrt(m / K), K the highest stiffness, m the lightest point
  Real k_max = k_.size() ? k_.maxCoeff() : Real(0);
  if (mesh_.seam_pairs.cols() && params_.seam_method == SeamMethod::kElastic)
    k_max = std::max(k_max, seam_k_.size() ? seam_k_.maxCoeff() : Real(0));
  if (!(k_max > 0)) return Real(1e-2);
  return Real(0.4 * M_PI) * std::sqrt(m_.minCoeff() / k_max);
}

Real Simulator::spectral_dt() const {
  // Gershgorin: omega^2 <= max_v sum_s k_s (1/m_v + 1/sqrt(m_v m_u)) over the springs s = (v, u)
  Scalars row = Scalars::Zero(m_.size());
  for (Eigen::Index s = 0; s < mesh_.springs.cols(); ++s)
    add_gershgorin(row, m_, mesh_.springs(0, s), mesh_.springs(1, s), k_[s]);
  if (params_.seam_method == SeamMethod::kElastic)
    for (Eigen::Index p = 0; p < mesh_.seam_pairs.cols(); ++p)
      add_gershgorin(row, m_, mesh_.seam_pairs(0, p), mesh_.seam_pairs(1, p), seam_k_[p]);
  const Real omega2 = row.size() ? row.maxCoeff() : Real(0);
  return omega2 > 0 ? Real(2) / std::sqrt(omega2) : Real(1e-2);
}

bool Simulator::step() {
  if (divergence_) return false;
  Stopwatch cdr;
  detect();
  double cdr_ms = cdr.ms();
  Stopwatch cs;
  const ForceModel model = force_model();
  if (integrator_->needs_forces()) model.eval(x_, v_, f_);
  integrator_->advance(model, dt_, x_, f_, v_, drift_);
  // limits, seam caps and the response act on the velocity that moves the points over the step
  const bool drifts = drift_.cols() == x_.cols();
  if (drifts) v_ += drift_ / dt_;
  Stopwatch limit;
  LimitState state = limit_state();
  limiter_->limit_velocities(state, false);
  double limit_ms = limit.ms();
  if (params_.seam_method == SeamMethod::kElastic) cap_seam_speeds();
  if (phase_ == Phase::kSew && params_.seam_method == SeamMethod::kAttraction) attract_seams();
  double cs_ms = cs.ms();
  cdr.restart();
  respond();
  Stopwatch cloth;
  const bool cloth_on = params_.self_contact > 0 || layers_;  // cloth against cloth timed only where it is on
  if (params_.self_contact > 0) self_.respond(mesh_, merged_groups_, x_, v_, inv_m_, params_.self_contact);
  respond_to_layers();
  double cloth_ms = cloth_on ? cloth.ms() : 0;
  cdr_ms += cdr.ms();
  cs.restart();
  // the limit again, each pass followed by the contacts' non-penetration: the body stops the cloth's motion
  // into it, the limit its stretch along it (a Gauss-Seidel sweep over both constraints)
  limit.restart();
  if (params_.limit_after_response && collider_) limiter_->limit_velocities(state, true);
  limit_ms += limit.ms();
  if (layers_) {
    cloth.restart();
    hold_out(layers_->under(), layers_->contacts().data());
    cloth_ms += cloth.ms();
  }
  // cloth against itself once more, last: the limit's second pass moves points along their springs and can carry
  // one through the cloth the first answer stopped it at; then the body's non-penetration again, which that answer
  // may have undone for a point between the body and the cloth
  if (params_.self_contact > 0 && params_.self_contact_last) {
    cdr.restart();
    self_.respond(mesh_, merged_groups_, x_, v_, inv_m_, params_.self_contact);
    if (collider_) hold_out(0, contacts_.data());
    if (layers_) hold_out(layers_->under(), layers_->contacts().data());
    const double ms = cdr.ms();
    cdr_ms += ms, cloth_ms += ms;
  }
  integrate_positions();
  if (drifts) v_ -= drift_ / dt_;  // back to the end-of-step velocity, with what limits and response changed
  limit.restart();
  limiter_->limit_positions(state);
  limit_ms += limit.ms();
  merge_seams(params_.merge_distance);
  cs_ms += cs.ms();
  timings_.cdr_ms += cdr_ms;
  timings_.cs_ms += cs_ms;
  timings_.limit_ms += limit_ms;
  timings_.cloth_ms += cloth_ms;
  timings_.limit_passes = limiter_->passes();
  ++timings_.iterations;
  ++iteration_;
  return check_divergence();
}

void Simulator::detect() {
  const Eigen::Index nv = x_.cols(), nq = params_.face_queries ? mesh_.quads.cols() : 0;
  contacts_.resize(static_cast<std::size_t>(nv + nq));
  if (!collider_) {
    std::fill(contacts_.begin(), contacts_.end(), Contact{});
    return;
  }
  collider_->query(PointsView(x_), {contacts_.data(), static_cast<std::size_t>(nv)});
  if (nq == 0) return;
  // quad midpoints: dressing section 6
  for (Eigen::Index q = 0; q < nq; ++q)
    mid_.col(q) = 0.25f * (x_.col(mesh_.quads(0, q)) + x_.col(mesh_.quads(1, q)) + x_.col(mesh_.quads(2, q)) +
                           x_.col(mesh_.quads(3, q)));
  collider_->query(PointsView(mid_.data(), static_cast<std::size_t>(nq)),
                   {contacts_.data() + nv, static_cast<std::size_t>(nq)});
}

LimitState Simulator::limit_state() {
  return {mesh_, x_, v_, m_, inv_m_, contacts_, merged_groups_, phase_gravity(), dt_};
}

Vec3 Simulator::phase_gravity() const {
  // gravity is off while sewing (Phase::kSew: the seams pull the panels in, gravity drapes them afterwards)
  return phase_ == Phase::kSew ? Vec3::Zero() : params_.gravity;
}

ForceModel Simulator::force_model() const {
  // elastic seams pull in every phase until their pairs merge
  const Vec3 g = phase_gravity();
  const bool elastic = params_.seam_method == SeamMethod::kElastic;
  return ForceModel{mesh_, k_, seam_k_, merged_, m_, inv_m_, contacts_, g, material_.damping, elastic,
                    params_.seam_reach, params_.reaction_force, material_.friction};
}

void Simulator::cap_seam_speeds() {
  // partners of an open seam approach each other at seam_speed at most, and no faster than closes the gap in
  // one step (no overshoot at a large dt; below dt = merge_distance / seam_speed this never binds): the excess
  // of their closing speed is removed along the seam, shared by inverse mass (momentum is kept)
  for (Eigen::Index p = 0; p < mesh_.seam_pairs.cols(); ++p) {
    if (merged_[static_cast<std::size_t>(p)]) continue;
    const int a = mesh_.seam_pairs(0, p), b = mesh_.seam_pairs(1, p);
    const Vec3 d = x_.col(a) - x_.col(b);
    const Real len = d.norm(), w = inv_m_[a] + inv_m_[b];
    if (!(len > 0) || !(w > 0)) continue;
    const Vec3 dir = d / len;
    const Real excess = -(v_.col(a) - v_.col(b)).dot(dir) - std::min(params_.seam_speed, len / dt_);
    if (excess <= 0) continue;
    col(v_, a) += (excess * inv_m_[a] / w) * dir;
    col(v_, b) -= (excess * inv_m_[b] / w) * dir;
  }
}

void Simulator::attract_seams() {
  // Durupinar Eq. 1: p1vel = c_attraction (p2 - p1)/|p2 - p1|, p2vel = -p1vel
  for (Eigen::Index p = 0; p < mesh_.seam_pairs.cols(); ++p) {
    if (merged_[static_cast<std::size_t>(p)]) continue;
    const int a = mesh_.seam_pairs(0, p), b = mesh_.seam_pairs(1, p);
    const Vec3 d = x_.col(b) - x_.col(a);
    const Real len = d.norm();
    if (!(len > 0)) continue;
    // never overshoot: at most half the gap per step
    const Real speed = std::min(params_.attraction_speed, 0.5f * len / dt_);
    if (inv_m_[a] > 0) col(v_, a) = speed * d / len;
    if (inv_m_[b] > 0) col(v_, b) = -speed * d / len;
  }
}

void Simulator::hold_out(Eigen::Index first, const Contact* contacts) {
  for (Eigen::Index i = first; i < x_.cols(); ++i) {
    const Contact& c = contacts[i - first];
    if (c.hit && inv_m_[i] != 0) stop_into_body(col(v_, i), c);
  }
}

void Simulator::respond_at(Eigen::Index i, const Contact& c) {
  if (!c.hit || inv_m_[i] == 0) return;
  col(v_, i) = collision_response(v_.col(i), c, material_.friction, material_.reflection);
  // Durupinar Eq. 3: a point that has passed beneath the surface is brought back to it along the normal, no
  // faster than push_speed (a body that swallowed the cloth between frames lets it out over a few steps,
  // not with a jump its springs would turn into a speed)
  if (params_.push_out && c.depth < 0) col(x_, i) += std::min(-c.depth, params_.push_speed * dt_) * c.normal;
}

void Simulator::set_layers_under(Collider* collider, Eigen::Index under, Real redraw) {
  layers_.reset();
  if (collider) layers_.emplace(*collider, mesh_, under, redraw, params_.face_queries);
}

void Simulator::respond_to_layers() {
  if (!layers_) return;
  layers_->detect(x_, v_);
  const auto& contacts = layers_->contacts();
  const auto above = static_cast<std::size_t>(x_.cols() - layers_->under());
  for (std::size_t k = 0; k < above; ++k) respond_at(layers_->under() + Eigen::Index(k), contacts[k]);
  if (params_.face_queries) respond_faces(layers_->first_quad(), contacts.data() + above);
}

void Simulator::respond() {
  if (!collider_) return;
  const Eigen::Index nv = x_.cols();
  // vertex contacts first
  for (Eigen::Index i = 0; i < nv; ++i) respond_at(i, contacts_[static_cast<std::size_t>(i)]);
  if (params_.face_queries) respond_faces(0, contacts_.data() + nv);
}

void Simulator::respond_faces(Eigen::Index first_quad, const Contact* contacts) {
  // face-body: the quad midpoint's response goes to its four vertices, averaged (dressing section 6),
  // as the change it makes to the midpoint's velocity: the vertices keep their motion relative to
  // each other (a seam closing across a quad is not stopped by it)
  const auto nv = static_cast<std::size_t>(x_.cols());
  std::vector<Vec3> face_sum(nv, Vec3::Zero());
  std::vector<int> face_count(nv, 0);
  for (Eigen::Index q = first_quad; q < mesh_.quads.cols(); ++q) {
    const Contact& c = contacts[q - first_quad];
    if (!c.hit) continue;
    Vec3 vq = Vec3::Zero();
    for (int k = 0; k < 4; ++k) vq += 0.25f * v_.col(mesh_.quads(k, q));
    const Vec3 dv = collision_response(vq, c, material_.friction, material_.reflection) - vq;
    for (int k = 0; k < 4; ++k) {
      face_sum[static_cast<std::size_t>(mesh_.quads(k, q))] += dv;
      ++face_count[static_cast<std::size_t>(mesh_.quads(k, q))];
    }
  }
  for (std::size_t i = 0; i < nv; ++i)
    if (face_count[i] && inv_m_[Eigen::Index(i)] > 0) col(v_, Eigen::Index(i)) += face_sum[i] / Real(face_count[i]);
}

void Simulator::integrate_positions() {
  // dressing Eq. 3: p += dt v (for rk45, v is the step's mean velocity here: its drift is folded in)
  x_ += dt_ * v_;
}

int Simulator::merge_seams(Real within) {
  // sewn pairs closer than `within` become one point (Durupinar 3.1); where seams meet (a sleeve,
  // the front and the back at the armpit) the pairs chain, and all of the chain is that one point
  int grown = 0;
  for (Eigen::Index p = 0; p < mesh_.seam_pairs.cols(); ++p) {
    auto& merged = merged_[static_cast<std::size_t>(p)];
    if (merged || !((x_.col(mesh_.seam_pairs(0, p)) - x_.col(mesh_.seam_pairs(1, p))).norm() < within)) continue;
    merged = 1;
    ++grown;
  }
  if (grown) group_merged_pairs();
  move_as_one(merged_groups_, m_, inv_m_, v_, &x_, [](int, Real) {});
  return grown;
}

int Simulator::merge_stalled_seams() {
  const Real within = 2 * params_.merge_distance;
  return seam_pair_gap_max() < within ? merge_seams(within) : 0;
}

void Simulator::group_merged_pairs() {
  // connected components of the merged pairs (union-find over the vertices)
  std::vector<int> root(static_cast<std::size_t>(x_.cols()));
  for (std::size_t i = 0; i < root.size(); ++i) root[i] = static_cast<int>(i);
  const auto up = [&](int i) -> int& { return root[static_cast<std::size_t>(i)]; };
  const auto find = [&](int i) {
    while (up(i) != i) i = up(i) = up(up(i));  // path halving
    return i;
  };
  std::vector<int> members;
  for (Eigen::Index p = 0; p < mesh_.seam_pairs.cols(); ++p) {
    if (!merged_[static_cast<std::size_t>(p)]) continue;
    const int a = mesh_.seam_pairs(0, p), b = mesh_.seam_pairs(1, p);
    up(find(a)) = find(b);
    members.push_back(a);
    members.push_back(b);
  }
  std::sort(members.begin(), members.end());
  members.erase(std::unique(members.begin(), members.end()), members.end());
  std::vector<int> group_of(root.size(), -1);
  merged_groups_.clear();
  for (int i : members) {  // in vertex order, so the result is deterministic
    auto& g = group_of[static_cast<std::size_t>(find(i))];
    if (g < 0) g = static_cast<int>(merged_groups_.size()), merged_groups_.emplace_back();
    merged_groups_[static_cast<std::size_t>(g)].push_back(i);
  }
}

bool Simulator::check_divergence() {
  // NaN, runaway speed, or a vertex far outside the scene: stop and say where and when
  const Real max_speed2 = params_.max_speed * params_.max_speed;
  const Vec3 lo = start_box_.min.array() - params_.bounds_margin;
  const Vec3 hi = start_box_.max.array() + params_.bounds_margin;
  for (Eigen::Index i = 0; i < x_.cols(); ++i) {
    const Vec3 x = x_.col(i), v = v_.col(i);
    std::string reason;
    if (!x.allFinite() || !v.allFinite())
      reason = "NaN or infinite position/velocity";
    else if (v.squaredNorm() > max_speed2)
      reason = "speed " + std::to_string(v.norm()) + " m/s above max_speed";
    else if ((x.array() < lo.array()).any() || (x.array() > hi.array()).any())
      reason = "left the scene bounds";
    if (reason.empty()) continue;
    divergence_ = Divergence{iteration_, phase_, static_cast<int>(i), reason};
    return false;
  }
  return true;
}

int Simulator::attach(const BodyFrame& body, Real reach) {
  // bind each attached vertex within reach to its closest body triangle (Durupinar 3.2); from now on it is moved by
  // the body only (1/m = 0), at its offset in that triangle's frame
  attach_vertex_.clear(), attach_tri_.clear();
  attach_bary_.resize(3, static_cast<Eigen::Index>(mesh_.attached.size()));
  attach_local_.resize(3, attach_bary_.cols());
  for (const int i : mesh_.attached) {
    const ClosestPoint cp = closest_point_brute(body, x_.col(i));
    const Vec3 offset = x_.col(i) - cp.point;
    if (!(offset.norm() <= reach)) continue;
    const auto k = static_cast<Eigen::Index>(attach_vertex_.size());
    attach_vertex_.push_back(i);
    attach_tri_.push_back(cp.triangle);
    attach_bary_.col(k) = cp.bary;
    attach_local_.col(k) = cp.triangle >= 0 ? Vec3(triangle_frame(body, cp.triangle).transpose() * offset) : offset;
    inv_m_[i] = 0;
    v_.col(i).setZero();
  }
  const auto bound = static_cast<Eigen::Index>(attach_vertex_.size());
  attach_bary_.conservativeResize(3, bound);
  attach_local_.conservativeResize(3, bound);
  return static_cast<int>(bound);
}

void Simulator::follow_attachments(const BodyFrame& body, Real time_before) {
  for (std::size_t i = 0; i < attach_tri_.size(); ++i) {
    if (attach_tri_[i] < 0) continue;
    const auto j = static_cast<Eigen::Index>(i);
    Vec3 x = Vec3::Zero(), v = Vec3::Zero();
    for (int k = 0; k < 3; ++k) {
      const int bv = body.triangles(k, attach_tri_[i]);
      x += attach_bary_(k, j) * body.positions.col(bv);
      v += attach_bary_(k, j) * body.velocities.col(bv);
    }
    // where the binding point was time_before seconds before the pose (first order)
    col(x_, attach_vertex_[i]) = x + triangle_frame(body, attach_tri_[i]) * attach_local_.col(j) - time_before * v;
    col(v_, attach_vertex_[i]) = v;
  }
}

namespace {

Real distance_to_segment(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const Real len2 = ab.squaredNorm();
  const Real t = len2 > 0 ? std::clamp((p - a).dot(ab) / len2, Real(0), Real(1)) : Real(0);
  return (p - (a + t * ab)).norm();
}

}  // namespace

SeamGap Simulator::widest_seam_gap() const {
  SeamGap widest;
  widest.gap = -1;  // a NaN distance is never the widest
  const auto consider = [&](Real d, int a, int b, bool loose) {
    if (d > widest.gap) widest = {d, a, b, loose};
  };
  for (Eigen::Index p = 0; p < mesh_.seam_pairs.cols(); ++p) {
    const int a = mesh_.seam_pairs(0, p), b = mesh_.seam_pairs(1, p);
    consider((x_.col(a) - x_.col(b)).norm(), a, b, false);
  }
  for (Eigen::Index l = 0; l < mesh_.seam_loose.cols(); ++l) {
    const int v = mesh_.seam_loose(0, l), b0 = mesh_.seam_loose(1, l), b1 = mesh_.seam_loose(2, l);
    const Vec3 x = x_.col(v);
    const int nearer = (x_.col(b0) - x).squaredNorm() <= (x_.col(b1) - x).squaredNorm() ? b0 : b1;
    consider(distance_to_segment(x, x_.col(b0), x_.col(b1)), v, nearer, true);
  }
  if (widest.vertex < 0) widest.gap = 0;
  return widest;
}

Real Simulator::seam_pair_gap_max() const {
  Real gap = 0;
  for (Eigen::Index p = 0; p < mesh_.seam_pairs.cols(); ++p)
    gap = std::max(gap, (x_.col(mesh_.seam_pairs(0, p)) - x_.col(mesh_.seam_pairs(1, p))).norm());
  return gap;
}

Real Simulator::sewn_fraction() const {
  if (merged_.empty()) return 1;
  return Real(std::count(merged_.begin(), merged_.end(), 1)) / Real(merged_.size());
}

StrainStats Simulator::strain() const {
  std::vector<Real> e;
  StrainStats st;
  for (Eigen::Index s = 0; s < mesh_.springs.cols(); ++s) {
    if (mesh_.kind[s] != SpringKind::kStructural) continue;
    const Real len = (x_.col(mesh_.springs(0, s)) - x_.col(mesh_.springs(1, s))).norm();
    e.push_back((len - mesh_.rest_length[s]) / mesh_.rest_length[s]);
    if (st.max_spring < 0 || e.back() > st.max) st.max = e.back(), st.max_spring = static_cast<int>(s);
  }
  if (e.empty()) return {};
  const Real limit = params_.threshold + Real(0.01);  // the accuracy limit on strain: threshold + 1 %
  st.over = Real(std::count_if(e.begin(), e.end(), [&](Real x) { return x > limit; })) / Real(e.size());
  const std::size_t k = std::min(e.size() - 1, static_cast<std::size_t>(0.99 * double(e.size())));
  std::nth_element(e.begin(), e.begin() + static_cast<long>(k), e.end());
  st.p99 = e[k];
  return st;
}

Real Simulator::max_speed() const { return v_.cols() ? v_.colwise().norm().maxCoeff() : Real(0); }

Real Simulator::kinetic_energy() const {
  return 0.5f * (v_.colwise().squaredNorm().transpose().cwiseProduct(m_)).sum();
}

}  // namespace clothbench
