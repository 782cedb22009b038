#include "clothbench/io/garmentcode.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <iterator>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <vector>

#include "clothbench/io/data_root.hpp"
#include "clothbench/io/errors.hpp"
#include "clothbench/io/pattern_file.hpp"

namespace clothbench {

namespace {

using nlohmann::json;

constexpr double kChordCm = 1.0;  // longest chord of a flattened curve [cm]

// A key as a JSON pointer token (RFC 6901: ~ as ~0, / as ~1).
std::string escape(const std::string& k) {
  std::string out;
  for (char c : k) out += c == '~' ? std::string("~0") : c == '/' ? std::string("~1") : std::string(1, c);
  return out;
}

// Counts lines as nlohmann's lexer consumes characters: the line of the last character read,
// not counting it when it is the newline that ended a number.
struct LineCounter {
  int newlines_before_last = 0;
  char last = 0;
  void consume(char c) {
    newlines_before_last += last == '\n' ? 1 : 0;
    last = c;
  }
  int line() const { return newlines_before_last + 1; }
};

class CountingIterator {
 public:
  using iterator_category = std::forward_iterator_tag;
  using value_type = char;
  using difference_type = std::ptrdiff_t;
  using pointer = const char*;
  using reference = const char&;

  CountingIterator(const char* p, LineCounter* counter) : p_(p), counter_(counter) {}
  reference operator*() const { return *p_; }
  CountingIterator& operator++() {
    counter_->consume(*p_);
    ++p_;
    return *this;
  }
  CountingIterator operator++(int) {
    CountingIterator old = *this;
    ++*this;
    return old;
  }
  bool operator==(const CountingIterator& o) const { return p_ == o.p_; }
  bool operator!=(const CountingIterator& o) const { return p_ != o.p_; }

 private:
  const char* p_;
  LineCounter* counter_;
};

// Builds the DOM (nlohmann's own SAX DOM builder) and notes the line of every value by its JSON
// pointer, so that errors found later can name a line.
class LineSax {
 public:
  LineSax(json& root, const LineCounter* counter) : dom_(root, false), counter_(counter) {}

  bool null() { return note() && dom_.null(); }
  bool boolean(bool v) { return note() && dom_.boolean(v); }
  bool number_integer(json::number_integer_t v) { return note() && dom_.number_integer(v); }
  bool number_unsigned(json::number_unsigned_t v) { return note() && dom_.number_unsigned(v); }
  bool number_float(json::number_float_t v, const json::string_t& s) { return note() && dom_.number_float(v, s); }
  bool string(json::string_t& v) { return note() && dom_.string(v); }
  bool binary(json::binary_t& v) { return note() && dom_.binary(v); }
  bool start_object(std::size_t n) { return open(false) && dom_.start_object(n); }
  bool end_object() { return close() && dom_.end_object(); }
  bool start_array(std::size_t n) { return open(true) && dom_.start_array(n); }
  bool end_array() { return close() && dom_.end_array(); }
  bool key(json::string_t& k) {
    stack_.back().key = escape(k);
    return dom_.key(k);
  }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception& e) {
    error_line_ = counter_->line();
    error_ = e.what();
    return false;
  }

  const std::map<std::string, int>& lines() const { return lines_; }
  int error_line() const { return error_line_; }
  const std::string& error() const { return error_; }

 private:
  struct Level {
    bool array = false;
    std::size_t index = 0;
    std::string key, path;
  };

  // the pointer of the value being read; arrays count their elements
  std::string here() {
    if (stack_.empty()) return "";
    Level& l = stack_.back();
    return l.path + "/" + (l.array ? std::to_string(l.index++) : l.key);
  }
  bool note() {
    lines_.emplace(here(), counter_->line());
    return true;
  }
  bool open(bool array) {
    const std::string path = here();
    lines_.emplace(path, counter_->line());
    stack_.push_back({array, 0, "", path});
    return true;
  }
  bool close() {
    stack_.pop_back();
    return true;
  }

  nlohmann::detail::json_sax_dom_parser<json> dom_;
  const LineCounter* counter_;
  std::vector<Level> stack_;
  std::map<std::string, int> lines_;
  int error_line_ = 0;
  std::string error_;
};

Vec2d rel_to_abs(const Vec2d& a, const Vec2d& b, const Vec2d& rel) {
  // pygarment utils.rel_to_abs_2d: x along the edge, y along the edge turned 90 degrees left
  const Vec2d e = b - a;
  return a + rel.x() * e + rel.y() * Vec2d(-e.y(), e.x());
}

// Points of the circle arc from a to b with radius r (pygarment CircleEdge from_points_radius),
// excluding a, including b; none when the arc needs more than kMaxOutlinePoints chords.
std::vector<Vec2d> flatten_arc(const Vec2d& a, const Vec2d& b, double r, bool large_arc, bool right) {
  const Vec2d chord = b - a;
  const double d = chord.norm();
  const double centre_r = std::sqrt(std::max(0.0, r * r - d * d / 4));
  const double h = (large_arc ? r + centre_r : r - centre_r) * (right ? -1 : 1);  // arc midpoint off the chord
  const Vec2d side = Vec2d(-chord.y(), chord.x()) / d;
  const Vec2d mid = a + chord / 2 + h * side;
  const Vec2d centre = a + chord / 2 + (h - std::copysign(r, h)) * side;
  // sweep from a to b through the arc midpoint
  auto angle = [&](const Vec2d& p) { return std::atan2(p.y() - centre.y(), p.x() - centre.x()); };
  auto ccw = [](double x) { return x - 2 * M_PI * std::floor(x / (2 * M_PI)); };
  const double a0 = angle(a), ccw_end = ccw(angle(b) - a0);
  const double sweep = ccw(angle(mid) - a0) < ccw_end ? ccw_end : ccw_end - 2 * M_PI;
  const double radius = (a - centre).norm();
  const double chords = std::ceil(std::abs(sweep) * radius / kChordCm);
  if (!(chords <= kMaxOutlinePoints)) return {};
  const int n = std::max(2, static_cast<int>(chords));
  std::vector<Vec2d> out;
  for (int k = 1; k < n; ++k) {
    const double t = a0 + sweep * k / n;
    out.push_back(centre + radius * Vec2d(std::cos(t), std::sin(t)));
  }
  out.push_back(b);
  return out;
}

// pygarment's rotation: intrinsic XYZ Euler angles [deg]
Eigen::Matrix3d garmentcode_rotation(const Eigen::Vector3d& deg) {
  const double d2r = M_PI / 180;
  return (Eigen::AngleAxisd(deg.x() * d2r, Eigen::Vector3d::UnitX()) *
          Eigen::AngleAxisd(deg.y() * d2r, Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(deg.z() * d2r, Eigen::Vector3d::UnitZ()))
      .toRotationMatrix();
}

// R = Ry(yaw) Rz(roll) Rx(pitch), the order of sim's Placement
void set_rotation(Placement& p, const Eigen::Matrix3d& r) {
  const double r2d = 180 / M_PI;
  const double roll = std::asin(std::clamp(r(1, 0), -1.0, 1.0));
  double yaw = 0, pitch = 0;
  if (std::abs(r(1, 0)) < 1 - 1e-12) {
    yaw = std::atan2(-r(2, 0), r(0, 0));
    pitch = std::atan2(-r(1, 2), r(1, 1));
  } else {
    yaw = std::atan2(r(0, 2), r(2, 2));
  }
  p.yaw_deg = Real(yaw * r2d);
  p.roll_deg = Real(roll * r2d);
  p.pitch_deg = Real(pitch * r2d);
}

class Converter {
 public:
  Converter(std::string file, const Box3& body) : file_(std::move(file)), body_(body) {}

  Pattern run(std::string_view text) {
    parse(text);
    const json& spec = at(doc_, "/pattern", json::value_t::object);
    read_properties();
    pattern_.name = stem();
    // panels in `panel_order` when given, else in key order
    const json& panels = at(spec, "/pattern/panels", json::value_t::object);
    std::vector<std::string> order;
    if (spec.contains("panel_order")) {
      const json& po = at(spec, "/pattern/panel_order", json::value_t::array);
      for (std::size_t i = 0; i < po.size(); ++i) {
        const std::string n =
            at(po, "/pattern/panel_order/" + std::to_string(i), json::value_t::string).get<std::string>();
        if (!panels.contains(n))
          fail("/pattern/panel_order/" + std::to_string(i),
               "panel_order names panel '" + n + "', which is not in panels");
        order.push_back(n);
      }
      for (const auto& [n, p] : panels.items())
        if (std::find(order.begin(), order.end(), n) == order.end()) order.push_back(n);
    } else {
      for (const auto& [n, p] : panels.items()) order.push_back(n);
    }
    for (const auto& n : order) panel(n, panels.at(n));
    stitches(at(spec, "/pattern/stitches", json::value_t::array));
    return validated_pattern(std::move(pattern_), file_);
  }

 private:
  [[noreturn]] void fail(const std::string& pointer, const std::string& message) const {
    // the closest enclosing value that has a line
    std::string p = pointer;
    int line = 0;
    while (true) {
      const auto it = lines_.find(p);
      if (it != lines_.end()) {
        line = it->second;
        break;
      }
      const auto slash = p.find_last_of('/');
      if (slash == std::string::npos) break;
      p = p.substr(0, slash);
    }
    throw InputError(located(file_, line, message));
  }

  void parse(std::string_view text) {
    LineCounter counter;
    LineSax sax(doc_, &counter);
    const CountingIterator first(text.data(), &counter), last(text.data() + text.size(), &counter);
    const bool ok = json::sax_parse(first, last, &sax);
    if (!ok) throw InputError(located(file_, sax.error_line(), "not valid JSON: " + sax.error()));
    lines_ = sax.lines();
  }

  // the value at `pointer` (absolute, for messages) inside `parent`, of the given type
  const json& at(const json& parent, const std::string& pointer, json::value_t type) const {
    const auto slash = pointer.find_last_of('/');
    const std::string key = pointer.substr(slash + 1);
    const json* v = nullptr;
    if (parent.is_object() && parent.contains(key)) v = &parent.at(key);
    if (parent.is_array()) {
      const std::size_t i = std::stoul(key);
      if (i < parent.size()) v = &parent.at(i);
    }
    if (!v) fail(pointer.substr(0, slash), "missing '" + key + "' (" + pointer + ")");
    const bool number = type == json::value_t::number_float, integer = type == json::value_t::number_integer;
    const bool ok = number ? v->is_number() : integer ? v->is_number_integer() : v->type() == type;
    if (!ok)
      fail(pointer, pointer + " must be " +
                        (number    ? std::string("a number")
                         : integer ? std::string("an integer")
                                   : std::string(json(type).type_name())));
    if (number && !std::isfinite(v->get<double>())) fail(pointer, pointer + " is not a finite number");
    return *v;
  }

  double number(const json& parent, const std::string& pointer) const {
    return at(parent, pointer, json::value_t::number_float).get<double>();
  }

  Vec2d point2(const json& parent, const std::string& pointer) const {
    const json& a = at(parent, pointer, json::value_t::array);
    if (a.size() != 2) fail(pointer, pointer + " must hold 2 numbers");
    return Vec2d(number(a, pointer + "/0"), number(a, pointer + "/1"));
  }

  Eigen::Vector3d point3(const json& parent, const std::string& pointer) const {
    const json& a = at(parent, pointer, json::value_t::array);
    if (a.size() != 3) fail(pointer, pointer + " must hold 3 numbers");
    return Eigen::Vector3d(number(a, pointer + "/0"), number(a, pointer + "/1"), number(a, pointer + "/2"));
  }

  std::string stem() const {
    const auto slash = file_.find_last_of('/');
    std::string s = slash == std::string::npos ? file_ : file_.substr(slash + 1);
    const auto dot = s.find_last_of('.');
    return dot == std::string::npos || dot == 0 ? s : s.substr(0, dot);
  }

  // units and curvature convention
  void read_properties() {
    if (!doc_.contains("properties")) return;
    const json& p = at(doc_, "/properties", json::value_t::object);
    if (p.contains("units_in_meter")) {
      const double u = number(p, "/properties/units_in_meter");
      if (!(u > 0)) fail("/properties/units_in_meter", "units_in_meter must be > 0");
      to_cm_ = 100.0 / u;
    }
    if (p.contains("curvature_coords")) {
      const std::string c = at(p, "/properties/curvature_coords", json::value_t::string).get<std::string>();
      if (c != "relative" && c != "absolute")
        fail("/properties/curvature_coords", "curvature_coords must be relative or absolute, got '" + c + "'");
      relative_ = c == "relative";
    }
  }

  // one panel: vertices, an edge loop with curves, placement
  void panel(const std::string& name, const json& pj) {
    const std::string base = "/pattern/panels/" + escape(name);
    if (!pj.is_object()) fail(base, base + " must be an object");
    if (name.find('.') != std::string::npos) fail(base, "panel name '" + name + "' must not contain '.'");
    const json& vs = at(pj, base + "/vertices", json::value_t::array);
    std::vector<Vec2d> verts;
    for (std::size_t i = 0; i < vs.size(); ++i)
      verts.push_back(to_cm_ * point2(vs, base + "/vertices/" + std::to_string(i)));
    const json& es = at(pj, base + "/edges", json::value_t::array);
    if (es.size() < 2) fail(base + "/edges", "panel '" + name + "' needs at least 2 edges");
    Panel p;
    p.name = name;
    std::vector<std::array<int, 2>> ends;
    for (std::size_t e = 0; e < es.size(); ++e) {
      const std::string ep = base + "/edges/" + std::to_string(e);
      const json& ej = at(es, ep, json::value_t::object);
      const json& en = at(ej, ep + "/endpoints", json::value_t::array);
      if (en.size() != 2) fail(ep + "/endpoints", "endpoints must hold 2 vertex indices");
      std::array<int, 2> ab{};
      for (std::size_t k = 0; k < 2; ++k) {
        const json& idx = en.at(k);
        if (!idx.is_number_integer() || idx.get<long long>() < 0 ||
            idx.get<long long>() >= static_cast<long long>(verts.size()))
          fail(ep + "/endpoints/" + std::to_string(k),
               "edge " + std::to_string(e) + " of panel '" + name + "' names a missing vertex");
        ab[k] = idx.get<int>();
      }
      if (e > 0 && ab[0] != ends.back()[1])
        fail(ep, "edges of panel '" + name + "' do not form a loop: edge " + std::to_string(e) + " starts at vertex " +
                     std::to_string(ab[0]) + ", edge " + std::to_string(e - 1) + " ended at " +
                     std::to_string(ends.back()[1]));
      ends.push_back(ab);
      if (e == 0) p.outline.push_back(verts[static_cast<std::size_t>(ab[0])]);
      p.edge_begin.push_back(static_cast<int>(p.outline.size()) - 1);
      auto pts = edge_points(ej, ep, verts[static_cast<std::size_t>(ab[0])], verts[static_cast<std::size_t>(ab[1])]);
      if (e + 1 == es.size()) pts.pop_back();  // the loop's end is its start
      p.outline.insert(p.outline.end(), pts.begin(), pts.end());
      if (p.outline.size() > static_cast<std::size_t>(kMaxOutlinePoints))
        fail(ep, "outline of panel '" + name + "' has more than " + std::to_string(kMaxOutlinePoints) + " points");
    }
    if (ends.back()[1] != ends.front()[0])
      fail(base + "/edges",
           "outline of panel '" + name + "' is not closed: its last edge does not end where the first starts");
    if (outline_self_intersects(p.outline)) fail(base, "outline of panel '" + name + "' intersects itself");
    placement(p, pj, base);
    panel_ends_.push_back(ends);
    panel_vertices_.push_back(verts);
    pattern_.panels.push_back(std::move(p));
  }

  // one edge's points after its start: straight, Bezier or circle arc
  std::vector<Vec2d> edge_points(const json& ej, const std::string& ep, const Vec2d& a, const Vec2d& b) const {
    if ((b - a).norm() < 1e-9) fail(ep, "edge has zero length");
    if (!ej.contains("curvature")) return {b};
    const json& c = at(ej, ep + "/curvature", json::value_t::object);
    const std::string type = at(c, ep + "/curvature/type", json::value_t::string).get<std::string>();
    const json& params = at(c, ep + "/curvature/params", json::value_t::array);
    if (type == "circle") {
      if (params.size() != 3) fail(ep + "/curvature/params", "circle params must be [radius, large_arc, right]");
      const double r = to_cm_ * number(params, ep + "/curvature/params/0");
      if (!(r > 0)) fail(ep + "/curvature/params/0", "circle radius must be > 0");
      auto arc = flatten_arc(a, b, r, number(params, ep + "/curvature/params/1") != 0,
                             number(params, ep + "/curvature/params/2") != 0);
      if (arc.empty()) fail(ep, "circle arc longer than " + std::to_string(kMaxOutlinePoints) + " cm");
      return arc;
    }
    const std::size_t n = type == "quadratic" ? 1 : type == "cubic" ? 2 : 0;
    if (n == 0)
      fail(ep + "/curvature/type", "unknown curvature type '" + type + "' (expected quadratic, cubic, circle)");
    if (params.size() != n)
      fail(ep + "/curvature/params", type + " curvature needs " + std::to_string(n) + " control points");
    std::vector<Vec2d> controls;
    for (std::size_t k = 0; k < n; ++k) {
      const Vec2d q = point2(params, ep + "/curvature/params/" + std::to_string(k));
      controls.push_back(relative_ ? rel_to_abs(a, b, q) : to_cm_ * q);
    }
    double len = (controls.front() - a).norm() + (b - controls.back()).norm();
    for (std::size_t k = 1; k < controls.size(); ++k) len += (controls[k] - controls[k - 1]).norm();
    const double chords = std::ceil(len / kChordCm);
    if (!(chords <= kMaxOutlinePoints)) fail(ep, "curve longer than " + std::to_string(kMaxOutlinePoints) + " cm");
    return flatten_bezier(a, controls, b, std::max(2, static_cast<int>(chords)));
  }

  // translation height as a fraction of the reference body; x, z as cm from its box centre
  void placement(Panel& p, const json& pj, const std::string& base) {
    Eigen::Vector3d t = Eigen::Vector3d::Zero(), deg = Eigen::Vector3d::Zero();
    if (pj.contains("translation")) t = to_cm_ * point3(pj, base + "/translation");
    if (pj.contains("rotation")) deg = point3(pj, base + "/rotation");
    const Eigen::Vector3d lo = body_.min.cast<double>() * 100, size = body_.size().cast<double>() * 100;
    const Eigen::Vector3d centre = lo + size / 2;
    p.placement.anchor = Vec3(0.5f, Real((t.y() - lo.y()) / size.y()), 0.5f);
    p.placement.offset_cm = Vec3(Real(t.x() - centre.x()), 0, Real(t.z() - centre.z()));
    const Eigen::Matrix3d r = garmentcode_rotation(deg);
    set_rotation(p.placement, r);
    panel_rotation_.push_back(r);
    panel_translation_.push_back(t);
  }

  // a stitch side {panel, edge}
  std::array<int, 2> side(const json& sj, const std::string& sp) const {
    if (!sj.is_object()) fail(sp, sp + " must be an object with 'panel' and 'edge'");
    const std::string n = at(sj, sp + "/panel", json::value_t::string).get<std::string>();
    int panel = -1;
    for (std::size_t i = 0; i < pattern_.panels.size(); ++i)
      if (pattern_.panels[i].name == n) panel = static_cast<int>(i);
    if (panel < 0) fail(sp + "/panel", "stitch names panel '" + n + "', which is not in panels");
    const json& e = at(sj, sp + "/edge", json::value_t::number_integer);
    const long long edge = e.get<long long>();
    if (edge < 0 || edge >= pattern_.panels[static_cast<std::size_t>(panel)].edge_count())
      fail(sp + "/edge", "stitch names edge " + std::to_string(edge) + " of panel '" + n + "', which has " +
                             std::to_string(pattern_.panels[static_cast<std::size_t>(panel)].edge_count()) + " edges");
    return {panel, static_cast<int>(edge)};
  }

  // an edge's end points in GarmentCode's 3D placement [cm]
  std::array<Eigen::Vector3d, 2> ends3(const std::array<int, 2>& pe) const {
    const auto pi = static_cast<std::size_t>(pe[0]);
    const auto& ab = panel_ends_[pi][static_cast<std::size_t>(pe[1])];
    std::array<Eigen::Vector3d, 2> out;
    for (std::size_t k = 0; k < 2; ++k) {
      const Vec2d v = panel_vertices_[pi][static_cast<std::size_t>(ab[k])];
      out[k] = panel_rotation_[pi] * Eigen::Vector3d(v.x(), v.y(), 0) + panel_translation_[pi];
    }
    return out;
  }

  void stitches(const json& sj) {
    std::map<std::array<int, 4>, std::size_t> seen;
    for (std::size_t i = 0; i < sj.size(); ++i) {
      const std::string sp = "/pattern/stitches/" + std::to_string(i);
      const json& s = at(sj, sp, json::value_t::array);
      if (s.size() < 2) fail(sp, "a stitch needs two sides");
      const auto a = side(s.at(0), sp + "/0"), b = side(s.at(1), sp + "/1");
      if (a == b) fail(sp, "stitch sews an edge to itself");
      std::array<int, 4> key{a[0], a[1], b[0], b[1]};
      if (key[0] > key[2] || (key[0] == key[2] && key[1] > key[3])) key = {key[2], key[3], key[0], key[1]};
      const auto [it, fresh] = seen.emplace(key, i);
      if (!fresh) fail(sp, "duplicated stitch (same edges as stitch " + std::to_string(it->second) + ")");
      // orientation: whichever pairing of the end points is closer in 3D
      const auto ea = ends3(a), eb = ends3(b);
      const double aligned = (ea[0] - eb[0]).norm() + (ea[1] - eb[1]).norm();
      const double reversed = (ea[0] - eb[1]).norm() + (ea[1] - eb[0]).norm();
      pattern_.seams.push_back({a[0], a[1], b[0], b[1], reversed <= aligned});
    }
  }

  std::string file_;
  Box3 body_;
  json doc_;
  std::map<std::string, int> lines_;
  double to_cm_ = 1.0;  // GarmentCode files are in cm unless units_in_meter says otherwise
  bool relative_ = true;
  Pattern pattern_;
  std::vector<std::vector<std::array<int, 2>>> panel_ends_;
  std::vector<std::vector<Vec2d>> panel_vertices_;
  std::vector<Eigen::Matrix3d> panel_rotation_;
  std::vector<Eigen::Vector3d> panel_translation_;
};

bool readable(const std::string& path) { return std::ifstream(path).good(); }

}  // namespace

Pattern parse_garmentcode(std::string_view json_text, const std::string& file, const Box3& reference_body) {
  return Converter(file, reference_body).run(json_text);
}

Box3 obj_bounding_box(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(located(path, 0, "cannot open the reference body"));
  Box3 box;
  bool any = false;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    if (line.rfind("v ", 0) != 0) continue;
    std::istringstream s(line.substr(2));
    Vec3 p;
    if (!(s >> p.x() >> p.y() >> p.z()) || !p.allFinite()) throw InputError(located(path, number, "bad vertex line"));
    box.min = any ? box.min.cwiseMin(p) : p;
    box.max = any ? box.max.cwiseMax(p) : p;
    any = true;
  }
  if (!any || !(box.size().y() > 0))
    throw InputError(located(path, 0, "the reference body has no vertices or no height"));
  return box;
}

Pattern load_garmentcode(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(located(path, 0, "cannot open the GarmentCode file"));
  std::ostringstream buf;
  buf << in.rdbuf();
  // the body GarmentCode placed the panels for
  const auto slash = path.find_last_of('/');
  const std::string beside =
      (slash == std::string::npos ? std::string() : path.substr(0, slash + 1)) + "mean_female.obj";
  const std::string shared = data_path("garments/garmentcode/mean_female.obj");
  if (!readable(beside) && !readable(shared))
    throw InputError(located(path, 0,
                             "GarmentCode placements need their reference body mean_female.obj (looked in " + beside +
                                 " and " + shared + ")"));
  return parse_garmentcode(buf.str(), path, obj_bounding_box(readable(beside) ? beside : shared));
}

}  // namespace clothbench
