// The force model shared by every integrator, explicit Euler (dressing Eq. 3) and the registry by name.
#include <algorithm>
#include <functional>
#include <stdexcept>
#include <utility>

#include "integrators.hpp"

namespace clothbench {

void ForceModel::external(const Points3& v, Points3& f) const {
  // gravity and viscous damping -C_vd v (dressing section 3) with C_vd = m_i c: per unit mass, so terminal
  // speeds g / c do not depend on the mesh resolution
  f = (gravity * m.transpose()).array() - damping * (v.array().rowwise() * m.transpose().array());
}

void ForceModel::react(Points3& f) const {
  // walking Eq. 16: f_reaction = -C_fric f_t - f_n for colliding points pushed into the body
  for (Eigen::Index i = 0; reaction && i < f.cols(); ++i) {
    const Contact& c = contacts[static_cast<std::size_t>(i)];
    if (!c.hit) continue;
    const Vec3 fi = f.col(i);
    const Real fn_len = fi.dot(c.normal);
    if (fn_len >= 0) continue;
    const Vec3 fn = fn_len * c.normal;
    f.col(i) += -friction * (fi - fn) - fn;
  }
}

void ForceModel::eval(const Points3& x, const Points3& v, Points3& f) const {
  external(v, f);
  // springs: dressing Eq. 2, f = -k (|d| - l0) d/|d| on the first end
  for (Eigen::Index s = 0; s < mesh.springs.cols(); ++s) {
    const int a = mesh.springs(0, s), b = mesh.springs(1, s);
    const Vec3 d = x.col(a) - x.col(b);
    const Real len = d.norm();
    if (!(len > 0)) continue;
    const Vec3 fa = -k[s] * (len - mesh.rest_length[s]) / len * d;
    f.col(a) += fa;
    f.col(b) -= fa;
  }
  // elastic seams: zero-length springs between partners not yet merged, in every phase, pulling no harder
  // than k seam_reach (panels placed far apart are drawn in without a jolt)
  for (Eigen::Index p = 0; elastic_seams && p < mesh.seam_pairs.cols(); ++p) {
    if (merged[static_cast<std::size_t>(p)]) continue;
    const int a = mesh.seam_pairs(0, p), b = mesh.seam_pairs(1, p);
    const Vec3 d = x.col(a) - x.col(b);
    const Real len = d.norm();
    if (!(len > 0)) continue;
    const Vec3 fa = -seam_k[p] * std::min(len, seam_reach) * (d / len);
    f.col(a) += fa;
    f.col(b) -= fa;
  }
  react(f);
}

namespace {

// dressing Eq. 3: a = f/m, v += dt a (attached vertices have 1/m = 0); then p += dt v (the Simulator)
class ExplicitEuler : public Integrator {
 public:
  const char* name() const override { return "explicit-euler"; }
  std::unique_ptr<Integrator> clone() const override { return std::make_unique<ExplicitEuler>(*this); }
  bool bounded_by_eq4() const override { return true; }
  void advance(const ForceModel& model, Real h, const Points3&, const Points3& f, Points3& v, Points3&) override {
    v += h * (f.array().rowwise() * model.inv_m.transpose().array()).matrix();
    ++stats_.force_evaluations;
    ++stats_.substeps;
  }
};

using Factory = std::unique_ptr<Integrator> (*)(const IntegratorParams&);

const std::vector<std::pair<std::string, Factory>>& registry() {
  static const std::vector<std::pair<std::string, Factory>> r{{"explicit-euler", make_explicit_euler},
                                                              {"implicit-euler", make_implicit_euler},
                                                              {"rk45", make_rk45},
                                                              {"projective", make_projective}};
  return r;
}

}  // namespace

std::unique_ptr<Integrator> make_explicit_euler(const IntegratorParams&) { return std::make_unique<ExplicitEuler>(); }

std::vector<std::string> integrator_names() {
  std::vector<std::string> names;
  for (const auto& e : registry()) names.push_back(e.first);
  return names;
}

void check_integrator(const std::string& name) {
  std::string known;
  for (const auto& e : registry()) {
    if (e.first == name) return;
    known += (known.empty() ? "" : ", ") + e.first;
  }
  throw std::invalid_argument("integrator: unknown integrator '" + name + "' (" + known + ")");
}

std::unique_ptr<Integrator> make_integrator(const std::string& name, const IntegratorParams& params) {
  check_integrator(name);
  const auto e = std::find_if(registry().begin(), registry().end(), [&](const auto& r) { return r.first == name; });
  return e->second(params);
}

}  // namespace clothbench
