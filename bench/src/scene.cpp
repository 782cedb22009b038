// Scene files: TOML through toml++, every key checked, errors located at file:line.
#include "clothbench/bench/scene.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <toml++/toml.h>
#include <vector>

#include "clothbench/config.h"
#include "clothbench/io/data_root.hpp"
#include "clothbench/io/errors.hpp"

namespace clothbench {

namespace {

// Levenshtein distance: single-character insertions, deletions and substitutions
std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

// " (did you mean `x`?)" for the nearest known name within a third of its length (at least 2
// edits), else " (known: a, b, ...)"
std::string suggestion(const std::string& name, const std::set<std::string>& known) {
  std::string best, all;
  std::size_t best_distance = std::max<std::size_t>(2, name.size() / 3) + 1;
  for (const auto& k : known) {
    all += (all.empty() ? "" : ", ") + k;
    const std::size_t d = edit_distance(name, k);
    if (d < best_distance && d < std::max(name.size(), k.size())) best = k, best_distance = d;
  }
  return best.empty() ? " (known: " + all + ")" : " (did you mean `" + best + "`?)";
}

// one table of the scene: typed reads that remember which keys were used
class Section {
 public:
  Section(const toml::table* table, std::string file, std::string name)
      : table_(table), file_(std::move(file)), name_(std::move(name)) {}

  [[noreturn]] void fail(const toml::node& node, const std::string& key, const std::string& msg) const {
    const int line = static_cast<int>(node.source().begin.line);
    const std::string where = line > 0 ? "" : " (from --set)";
    throw InputError(located(file_, line, name_ + "." + key + where + ": " + msg));
  }

  const toml::node* find(const std::string& key) {
    used_.insert(key);
    return table_ ? table_->get(key) : nullptr;
  }

  template <class T>
  void number(const std::string& key, T& out, double lo, double hi) {
    const toml::node* n = find(key);
    if (!n) return;
    const auto v = n->value<double>();
    if (!v || n->is_boolean()) fail(*n, key, "expected a number");
    if (!std::isfinite(*v) || *v < lo || *v > hi)
      fail(*n, key, "must be in [" + fmt(lo) + ", " + fmt(hi) + "], got " + fmt(*v));
    if constexpr (std::is_integral_v<T>) {
      if (std::floor(*v) != *v) fail(*n, key, "expected an integer");
    }
    out = static_cast<T>(*v);
  }

  void flag(const std::string& key, bool& out) {
    const toml::node* n = find(key);
    if (!n) return;
    const auto v = n->value<bool>();
    if (!v || !n->is_boolean()) fail(*n, key, "expected true or false");
    out = *v;
  }

  void text(const std::string& key, std::string& out) {
    const toml::node* n = find(key);
    if (!n) return;
    const auto v = n->value<std::string>();
    if (!v || !n->is_string()) fail(*n, key, "expected a string");
    out = *v;
  }

  void vec3(const std::string& key, Vec3& out) {
    const toml::node* n = find(key);
    if (!n) return;
    const toml::array* a = n->as_array();
    if (!a || a->size() != 3) fail(*n, key, "expected [x, y, z]");
    for (int k = 0; k < 3; ++k) {
      const auto v = a->get(k)->value<double>();
      if (!v || !std::isfinite(*v)) fail(*n, key, "expected three finite numbers");
      out[k] = static_cast<Real>(*v);
    }
  }

  // a string converted by `parse` (which throws std::invalid_argument on unknown names)
  template <class Parse>
  void choice(const std::string& key, Parse parse) {
    const toml::node* n = find(key);
    if (!n) return;
    const auto v = n->value<std::string>();
    if (!v) fail(*n, key, "expected a string");
    try {
      parse(*v);
    } catch (const std::invalid_argument& e) {
      fail(*n, key, e.what());
    }
  }

  // every key not read is an error: misspelt keys must not be silently ignored (every reader
  // looks up all its keys, so used_ holds the known ones)
  void finish() const {
    if (!table_) return;
    for (auto&& [key, node] : *table_) {
      const std::string k(key.str());
      if (!used_.count(k)) fail(node, k, "unknown key `" + k + "`" + suggestion(k, used_));
    }
  }

  static std::string fmt(double v) {
    std::ostringstream s;
    s << v;
    return s.str();
  }

 private:
  const toml::table* table_;
  std::string file_, name_;
  std::set<std::string> used_;
};

void read_body(Section s, BodySpec& b) {
  s.text("file", b.file);
  s.text("animation", b.animation);
  s.number("dress_at_s", b.dress_at_s, 0, 1e4);
  s.number("start_s", b.start_s, 0, 1e4);
  s.number("end_s", b.end_s, -1, 1e4);
  s.flag("walk_in_place", b.walk_in_place);
  s.number("fps", b.fps, 1, 1000);
  s.flag("move_between_frames", b.move_between_frames);
  s.flag("prepare_ahead", b.prepare_ahead);
  s.number("skin_mm", b.skin_mm, 0, 1000);
  s.number("collision_triangles", b.collision_triangles, 0, 1e8);
  s.choice("shape", [&](const std::string& v) {
    if (v != "mesh" && v != "sphere") throw std::invalid_argument("expected \"mesh\" or \"sphere\", got \"" + v + "\"");
    b.shape = v;
  });
  s.number("radius", b.radius, 1e-3, 100);
  s.vec3("center", b.center);
  s.vec3("velocity", b.velocity);
  s.number("move_s", b.move_s, 0, 1e4);
  s.finish();
}

void read_garment(Section s, GarmentSpec& g) {
  s.text("file", g.file);
  s.number("vertices", g.vertices, 0, 1e6);
  s.number("spacing_cm", g.spacing_cm, 0.05, 100);
  s.flag("attach", g.attach);
  s.number("jitter_mm", g.jitter_mm, 0, 100);
  s.number("seed", g.seed, 0, 1e9);
  s.finish();
}

void read_material(Section s, Material& m) {
  s.number("density", m.density, 1e-4, 100);
  s.number("k_structural", m.k_structural, 0, 1e7);  // 0 = automatic (the papers' regime)
  s.number("k_shear", m.k_shear, 0, 1e7);
  s.number("k_flexion", m.k_flexion, 0, 1e7);
  s.number("damping", m.damping, 0, 1e4);  // per unit mass [1/s]
  s.number("friction", m.friction, 0, 1);
  s.number("reflection", m.reflection, 0, 1);
  s.finish();
}

// [solver] regime: a preset applied before any key, so that every key given explicitly overrides it
void apply_regime_key(Section s, Material& m, SolverParams& p) {
  Regime regime = Regime::kStable;
  s.choice("regime", [&](const std::string& v) { regime = parse_regime(v); });
  apply_regime(regime, m, p);
}

void read_solver(Section s, SolverParams& p) {
  s.choice("regime", [](const std::string&) {});  // applied first (apply_regime_key); read here as a known key
  s.choice("masses", [&](const std::string& v) { p.masses = parse_mass_model(v); });
  if (const toml::node* n = s.find("dt")) {
    if (n->value<std::string>() == std::optional<std::string>("auto")) {
      p.dt = 0;
    } else {
      s.number("dt", p.dt, 1e-7, 1);
    }
  }
  s.number("dt_fraction", p.dt_fraction, 1e-3, 1);
  s.flag("allow_unstable_dt", p.allow_unstable_dt);
  s.choice("limit", [&](const std::string& v) {
    check_limiter(v);
    p.limit = v;
  });
  s.number("threshold", p.threshold, 1e-4, 10);
  s.number("stiff_factor", p.stiff_factor, 1, 1e4);
  s.number("limit_passes", p.limit_passes, 1, 1000);
  s.flag("limit_after_response", p.limit_after_response);
  s.flag("push_out", p.push_out);
  s.number("push_speed", p.push_speed, 1e-3, 100);
  s.number("limit_speed", p.limit_speed, 0, 100);
  double tolerance_mm = -1;  // given in mm, kept in m
  s.number("limit_tolerance_mm", tolerance_mm, 0, 10);
  if (tolerance_mm >= 0) p.limit_tolerance = Real(tolerance_mm * 1e-3);
  s.flag("face_queries", p.face_queries);
  s.flag("reaction_force", p.reaction_force);
  s.vec3("gravity", p.gravity);
  s.choice("seam_method", [&](const std::string& v) { p.seam_method = parse_seam_method(v); });
  s.number("seam_stiffness", p.seam_stiffness, 0, 1e7);
  s.number("seam_reach", p.seam_reach, 1e-4, 10);
  s.number("seam_speed", p.seam_speed, 1e-4, 100);
  s.number("attraction_speed", p.attraction_speed, 0, 100);
  s.number("merge_distance", p.merge_distance, 0, 1);
  s.number("max_speed", p.max_speed, 1e-3, 1e6);
  s.choice("integrator", [&](const std::string& v) { check_integrator(v), p.integrator = v; });
  s.number("cg_tolerance", p.integration.cg_tolerance, 1e-7, 0.5);
  s.number("cg_max_iterations", p.integration.cg_max_iterations, 1, 1e5);
  s.number("rk_tol_x", p.integration.rk_tol_x, 1e-9, 1);
  s.number("rk_tol_v", p.integration.rk_tol_v, 1e-9, 100);
  s.number("projective_iterations", p.integration.projective_iterations, 1, 1000);
  s.finish();
}

void read_collider(Section s, Scene& scene) {
  ColliderOptions& o = scene.collider_options;
  s.text("name", scene.collider);
  s.text("dress_with", scene.dress_with);
  s.number("tol", o.tol, 0, 1);
  s.flag("face_normals", o.face_normals);
  s.number("search_radius", o.search_radius, 1e-4, 10);
  s.number("map_size", o.map_size, 16, 8192);
  s.flag("side_layer", o.side_layer);
  s.number("side_layer_mm", o.side_layer_mm, 0, 1000);
  s.number("views", o.views, 0, 1e6);
  if (o.views != 2 && o.views != 4 && o.views != 6)
    s.fail(*s.find("views"), "views", "must be 2 (front/back), 4 (+ left/right) or 6 (+ top/bottom), got " +
                                          std::to_string(o.views));
  s.number("layers", o.layers, 1, 8);
  s.flag("fit_extent", o.fit_extent);
  s.flag("float_maps", o.float_maps);
  s.flag("tangent_plane", o.tangent_plane);
  s.number("max_speed", o.max_speed, 1e-3, 1e3);
  s.number("query_margin_mm", o.query_margin_mm, 0, 1e4);
  s.number("threads", o.threads, 1, 256);
  s.flag("coherent", o.coherent);
  s.number("voxel_size", o.voxel_size, 1e-4, 0.1);
  s.finish();
}

void read_stop(Section s, StopRule& r) {
  s.flag("sew", r.sew);
  s.number("sew_max_s", r.sew_max_s, 0, 1e4);
  s.number("sewn_gap_mm", r.sewn_gap_mm, 0, 1e4);
  s.number("drape_max_s", r.drape_max_s, 0, 1e4);
  s.number("settle_speed", r.settle_speed, 0, 100);
  s.number("settle_window_s", r.settle_window_s, 0, 100);
  s.number("max_iterations", r.max_iterations, 0, 1e9);
  s.finish();
}

// "section.key=value": value in TOML syntax, or a bare word taken as a string
void apply_override(toml::table& root, const std::string& item) {
  const auto eq = item.find('=');
  const auto dot = item.find('.');
  if (eq == std::string::npos || dot == std::string::npos || dot > eq || dot == 0 || dot + 1 == eq)
    throw InputError("--set " + item + ": expected section.key=value");
  const std::string section = item.substr(0, dot), key = item.substr(dot + 1, eq - dot - 1), text = item.substr(eq + 1);
  toml::table parsed;
  try {
    parsed = toml::parse("v = " + text);
  } catch (const toml::parse_error&) {
    parsed = toml::table{{"v", text}};
  }
  // a fresh node has no source position: messages then say "(from --set)"
  const auto insert = [&](toml::table& t) { t.insert_or_assign(key, *parsed.get("v")); };
  if (section == "garment") {
    toml::array* garments = root["garment"].as_array();
    if (!garments) throw InputError("--set " + item + ": the scene has no [[garment]]");
    for (auto& g : *garments)
      if (auto* t = g.as_table()) insert(*t);
    return;
  }
  if (!root.contains(section)) root.insert(section, toml::table{});
  toml::table* t = root[section].as_table();
  if (!t) throw InputError("--set " + item + ": '" + section + "' is not a table");
  insert(*t);
}

Scene read_scene(toml::table& root, const std::string& file, const std::vector<std::string>& overrides) {
  for (const auto& o : overrides) apply_override(root, o);
  Scene s;
  s.path = file;
  s.name = std::filesystem::path(file).stem().string();
  const std::set<std::string> sections{"scene", "body", "garment", "material", "solver", "collider", "stop"};
  for (auto&& [key, node] : root) {
    const std::string k(key.str());
    if (!sections.count(k) || (k != "garment" && !node.is_table()))
      throw InputError(located(file, static_cast<int>(node.source().begin.line),
                               "unknown section '" + k + "'" + (sections.count(k) ? "" : suggestion(k, sections)) +
                                   " (sections: scene, body, [[garment]], material, solver, collider, stop)"));
  }
  Section head(root["scene"].as_table(), file, "scene");
  head.text("name", s.name);
  head.text("description", s.description);
  head.finish();
  read_body(Section(root["body"].as_table(), file, "body"), s.body);
  if (const toml::node* g = root.get("garment")) {
    const toml::array* list = g->as_array();
    if (!list) throw InputError(located(file, static_cast<int>(g->source().begin.line), "garment: use [[garment]] tables"));
    for (const auto& item : *list) {
      if (!item.as_table()) throw InputError(located(file, static_cast<int>(item.source().begin.line), "garment: expected a table"));
      GarmentSpec spec;
      read_garment(Section(item.as_table(), file, "garment"), spec);
      if (spec.file.empty()) throw InputError(located(file, static_cast<int>(item.source().begin.line), "garment.file is required"));
      s.garments.push_back(spec);
    }
  }
  apply_regime_key(Section(root["solver"].as_table(), file, "solver"), s.material, s.solver);
  read_material(Section(root["material"].as_table(), file, "material"), s.material);
  read_solver(Section(root["solver"].as_table(), file, "solver"), s.solver);
  read_collider(Section(root["collider"].as_table(), file, "collider"), s);
  if (s.body.skin_mm > 0 && !(s.body.skin_mm * 1e-3 < double(s.collider_options.tol)))
    throw InputError(located(file, 0, "body.skin_mm = " + std::to_string(s.body.skin_mm) +
                                          ": must be below collider.tol (" +
                                          std::to_string(1e3 * double(s.collider_options.tol)) +
                                          " mm), or the skin would push every contact out"));
  read_stop(Section(root["stop"].as_table(), file, "stop"), s.stop);
  return s;
}

// one `section.key = value` line; numbers with 17 significant digits (exact for float and double)
class ConfigWriter {
 public:
  explicit ConfigWriter(std::string section) : section_(std::move(section)) {}
  ConfigWriter& operator()(const char* key, double v) { return line(key, number(v)); }
  ConfigWriter& operator()(const char* key, bool v) { return line(key, v ? "true" : "false"); }
  ConfigWriter& operator()(const char* key, int v) { return line(key, std::to_string(v)); }
  ConfigWriter& operator()(const char* key, long v) { return line(key, std::to_string(v)); }
  ConfigWriter& operator()(const char* key, const std::string& v) { return line(key, quoted(v)); }
  ConfigWriter& operator()(const char* key, const char* v) { return (*this)(key, std::string(v)); }
  ConfigWriter& operator()(const char* key, const Vec3& v) {
    return line(key, "[" + number(v.x()) + ", " + number(v.y()) + ", " + number(v.z()) + "]");
  }
  std::string str() const { return text_.str(); }

 private:
  static std::string quoted(const std::string& v) {
    std::string q = "\"";
    for (const char c : v) q += c == '"' || c == '\\' ? std::string("\\") + c : std::string(1, c);
    return q + "\"";
  }
  static std::string number(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return buf;
  }
  template <class V>
  ConfigWriter& line(const char* key, const V& value) {
    text_ << section_ << "." << key << " = " << value << "\n";
    return *this;
  }
  std::string section_;
  std::ostringstream text_;
};

std::string body_config(const BodySpec& b) {
  ConfigWriter w("body");
  w("file", b.file)("animation", b.animation)("dress_at_s", b.dress_at_s)("start_s", b.start_s)("end_s", b.end_s);
  w("walk_in_place", b.walk_in_place)("fps", b.fps)("move_between_frames", b.move_between_frames)("skin_mm", b.skin_mm)(
      "prepare_ahead", b.prepare_ahead);
  if (b.collision_triangles > 0) w("collision_triangles", b.collision_triangles);  // absent: the hashes before it
  w("shape", b.shape)("radius", double(b.radius));
  w("center", b.center)("velocity", b.velocity)("move_s", b.move_s);
  return w.str();
}

std::string garment_config(const GarmentSpec& g) {
  ConfigWriter w("garment");
  w("file", g.file)("vertices", g.vertices)("spacing_cm", g.spacing_cm)("attach", g.attach)("jitter_mm", g.jitter_mm)("seed", g.seed);
  return w.str();
}

std::string material_config(const Material& m) {
  ConfigWriter w("material");
  w("density", double(m.density))("k_structural", double(m.k_structural))("k_shear", double(m.k_shear));
  w("k_flexion", double(m.k_flexion))("damping", double(m.damping))("friction", double(m.friction));
  w("reflection", double(m.reflection));
  return w.str();
}

std::string solver_config(const SolverParams& p) {
  ConfigWriter w("solver");
  w("dt", double(p.dt))("dt_fraction", double(p.dt_fraction))("allow_unstable_dt", p.allow_unstable_dt);
  w("masses", to_string(p.masses))("limit_after_response", p.limit_after_response);
  w("push_out", p.push_out)("push_speed", double(p.push_speed));
  w("limit", p.limit)("threshold", double(p.threshold))("stiff_factor", double(p.stiff_factor));
  w("limit_passes", p.limit_passes)("limit_speed", double(p.limit_speed))(
      "limit_tolerance_mm", 1e3 * double(p.limit_tolerance))("face_queries", p.face_queries);
  w("reaction_force", p.reaction_force)("gravity", p.gravity)("seam_method", to_string(p.seam_method));
  w("seam_stiffness", double(p.seam_stiffness))("seam_reach", double(p.seam_reach));
  w("seam_speed", double(p.seam_speed))("attraction_speed", double(p.attraction_speed));
  w("merge_distance", double(p.merge_distance))("max_speed", double(p.max_speed));
  w("bounds_margin", double(p.bounds_margin));  // not a scene key, but it decides divergence
  w("integrator", p.integrator)("cg_tolerance", double(p.integration.cg_tolerance));
  w("cg_max_iterations", p.integration.cg_max_iterations)("rk_tol_x", double(p.integration.rk_tol_x));
  w("rk_tol_v", double(p.integration.rk_tol_v))("projective_iterations", p.integration.projective_iterations);
  return w.str();
}

std::string collider_config(const Scene& s) {
  const ColliderOptions& o = s.collider_options;
  ConfigWriter w("collider");
  w("name", s.collider)("dress_with", s.dress_with)("tol", double(o.tol))("search_radius", double(o.search_radius));
  w("map_size", o.map_size)("side_layer", o.side_layer)("fit_extent", o.fit_extent)("float_maps", o.float_maps);
  w("max_speed", double(o.max_speed))("threads", o.threads)("coherent", o.coherent)("face_normals", o.face_normals);
  w("voxel_size", double(o.voxel_size))("views", o.views)("layers", o.layers)("side_layer_mm", double(o.side_layer_mm));
  w("tangent_plane", o.tangent_plane)("query_margin_mm", double(o.query_margin_mm));
  return w.str();
}

std::string stop_config(const StopRule& r) {
  ConfigWriter w("stop");
  w("sew", r.sew)("sew_max_s", r.sew_max_s)("sewn_gap_mm", double(r.sewn_gap_mm))("drape_max_s", r.drape_max_s);
  w("settle_speed", double(r.settle_speed))("settle_window_s", r.settle_window_s)("max_iterations", r.max_iterations);
  return w.str();
}

}  // namespace

std::string config_text(const Scene& scene) {
  std::string text = body_config(scene.body);
  for (const auto& g : scene.garments) text += garment_config(g);
  return text + material_config(scene.material) + solver_config(scene.solver) + collider_config(scene) +
         stop_config(scene.stop);
}

namespace {

// FNV-1a 64
struct Fnv1a {
  std::uint64_t h = 14695981039346656037ull;  // the offset basis
  void add(const char* data, std::size_t n) {
    for (std::size_t i = 0; i < n; ++i) h = (h ^ static_cast<unsigned char>(data[i])) * 1099511628211ull;
  }
  std::string hex() const {
    char out[17];
    std::snprintf(out, sizeof out, "%016llx", static_cast<unsigned long long>(h));
    return out;
  }
};

// the digest of the bytes of a file the run reads ("" when the reference does not resolve: the run then fails)
std::string file_digest(const Scene& scene, const std::string& ref) {
  std::string path;
  try {
    path = resolve_scene_path(scene, ref);
  } catch (const InputError&) {
    return {};
  }
  std::ifstream in(path, std::ios::binary);
  Fnv1a f;
  std::vector<char> buffer(1 << 16);
  while (in.read(buffer.data(), static_cast<std::streamsize>(buffer.size())) || in.gcount() > 0)
    f.add(buffer.data(), static_cast<std::size_t>(in.gcount()));
  return f.hex();
}

}  // namespace

std::string config_hash(const Scene& scene) {
  // the settings and the bytes of every file they name: an edited pattern or body is another configuration
  std::string text = config_text(scene);
  if (scene.body.shape == "mesh") text += "body.file_fnv1a = " + file_digest(scene, scene.body.file) + "\n";
  for (const auto& g : scene.garments) text += "garment.file_fnv1a = " + file_digest(scene, g.file) + "\n";
  Fnv1a f;
  f.add(text.data(), text.size());
  return f.hex();
}

Scene parse_scene(const std::string& text, const std::string& name, const std::vector<std::string>& overrides) {
  toml::table root;
  try {
    root = toml::parse(text, name);
  } catch (const toml::parse_error& e) {
    throw InputError(located(name, static_cast<int>(e.source().begin.line), std::string(e.description())));
  }
  return read_scene(root, name, overrides);
}

Scene load_scene(const std::string& path, const std::vector<std::string>& overrides) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) throw InputError(located(path, 0, "scene file not found"));
  toml::table root;
  try {
    root = toml::parse_file(path);
  } catch (const toml::parse_error& e) {
    throw InputError(located(path, static_cast<int>(e.source().begin.line), std::string(e.description())));
  }
  return read_scene(root, path, overrides);
}

std::string resolve_scene_path(const Scene& scene, const std::string& ref) {
  namespace fs = std::filesystem;
  if (ref == "debian:human" || ref.rfind("data:", 0) == 0) return resolve_data_reference(ref);
  const fs::path p(ref);
  std::error_code ec;
  if (p.is_absolute()) {
    if (!fs::exists(p, ec)) throw InputError(located(scene.path, 0, "file not found: " + ref));
    return ref;
  }
  // scene-relative first, then the source tree's scenes/ folder
  std::vector<fs::path> tried;
  if (!scene.path.empty()) tried.push_back(fs::path(scene.path).parent_path() / p);
  tried.push_back(fs::path(CLOTHBENCH_SOURCE_DIR) / "scenes" / p);
  std::string looked;
  for (const fs::path& candidate : tried) {
    if (fs::exists(candidate, ec)) return candidate.string();
    looked += (looked.empty() ? "" : ", ") + candidate.string();
  }
  throw InputError(located(scene.path, 0, "file not found: `" + ref + "` (looked in " + looked + ")"));
}

}  // namespace clothbench
