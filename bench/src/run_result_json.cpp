// RunResult <-> JSON (run_result_json.hpp).
#include "clothbench/bench/run_result_json.hpp"

#include <algorithm>
#include <cstdint>
#include <vector>

#include "clothbench/io/errors.hpp"

namespace clothbench {

namespace {

// one list of fields for both directions
template <typename J, typename R, typename F>
void phase_fields(J& j, R& p, F&& f) {
  f(j, "iterations", p.iterations);
  f(j, "wall_ms", p.wall_ms);
  f(j, "cpu_ms", p.cpu_ms);
  f(j, "cdr_ms", p.cdr_ms);
  f(j, "cs_ms", p.cs_ms);
  f(j, "limit_ms", p.limit_ms);
  f(j, "cloth_ms", p.cloth_ms);
  f(j, "reached", p.reached);
}

template <typename J, typename A, typename F>
void accuracy_fields(J& j, A& a, F&& f) {
  f(j, "inside_pct", a.inside_pct), f(j, "depth_max_mm", a.depth_max_mm), f(j, "depth_mean_mm", a.depth_mean_mm);
  f(j, "depth_p95_mm", a.depth_p95_mm), f(j, "points", a.points), f(j, "inside", a.inside);
  f(j, "segments", a.segments), f(j, "crossings", a.crossings), f(j, "crossings_pct", a.crossings_pct);
  f(j, "faces", a.faces), f(j, "faces_inside", a.faces_inside), f(j, "faces_inside_pct", a.faces_inside_pct);
  f(j, "depth_ms", a.depth_ms), f(j, "crossings_ms", a.crossings_ms);
  f(j, "cloth_crossings", a.cloth_crossings), f(j, "cloth_crossings_pct", a.cloth_crossings_pct);
}

template <typename J, typename R, typename F>
void run_fields(J& j, R& r, F&& f) {
  f(j, "scene", r.scene), f(j, "collider", r.collider), f(j, "device", r.device), f(j, "integrator", r.integrator);
  f(j, "regime", r.regime);
  f(j, "config_hash", r.config_hash), f(j, "strain_threshold", r.strain_threshold);
  f(j, "iteration_budget", r.iteration_budget), f(j, "estimate_s", r.estimate_s), f(j, "vertices", r.vertices);
  f(j, "query_points", r.query_points), f(j, "body_triangles", r.body_triangles), f(j, "dt_s", r.dt_s);
  f(j, "collision_triangles", r.collision_triangles), f(j, "proxy_deviation_mm", r.proxy_deviation_mm);
  f(j, "dt_bound_s", r.dt_bound_s), f(j, "dt_spectral_s", r.dt_spectral_s), f(j, "k_structural", r.k_structural);
  f(j, "frames", r.frames), f(j, "steps_per_frame", r.steps_per_frame), f(j, "skinning_ms", r.skinning_ms);
  f(j, "collider_update_ms", r.collider_update_ms), f(j, "collider_updates", r.collider_updates);
  f(j, "setup_ms", r.setup_ms), f(j, "search_share", r.search_share);
  f(j, "threads", r.threads), f(j, "prepared_frames", r.prepared_frames), f(j, "seam_gap_max_mm", r.seam_gap_max_mm);
  f(j, "strain_max", r.strain_max);
  f(j, "strain_p99", r.strain_p99), f(j, "strain_over", r.strain_over), f(j, "strain_max_where", r.strain_max_where);
  f(j, "cloth_crossings_where", r.cloth_crossings_where);
  f(j, "seam_gap_where", r.seam_gap_where);
  f(j, "depth_max_where", r.depth_max_where);
  f(j, "kinetic_energy", r.kinetic_energy), f(j, "animate_strain_max", r.animate_strain_max);
  f(j, "animate_strain_max_where", r.animate_strain_max_where);
  f(j, "sew_iteration_ms", r.sew_iteration_ms);
  f(j, "converged", r.converged), f(j, "window_seam_gap_mm", r.window_seam_gap_mm);
}

// frame samples as rows [t_s, inside_pct, depth_max_mm, crossings_pct, strain_max, strain_p99, cloth_crossings_pct]
nlohmann::json frames_json(const std::vector<FrameSample>& samples) {
  nlohmann::json rows = nlohmann::json::array();
  for (const FrameSample& s : samples) rows.push_back({s.t_s, s.inside_pct, s.depth_max_mm, s.crossings_pct, s.strain_max, s.strain_p99, s.cloth_crossings_pct});
  return rows;
}

std::vector<FrameSample> frames_from_json(const nlohmann::json& rows) {
  std::vector<FrameSample> samples;
  for (const auto& row : rows)
    samples.push_back({row.at(0).get<double>(), row.at(1).get<double>(), row.at(2).get<double>(),
                       row.at(3).get<double>(), row.at(4).get<double>(), row.at(5).get<double>(),
                       row.at(6).get<double>()});
  return samples;
}

}  // namespace

nlohmann::json to_json(const RunResult& r, bool end_state) {
  const auto put = [](nlohmann::json& j, const char* key, const auto& v) { j[key] = v; };
  nlohmann::json j = nlohmann::json::object();
  run_fields(j, r, put);
  for (const auto& [name, p] : {std::pair{"sew", &r.sew}, {"drape", &r.drape}, {"animate", &r.animate}})
    phase_fields(j[name], *p, put);
  accuracy_fields(j["accuracy"], r.accuracy, put);
  j["frame_samples"] = frames_json(r.frame_samples);
  if (r.divergence)
    j["divergence"] = {{"iteration", r.divergence->iteration},
                       {"phase", static_cast<int>(r.divergence->phase)},
                       {"vertex", r.divergence->vertex},
                       {"reason", r.divergence->reason}};
  if (end_state) put_end_state(j, r.mesh);
  return j;
}

void put_end_state(nlohmann::json& j, const ClothMesh& mesh) {
  const auto& x = mesh.positions;
  const auto& q = mesh.quads;
  j["end_positions"] = std::vector<float>(x.data(), x.data() + x.size());
  j["end_quads"] = std::vector<std::int32_t>(q.data(), q.data() + q.size());
}

std::optional<ClothMesh> end_state_from_json(const nlohmann::json& j) {
  if (!j.contains("end_positions")) return std::nullopt;
  std::vector<float> x;
  std::vector<std::int32_t> q;
  try {
    x = j["end_positions"].get<std::vector<float>>();
    q = j.at("end_quads").get<std::vector<std::int32_t>>();
  } catch (const nlohmann::json::exception& e) {
    throw InputError(std::string("end state: ") + e.what());
  }
  const auto nv = static_cast<std::int32_t>(x.size() / 3);
  if (x.size() % 3 || q.size() % 4 || std::any_of(q.begin(), q.end(), [&](std::int32_t v) { return v < 0 || v >= nv; }))
    throw InputError("end state: end_positions is not 3 per vertex, or end_quads not 4 vertex indices per quad");
  ClothMesh m;
  m.positions = Eigen::Map<const Points3>(x.data(), 3, nv);
  m.quads = Eigen::Map<const Quads>(q.data(), 4, static_cast<Eigen::Index>(q.size() / 4));
  return m;
}

RunResult run_result_from_json(const nlohmann::json& j) {
  const auto get = [](const nlohmann::json& from, const char* key, auto& v) { from.at(key).get_to(v); };
  RunResult r;
  run_fields(j, r, get);
  for (const auto& [name, p] : {std::pair{"sew", &r.sew}, {"drape", &r.drape}, {"animate", &r.animate}})
    phase_fields(j.at(name), *p, get);
  accuracy_fields(j.at("accuracy"), r.accuracy, get);
  r.frame_samples = frames_from_json(j.at("frame_samples"));
  if (j.contains("divergence")) {
    const auto& d = j["divergence"];
    r.divergence = Divergence{d.at("iteration").get<long>(), static_cast<Phase>(d.at("phase").get<int>()),
                              d.at("vertex").get<int>(), d.at("reason").get<std::string>()};
  }
  if (auto end = end_state_from_json(j)) r.mesh = std::move(*end);
  return r;
}

}  // namespace clothbench
