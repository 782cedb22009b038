#pragma once
/// The field tables (fields.hpp) of the scene sections [material], [solver] and [collider]'s options:
/// one row per key, in the configuration hash's order. scenes/README.md documents each key in full.
#include <string>

#include "clothbench/sim/collider.hpp"
#include "clothbench/sim/fields.hpp"
#include "clothbench/sim/integrator.hpp"
#include "clothbench/sim/limiter.hpp"
#include "clothbench/sim/simulator.hpp"

namespace clothbench {

namespace fields {
template <class E>
auto named(E (*parse)(const std::string&)) {
  return choice(parse, [](E e) { return std::string(to_string(e)); });
}
}  // namespace fields

/// [material] (M: Material or const Material).
template <class M, class V, std::enable_if_t<std::is_same_v<std::remove_const_t<M>, Material>, int> = 0>
void visit_fields(M& m, V& v) {
  using fields::Key, fields::Range;
  v(Key{"density", "kg/m^2", "mass per area"}, m.density, Range{1e-4, 100});
  v(Key{"k_structural", "N/m", "structural stiffness (dressing Eq. 2); 0 = automatic"}, m.k_structural, Range{0, 1e7});
  v(Key{"k_shear", "N/m", "shear stiffness; 0 = automatic"}, m.k_shear, Range{0, 1e7});
  v(Key{"k_flexion", "N/m", "flexion stiffness; 0 = automatic"}, m.k_flexion, Range{0, 1e7});
  v(Key{"damping", "1/s", "viscous damping per unit mass"}, m.damping, Range{0, 1e4});
  v(Key{"friction", "", "C_fric of dressing Eq. 12"}, m.friction, Range{0, 1});
  v(Key{"reflection", "", "C_refl of dressing Eq. 12"}, m.reflection, Range{0, 1});
}

/// [solver] (P: SolverParams or const SolverParams). `regime` is a preset the reader applies before the rest.
template <class P, class V, std::enable_if_t<std::is_same_v<std::remove_const_t<P>, SolverParams>, int> = 0>
void visit_fields(P& p, V& v) {
  using fields::Key, fields::Range, fields::Flag, fields::Hash;
  v(Key{"regime", "", "preset applied before every other key: stable or papers", Hash::kNever}, p.regime,
    fields::named(parse_regime));
  v(Key{"dt", "s", "time step, or \"auto\""}, p.dt, fields::RangeOrAuto{1e-7, 1});
  v(Key{"dt_fraction", "", "margin of the automatic dt and stiffness"}, p.dt_fraction, Range{1e-3, 1});
  v(Key{"allow_unstable_dt", "", "explicit-euler: accept a dt above the Eq. 4 bound"}, p.allow_unstable_dt, Flag{});
  v(Key{"masses", "", "point masses: area or equal"}, p.masses, fields::named(parse_mass_model));
  v(Key{"limit_after_response", "", "limit again after the collision response"}, p.limit_after_response, Flag{});
  v(Key{"push_out", "", "vertices inside the body moved to its surface"}, p.push_out, Flag{});
  v(Key{"push_speed", "m/s", "push_out's largest speed"}, p.push_speed, Range{1e-3, 100});
  v(Key{"self_contact_mm", "mm", "cloth against itself: the thickness (0: off)", Hash::kWhenNonzero}, p.self_contact,
    fields::Scaled{0, 100, 1e-3, 1e3});
  v(Key{"self_contact_last", "", "cloth against itself answered again after the limit", Hash::kWhenNonzero},
    p.self_contact_last, Flag{});
  v(Key{"limit", "", "the strain limiter (limiter_names())"}, p.limit, fields::checked(check_limiter));
  v(Key{"threshold", "", "elongation threshold of the limit (fraction)"}, p.threshold, Range{1e-4, 1});
  v(Key{"stiff_factor", "", "the stiff limit's stiffness factor"}, p.stiff_factor, Range{1, 1e4});
  v(Key{"limit_passes", "", "passes of the limit per call"}, p.limit_passes, Range{1, 1000});
  v(Key{"limit_speed", "m/s", "velocity limits shorten a spring at most this fast"}, p.limit_speed, Range{0, 100});
  v(Key{"limit_tolerance_mm", "mm", "a pass's change below this does not revisit springs"}, p.limit_tolerance,
    fields::Scaled{0, 10, 1e-3, 1e3});
  v(Key{"face_queries", "", "also query quad midpoints (dressing section 6)"}, p.face_queries, Flag{});
  v(Key{"reaction_force", "", "the reaction force of walking Eq. 16"}, p.reaction_force, Flag{});
  v(Key{"gravity", "m/s^2", "gravity"}, p.gravity, fields::Triple{});
  v(Key{"seam_method", "", "elastic or attraction (Durupinar Eq. 1)"}, p.seam_method, fields::named(parse_seam_method));
  v(Key{"seam_stiffness", "N/m", "elastic seams; 0 = as the structural springs"}, p.seam_stiffness, Range{0, 1e7});
  v(Key{"seam_reach", "m", "elastic seams pull no harder beyond this gap"}, p.seam_reach, Range{1e-4, 10});
  v(Key{"seam_speed", "m/s", "seam partners approach no faster"}, p.seam_speed, Range{1e-4, 100});
  v(Key{"attraction_speed", "m/s", "Durupinar Eq. 1's speed"}, p.attraction_speed, Range{0, 100});
  v(Key{"merge_distance", "m", "seam pairs closer than this merge"}, p.merge_distance, Range{0, 1});
  v(Key{"max_speed", "m/s", "divergence: a vertex faster than this"}, p.max_speed, Range{1e-3, 1e6});
  v(Key{"bounds_margin", "m", "divergence: a vertex farther than this from its start box"}, p.bounds_margin,
    Range{1e-3, 1e3});
  v(Key{"integrator", "", "the integrator (integrator_names())"}, p.integrator, fields::checked(check_integrator));
  visit_fields(p.integration, v);
}

/// The integrators' tolerances, keys of [solver].
template <class I, class V, std::enable_if_t<std::is_same_v<std::remove_const_t<I>, IntegratorParams>, int> = 0>
void visit_fields(I& i, V& v) {
  using fields::Key, fields::Range;
  v(Key{"cg_tolerance", "", "implicit-euler: CG's relative residual"}, i.cg_tolerance, Range{1e-7, 0.5});
  v(Key{"cg_max_iterations", "", "implicit-euler: CG's most iterations"}, i.cg_max_iterations, Range{1, 1e5});
  v(Key{"rk_tol_x", "m", "rk45: largest position error per sub-step"}, i.rk_tol_x, Range{1e-9, 1});
  v(Key{"rk_tol_v", "m/s", "rk45: largest velocity error per sub-step"}, i.rk_tol_v, Range{1e-9, 100});
  v(Key{"projective_iterations", "", "projective: local/global iterations per step"}, i.projective_iterations,
    Range{1, 1000});
}

/// [collider]'s options (O: ColliderOptions or const ColliderOptions); the collider's name is the scene's.
template <class O, class V, std::enable_if_t<std::is_same_v<std::remove_const_t<O>, ColliderOptions>, int> = 0>
void visit_fields(O& o, V& v) {
  using fields::Key, fields::Range, fields::Flag;
  v(Key{"tol", "m", "hit when closer than this (dressing Eq. 5)"}, o.tol, Range{0, 1});
  v(Key{"search_radius", "m", "object space: closest points searched within this"}, o.search_radius, Range{1e-4, 10});
  v(Key{"map_size", "pixels", "image space: map resolution"}, o.map_size, Range{16, 8192});
  v(Key{"side_layer", "", "image space: a layer around the silhouette"}, o.side_layer, Flag{});
  v(Key{"fit_extent", "", "image space: map square fitted to the body"}, o.fit_extent, Flag{});
  v(Key{"float_maps", "", "image space: float targets (false: 8-bit colours)"}, o.float_maps, Flag{});
  v(Key{"max_speed", "m/s", "image space, 8-bit velocities: maxv (walking Eq. 9)"}, o.max_speed, Range{1e-3, 1e3});
  v(Key{"threads", "", "object space worker threads"}, o.threads, Range{1, 256});
  v(Key{"coherent", "", "object space: bounds carried between queries"}, o.coherent, Flag{});
  v(Key{"face_normals", "", "respond along the closest face's normal"}, o.face_normals, Flag{});
  v(Key{"voxel_size", "m", "vdb: voxel edge"}, o.voxel_size, Range{1e-4, 0.1});
  v(Key{"views", "", "image space: 2, 4 or 6 views"}, o.views,
    fields::OneOf{{2, 4, 6}, "2 (front/back), 4 (+ left/right) or 6 (+ top/bottom)"});
  v(Key{"layers", "", "image space: surfaces peeled per view pair"}, o.layers, Range{1, 8});
  v(Key{"side_layer_mm", "mm", "image space: the side layer's width; 0 = one pixel"}, o.side_layer_mm, Range{0, 1000});
  v(Key{"tangent_plane", "", "image space: refine by the tangent plane"}, o.tangent_plane, Flag{});
  v(Key{"query_margin_mm", "mm", "image space: map rows the cloth's box grown by this spans; 0 = all"},
    o.query_margin_mm, Range{0, 1e4});
}

}  // namespace clothbench
