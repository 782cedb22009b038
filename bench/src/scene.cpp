// Scene files: TOML through toml++, every key checked, errors located at file:line.
#include "clothbench/bench/scene.hpp"

#include <toml++/toml.h>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <vector>

#include "clothbench/config.h"
#include "clothbench/io/data_root.hpp"
#include "clothbench/io/errors.hpp"
#include "clothbench/sim/garment_draft.hpp"
#include "clothbench/sim/param_fields.hpp"

namespace clothbench {

namespace {

// body.pose_fps: 0, or a whole multiple of body.fps
void check_pose_fps(const std::string& file, const BodySpec& b) {
  const double ratio = b.pose_fps / b.fps;
  if (b.pose_fps == 0 || (ratio >= 1 && std::abs(ratio - std::round(ratio)) < 1e-9)) return;
  std::ostringstream msg;
  msg << "body.pose_fps = " << b.pose_fps << ": must be 0 (once per frame) or a whole multiple of body.fps (" << b.fps
      << ")";
  throw InputError(located(file, 0, msg.str()));
}

// a skin `key` of `mm` (BodyBetweenFrames: contacts answered that much closer) below the hit distance `tol` [m]
void check_skin(const std::string& file, const std::string& key, double mm, Real tol) {
  if (mm * 1e-3 < double(tol)) return;
  throw InputError(located(file, 0,
                           key + " = " + std::to_string(mm) + ": must be below collider.tol (" +
                               std::to_string(1e3 * double(tol)) + " mm), or the skin would push every contact out"));
}

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

using fields::Flag, fields::Hash, fields::Key, fields::Range, fields::Text;

// [scene]: labels, not settings
struct Head {
  std::string& name;
  std::string& description;
};

template <class V>
void visit_fields(const Head& h, V& v) {
  v(Key{"name", "", "the label in tables (default: the file name)", Hash::kNever}, h.name, Text{});
  v(Key{"description", "", "a line of text", Hash::kNever}, h.description, Text{});
}

template <class B, class V, std::enable_if_t<std::is_same_v<std::remove_const_t<B>, BodySpec>, int> = 0>
void visit_fields(B& b, V& v) {
  v(Key{"file", "", "the body: debian:human, data:REL or a path"}, b.file, Text{});
  v(Key{"animation", "", "animation name; empty: the rest pose"}, b.animation, Text{});
  v(Key{"dress_at_s", "s", "garments are dressed on the frame at this time"}, b.dress_at_s, Range{0, 1e4});
  v(Key{"start_s", "s", "the measured window's start"}, b.start_s, Range{0, 1e4});
  v(Key{"end_s", "s", "the measured window's end; < 0: the clip's end"}, b.end_s, Range{-1, 1e4});
  v(Key{"walk_in_place", "", "remove the root's horizontal travel"}, b.walk_in_place, Flag{});
  v(Key{"fps", "1/s", "body frames per second of animation"}, b.fps, Range{1, 1000});
  v(Key{"pose_fps", "1/s", "> 0: the body posed this often, a multiple of fps; 0: once per frame", Hash::kWhenNonzero},
    b.pose_fps, Range{0, 1e4});
  v(Key{"move_between_frames", "", "each step sees the body at its own time"}, b.move_between_frames, Flag{});
  v(Key{"skin_mm", "mm", "contacts answered this much closer"}, b.skin_mm, Range{0, 1000});
  v(Key{"prepare_ahead", "", "the next frame prepared on a second thread"}, b.prepare_ahead, Flag{});
  v(Key{"collision_triangles", "", "> 0: colliders see a simplified copy", Hash::kWhenNonzero}, b.collision_triangles,
    Range{0, 1e8});
  v(Key{"scale", "", "the mesh scaled along x, y, z about the origin (soles' centre)", Hash::kUnlessOne}, b.scale,
    fields::Triple{});
  v(Key{"shape", "", "mesh or sphere"}, b.shape, fields::checked([](const std::string& x) {
      if (x != "mesh" && x != "sphere")
        throw std::invalid_argument("expected \"mesh\" or \"sphere\", got \"" + x + "\"");
    }));
  v(Key{"radius", "m", "sphere radius"}, b.radius, Range{1e-3, 100});
  v(Key{"center", "m", "sphere centre at t = 0"}, b.center, fields::Triple{});
  v(Key{"velocity", "m/s", "sphere velocity while animated"}, b.velocity, fields::Triple{});
  v(Key{"move_s", "s", "sphere: seconds of motion"}, b.move_s, Range{0, 1e4});
}

template <class G, class V, std::enable_if_t<std::is_same_v<std::remove_const_t<G>, GarmentSpec>, int> = 0>
void visit_fields(G& g, V& v) {
  v(Key{"file", "", "pattern file (or fit)"}, g.file, Text{});
  v(Key{"fit", "", "a garment type drafted from the body's measurements (or file)"}, g.fit,
    fields::checked([](const std::string& x) {
      std::string types;
      for (const std::string& t : draft_types()) {
        if (x == t) return;
        types += (types.empty() ? "" : ", ") + t;
      }
      if (!x.empty()) throw std::invalid_argument("expected a drafted garment type (" + types + "), got \"" + x + "\"");
    }));
  v(Key{"size", "", "fit: S, M, L or XL"}, g.size, fields::checked([](const std::string& x) { size_ease_cm(x); }));
  v(Key{"ease_cm", "cm", "fit: the ease at the hip; -1: the size's"}, g.ease_cm, Range{-1, 100});
  v(Key{"vertices", "", "target vertex count; 0: use spacing_cm"}, g.vertices, Range{0, 1e6});
  v(Key{"spacing_cm", "cm", "grid spacing when vertices is 0"}, g.spacing_cm, Range{0.05, 100});
  v(Key{"attach", "", "honour the pattern's attached edges"}, g.attach, Flag{});
  v(Key{"on_grid", "", "Durupinar's construction: the outline drawn on the grid", Hash::kWhenNonzero}, g.on_grid,
    Flag{});
  v(Key{"smooth", "", "on the grid: Durupinar's step 7, the outline made smooth", Hash::kWhenNonzero}, g.smooth, Flag{});
  v(Key{"jitter_mm", "mm", "> 0: the placed garment moved by a random offset"}, g.jitter_mm, Range{0, 100});
  v(Key{"seed", "", "the jitter's random seed"}, g.seed, Range{0, 1e9});
  v(Key{"layer", "", "dressed a layer at a time, the lowest first, each outside those before", Hash::kWhenNonzero},
    g.layer, Range{0, 16});
}

// [collider]: the collider's name, the dressing one's, and every collider's options
template <class S, class V, std::enable_if_t<std::is_same_v<std::remove_const_t<S>, Scene>, int> = 0>
void visit_fields(S& s, V& v) {
  v(Key{"name", "", "the collider (clothbench colliders)"}, s.collider, Text{});
  v(Key{"dress_with", "", "the collider of sewing, draping and the lead-in; empty: name"}, s.dress_with, Text{});
  v(Key{"cloth_under", "", "image space: an outer layer against the cloth under it; empty: none", Hash::kWhenNonzero},
    s.cloth_under, Text{});
  v(Key{"cloth_skin_mm", "mm", "cloth_under: the cloth under answered this much thicker", Hash::kWhenNonzero},
    s.cloth_skin_mm, Range{0, 1000});
  visit_fields(s.collider_options, v);
}

template <class R, class V, std::enable_if_t<std::is_same_v<std::remove_const_t<R>, StopRule>, int> = 0>
void visit_fields(R& r, V& v) {
  v(Key{"sew", "", "run the sew phase"}, r.sew, Flag{});
  v(Key{"sew_max_s", "s", "sew phase limit (simulated)"}, r.sew_max_s, Range{0, 1e4});
  v(Key{"sewn_gap_mm", "mm", "sewn: every seam pair closer than this"}, r.sewn_gap_mm, Range{0, 1e4});
  v(Key{"drape_max_s", "s", "drape phase limit (simulated)"}, r.drape_max_s, Range{0, 1e4});
  v(Key{"settle_speed", "m/s", "settled: RMS speed below this"}, r.settle_speed, Range{0, 100});
  v(Key{"settle_window_s", "s", "... for this long"}, r.settle_window_s, Range{0, 100});
  v(Key{"max_iterations", "", "> 0: stop each phase after this many iterations"}, r.max_iterations, Range{0, 1e9});
}

// the reading visitor: each row's key read from one table of the scene, checked against the row's rule
class Reader {
 public:
  explicit Reader(Section& s) : s_(s) {}
  template <class T>
  void operator()(const Key& k, T& m, const Range& r) {
    s_.number(k.name, m, r.lo, r.hi);
  }
  template <class T>
  void operator()(const Key& k, T& m, const fields::RangeOrAuto& r) {
    const toml::node* n = s_.find(k.name);
    if (n && n->value<std::string>() == std::optional<std::string>("auto"))
      m = 0;
    else if (n)
      s_.number(k.name, m, r.lo, r.hi);
  }
  template <class T>
  void operator()(const Key& k, T& m, const fields::Scaled& r) {
    if (!s_.find(k.name)) return;
    double given = 0;  // in the key's unit
    s_.number(k.name, given, r.lo, r.hi);
    m = T(given * r.to_member);
  }
  void operator()(const Key& k, int& m, const fields::OneOf& r) {
    if (!s_.find(k.name)) return;
    s_.number(k.name, m, -1e9, 1e9);
    if (std::find(r.values.begin(), r.values.end(), m) == r.values.end())
      s_.fail(*s_.find(k.name), k.name, std::string("must be ") + r.says + ", got " + std::to_string(m));
  }
  void operator()(const Key& k, bool& m, Flag) { s_.flag(k.name, m); }
  void operator()(const Key& k, std::string& m, Text) { s_.text(k.name, m); }
  void operator()(const Key& k, Vec3& m, fields::Triple) { s_.vec3(k.name, m); }
  template <class T, class P, class Q>
  void operator()(const Key& k, T& m, const fields::Choice<P, Q>& c) {
    s_.choice(k.name, [&](const std::string& v) { m = c.parse(v); });
  }

 private:
  Section& s_;
};

// every key of a table read through its rows; any other key is an error
template <class T>
void read_section(Section s, T&& fields) {
  Reader reader(s);
  visit_fields(fields, reader);
  s.finish();
}

// [solver] regime: a preset applied before any key, so that every key given explicitly overrides it
void apply_regime_key(Section s, Material& m, SolverParams& p) {
  Regime regime = Regime::kStable;
  s.choice("regime", [&](const std::string& v) { regime = parse_regime(v); });
  apply_regime(regime, m, p);
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

void give_way_to_a_preset(toml::table& root, const std::vector<std::string>& overrides);

Scene read_scene(toml::table& root, const std::string& file, const std::vector<std::string>& overrides) {
  give_way_to_a_preset(root, overrides);
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
  const auto section = [&](const char* name) { return Section(root[name].as_table(), file, name); };
  read_section(section("scene"), Head{s.name, s.description});
  read_section(section("body"), s.body);
  if (const toml::node* g = root.get("garment")) {
    const toml::array* list = g->as_array();
    if (!list)
      throw InputError(located(file, static_cast<int>(g->source().begin.line), "garment: use [[garment]] tables"));
    for (const auto& item : *list) {
      if (!item.as_table())
        throw InputError(located(file, static_cast<int>(item.source().begin.line), "garment: expected a table"));
      GarmentSpec spec;
      read_section(Section(item.as_table(), file, "garment"), spec);
      if (spec.file.empty() == spec.fit.empty())
        throw InputError(located(
            file, static_cast<int>(item.source().begin.line),
            spec.file.empty()
                ? "garment: give a pattern file or a fit (neither is given)"
                : "garment: give a pattern file or a fit, not both (`--set garment.file=` clears a scene's file)"));
      if (spec.ease_cm < 0 && spec.ease_cm != -1)
        throw InputError(located(file, static_cast<int>(item.source().begin.line),
                                 "garment.ease_cm: expected -1 (the size's) or 0 to 100 cm"));
      s.garments.push_back(spec);
    }
  }
  apply_regime_key(section("solver"), s.material, s.solver);
  read_section(section("material"), s.material);
  read_section(section("solver"), s.solver);
  read_section(section("collider"), s);
  if (s.body.skin_mm > 0) check_skin(file, "body.skin_mm", s.body.skin_mm, s.collider_options.tol);
  if (!s.cloth_under.empty()) check_skin(file, "collider.cloth_skin_mm", s.cloth_skin_mm, s.collider_options.tol);
  read_section(section("stop"), s.stop);
  check_pose_fps(file, s.body);
  return s;
}

template <class Rule>
struct IsChoice : std::false_type {};
template <class P, class Q>
struct IsChoice<fields::Choice<P, Q>> : std::true_type {};

inline bool is_one(const Vec3& v) { return v == Vec3::Ones(); }
template <class T>
bool is_one(const T& v) {
  if constexpr (std::is_arithmetic_v<T>) return v == T(1);
  return false;
}

// the hashing visitor: one `section.key = value` line per row; numbers with 17 significant digits (exact for
// float and double)
class ConfigWriter {
 public:
  explicit ConfigWriter(const char* section) : section_(section) {}
  template <class T, class Rule>
  void operator()(const Key& k, const T& m, const Rule& rule) {
    if (k.hash == Hash::kNever) return;
    if constexpr (std::is_same_v<Rule, fields::Scaled>) {
      write(k.name, double(m) * rule.to_key);
    } else if constexpr (IsChoice<Rule>::value) {
      write(k.name, rule.print(m));
    } else {
      if (k.hash == Hash::kWhenNonzero && m == T{}) return;
      if (k.hash == Hash::kUnlessOne && is_one(m)) return;
      write(k.name, m);
    }
  }
  std::string str() const { return text_.str(); }

 private:
  void write(const char* key, double v) { line(key, number(v)); }
  void write(const char* key, bool v) { line(key, v ? "true" : "false"); }
  void write(const char* key, int v) { line(key, std::to_string(v)); }
  void write(const char* key, long v) { line(key, std::to_string(v)); }
  void write(const char* key, const std::string& v) { line(key, quoted(v)); }
  void write(const char* key, const Vec3& v) {
    line(key, "[" + number(v.x()) + ", " + number(v.y()) + ", " + number(v.z()) + "]");
  }
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
  void line(const char* key, const std::string& value) { text_ << section_ << "." << key << " = " << value << "\n"; }
  std::string section_;
  std::ostringstream text_;
};

template <class T>
std::string config(const char* section, const T& fields) {
  ConfigWriter w(section);
  visit_fields(fields, w);
  return w.str();
}

// the [material] and [solver] keys the two presets set to different values (apply_regime), as "section.key"
std::set<std::string> keys_the_presets_decide() {
  const auto preset = [](Regime r) {
    Material m;
    SolverParams p;
    apply_regime(r, m, p);
    std::map<std::string, std::string> values;
    std::istringstream lines(config("material", m) + config("solver", p));
    for (std::string line; std::getline(lines, line);) {
      const auto eq = line.find(" = ");
      values[line.substr(0, eq)] = line.substr(eq + 3);
    }
    return values;
  };
  const auto stable = preset(Regime::kStable), papers = preset(Regime::kPapers);
  std::set<std::string> decided;
  for (const auto* one : {&stable, &papers})
    for (const auto& [key, value] : *one) {
      const auto* other = one == &stable ? &papers : &stable;
      const auto it = other->find(key);
      if (it == other->end() || it->second != value) decided.insert(key);
    }
  return decided;
}

// a regime given with --set other than the file's own runs the scene under that preset: the file's values of the keys
// the presets decide (tuned for its own regime) give way to it; every other --set key still applies after it
void give_way_to_a_preset(toml::table& root, const std::vector<std::string>& overrides) {
  const auto regime = [](toml::table& t) {
    return t["solver"]["regime"].value_or(std::string(to_string(Regime::kStable)));
  };
  toml::table given = root;  // the regime the overrides leave, read as the reader reads it
  for (const auto& o : overrides) apply_override(given, o);
  if (regime(given) == regime(root)) return;
  for (const std::string& key : keys_the_presets_decide()) {
    const auto dot = key.find('.');
    if (toml::table* t = root[key.substr(0, dot)].as_table()) t->erase(key.substr(dot + 1));
  }
}

}  // namespace

std::vector<SceneKey> scene_keys() {
  std::vector<SceneKey> keys;
  const auto list = [&](const char* section, auto&& fields) {
    auto add = [&](const Key& k, const auto&, const auto&) { keys.push_back({section, k.name, k.unit, k.doc}); };
    visit_fields(fields, add);
  };
  Scene s;
  GarmentSpec g;
  list("scene", Head{s.name, s.description});
  list("body", s.body);
  list("garment", g);
  list("material", s.material);
  list("solver", s.solver);
  list("collider", s);
  list("stop", s.stop);
  return keys;
}

std::string config_text(const Scene& scene) {
  std::string text = config("body", scene.body);
  for (const auto& g : scene.garments) text += config("garment", g);
  return text + config("material", scene.material) + config("solver", scene.solver) + config("collider", scene) +
         config("stop", scene.stop);
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
  for (const auto& g : scene.garments)
    if (!g.file.empty()) text += "garment.file_fnv1a = " + file_digest(scene, g.file) + "\n";
  Fnv1a f;
  f.add(text.data(), text.size());
  return f.hex();
}

long poses_per_frame(const BodySpec& body) {
  return body.pose_fps > 0 ? std::max(1L, std::lround(body.pose_fps / body.fps)) : 1;
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
