#include "clothbench/io/pattern_file.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "clothbench/io/errors.hpp"

namespace clothbench {

namespace {

// One line of the file split into words, comments removed.
struct TextLine {
  int number = 0;
  std::vector<std::string_view> words;
};

// Where a seam was written, resolved once every panel is known.
struct SeamDraft {
  int line = 0;
  std::string panel_a, edge_a, panel_b, edge_b;
  bool reversed = true;
};

// A panel while it is being read: its edges' names and lines, and the outline's end point.
struct PanelDraft {
  Panel panel;
  int line = 0;
  std::vector<std::string> edge_names;
  std::vector<int> edge_lines;
  std::vector<int> segment_edge;  // edge of each outline segment
  bool started = false, closed = false;
  Vec2d start = Vec2d::Zero(), cursor = Vec2d::Zero();
};

std::string stem(const std::string& path) {
  const auto slash = path.find_last_of('/');
  std::string s = slash == std::string::npos ? path : path.substr(slash + 1);
  const auto dot = s.find_last_of('.');
  if (dot != std::string::npos && dot > 0) s = s.substr(0, dot);
  // a name is one word: spaces become underscores
  std::replace_if(
      s.begin(), s.end(), [](char c) { return c == ' ' || c == '\t'; }, '_');
  return s;
}


// Length of a valid UTF-8 sequence starting at s[i], or 0.
int utf8_length(std::string_view s, std::size_t i) {
  const auto c = static_cast<unsigned char>(s[i]);
  const int n = c < 0x80 ? 1 : (c >> 5) == 0x6 ? 2 : (c >> 4) == 0xe ? 3 : (c >> 3) == 0x1e ? 4 : 0;
  if (n == 0 || i + static_cast<std::size_t>(n) > s.size()) return 0;
  for (int k = 1; k < n; ++k)
    if ((static_cast<unsigned char>(s[i + static_cast<std::size_t>(k)]) >> 6) != 0x2) return 0;
  return n;
}

std::string format_number(double v) {
  std::array<char, 32> buf{};
  const auto r = std::to_chars(buf.data(), buf.data() + buf.size(), v);
  return std::string(buf.data(), r.ptr);
}

class Parser {
 public:
  Parser(std::string_view text, std::string file) : text_(text), file_(std::move(file)) {}

  Pattern run() {
    pattern_.name = stem(file_);
    const std::vector<TextLine> lines = split();
    for (const auto& l : lines) {
      line_ = l.number;
      statement(l.words);
    }
    line_ = last_line_;
    if (current_) {
      line_ = current_->line;
      fail("panel '" + current_->panel.name + "' has no 'end'");
    }
    if (drafts_.empty()) fail("empty pattern: no panels");
    for (const auto& d : drafts_) {
      pattern_.panels.push_back(d.panel);
      pattern_.panels.back().edge_names = d.edge_names;
    }
    resolve_seams();
    return validated_pattern(std::move(pattern_), file_);
  }

 private:
  [[noreturn]] void fail(const std::string& message) const { throw InputError(located(file_, line_, message)); }

  // splits the text into lines of words; rejects binary data and invalid UTF-8
  std::vector<TextLine> split() {
    check_binary();
    std::vector<TextLine> out;
    int number = 1;
    std::size_t begin = 0;
    while (begin <= text_.size()) {
      if (begin == text_.size() && number > 1) break;  // no line after the final newline
      std::size_t end = text_.find('\n', begin);
      if (end == std::string_view::npos) end = text_.size();
      line_ = number;
      std::string_view row = text_.substr(begin, end - begin);
      if (!row.empty() && row.back() == '\r') row.remove_suffix(1);
      check_text(row);
      const auto hash = row.find('#');
      if (hash != std::string_view::npos) row = row.substr(0, hash);
      TextLine tl{number, words(row)};
      if (!tl.words.empty()) out.push_back(std::move(tl));
      last_line_ = number;
      if (end == text_.size()) break;
      begin = end + 1;
      ++number;
    }
    return out;
  }

  // control characters anywhere (other than tab and line ends) mean a binary file
  void check_binary() {
    line_ = 1;
    std::size_t column = 1;
    for (std::size_t i = 0; i < text_.size(); ++i, ++column) {
      const auto c = static_cast<unsigned char>(text_[i]);
      if (c == '\n') line_ += 1, column = 0;
      if ((c < 0x20 && c != '\t' && c != '\n' && c != '\r') || c == 0x7f) {
        std::ostringstream m;
        m << "binary data, not a pattern file (byte 0x" << std::hex << int(c) << std::dec << " at column " << column
          << ")";
        fail(m.str());
      }
    }
  }

  void check_text(std::string_view row) const {
    for (std::size_t i = 0; i < row.size();) {
      const int n = utf8_length(row, i);
      if (n == 0) fail("not UTF-8 text (bad byte at column " + std::to_string(i + 1) + ")");
      i += static_cast<std::size_t>(n);
    }
  }

  static std::vector<std::string_view> words(std::string_view row) {
    std::vector<std::string_view> out;
    std::size_t i = 0;
    while (i < row.size()) {
      while (i < row.size() && (row[i] == ' ' || row[i] == '\t')) ++i;
      std::size_t j = i;
      while (j < row.size() && row[j] != ' ' && row[j] != '\t') ++j;
      if (j > i) out.push_back(row.substr(i, j - i));
      i = j;
    }
    return out;
  }

  double number(std::string_view w, const std::string& what) const {
    double v = 0;
    const auto r = std::from_chars(w.data(), w.data() + w.size(), v);
    if (r.ec != std::errc() || r.ptr != w.data() + w.size()) fail(what + ": '" + std::string(w) + "' is not a number");
    if (!std::isfinite(v)) fail(what + ": '" + std::string(w) + "' is not a finite number");
    return v;
  }

  // the numbers that follow a keyword: `count` of them starting at word `at`
  std::vector<double> numbers(const std::vector<std::string_view>& w, std::size_t at, std::size_t count,
                              const std::string& what) const {
    if (w.size() < at + count) fail(what + " needs " + std::to_string(count) + " numbers");
    std::vector<double> out;
    for (std::size_t k = 0; k < count; ++k) out.push_back(number(w[at + k], what));
    return out;
  }

  std::string name(std::string_view w, const std::string& what) const {
    if (w.find('.') != std::string_view::npos) fail(what + " name '" + std::string(w) + "' must not contain '.'");
    return std::string(w);
  }

  void expect_count(const std::vector<std::string_view>& w, std::size_t n, const std::string& usage) const {
    if (w.size() != n) fail("expected '" + usage + "'");
  }

  void statement(const std::vector<std::string_view>& w) {
    const std::string_view key = w[0];
    if (key == "garment") return garment(w);
    if (key == "curve_step") return curve_step(w);
    if (key == "panel") return begin_panel(w);
    if (key == "seam") return seam(w);
    if (key == "end") return end_panel(w);
    if (key == "place" || key == "start" || key == "edge" || key == "rect" || key == "attach") {
      if (!current_) fail("'" + std::string(key) + "' outside a panel (write it between 'panel NAME' and 'end')");
      if (key == "place") return place(w);
      if (key == "start") return start(w);
      if (key == "edge") return edge(w);
      if (key == "rect") return rect(w);
      return attach(w);
    }
    fail("unknown keyword '" + std::string(key) +
         "' (expected garment, curve_step, panel, place, start, edge, rect, attach, end, seam)");
  }

  void garment(const std::vector<std::string_view>& w) {
    expect_count(w, 2, "garment NAME");
    pattern_.name = std::string(w[1]);
  }

  void curve_step(const std::vector<std::string_view>& w) {
    expect_count(w, 2, "curve_step CM");
    const double v = number(w[1], "curve_step");
    if (!(v > 0)) fail("curve_step must be > 0 cm, got " + std::string(w[1]));
    curve_step_ = v;
  }

  void begin_panel(const std::vector<std::string_view>& w) {
    if (current_) fail("'panel' inside panel '" + current_->panel.name + "' (close it with 'end' first)");
    expect_count(w, 2, "panel NAME");
    const std::string n = name(w[1], "panel");
    for (const auto& d : drafts_)
      if (d.panel.name == n) fail("panel '" + n + "' is defined twice (first at line " + std::to_string(d.line) + ")");
    drafts_.emplace_back();
    current_ = &drafts_.back();
    current_->panel.name = n;
    current_->line = line_;
  }

  void place(const std::vector<std::string_view>& w) {
    Placement& p = current_->panel.placement;
    for (std::size_t i = 1; i < w.size();) {
      const std::string key(w[i]);
      if (key == "anchor" || key == "offset") {
        const auto v = numbers(w, i + 1, 3, "place " + key);
        if (key == "anchor" && (std::min({v[0], v[1], v[2]}) < 0 || std::max({v[0], v[1], v[2]}) > 1))
          fail("place anchor: fractions of the body's bounding box must be in [0, 1] (move further with 'offset')");
        (key == "anchor" ? p.anchor : p.offset_cm) = Vec3(Real(v[0]), Real(v[1]), Real(v[2]));
        i += 4;
      } else if (key == "yaw" || key == "pitch" || key == "roll" || key == "wrap") {
        const double v = numbers(w, i + 1, 1, "place " + key)[0];
        if (key == "wrap" && v < 0) fail("place wrap: the radius must be >= 0 cm, got " + std::string(w[i + 1]));
        (key == "yaw"     ? p.yaw_deg
         : key == "pitch" ? p.pitch_deg
         : key == "roll"  ? p.roll_deg
                          : p.wrap_radius_cm) = Real(v);
        i += 2;
      } else {
        fail("place: unknown key '" + key + "' (expected anchor, offset, yaw, pitch, roll, wrap)");
      }
    }
  }

  void start(const std::vector<std::string_view>& w) {
    if (current_->started) fail("panel '" + current_->panel.name + "' already has a start point");
    expect_count(w, 3, "start X Y");
    const auto v = numbers(w, 1, 2, "start");
    current_->started = true;
    current_->start = current_->cursor = Vec2d(v[0], v[1]);
    current_->panel.outline.push_back(current_->start);
  }

  // edge NAME SEGMENT...: each segment continues from the current point
  void edge(const std::vector<std::string_view>& w) {
    PanelDraft& d = *current_;
    if (!d.started) fail("edge before 'start X Y' in panel '" + d.panel.name + "'");
    if (d.closed) fail("edge after the outline of panel '" + d.panel.name + "' was closed");
    if (w.size() < 3)
      fail("expected 'edge NAME SEGMENT...' (segments: line X Y, quad CX CY X Y, cubic C1X C1Y C2X C2Y X Y, close)");
    add_edge_name(name(w[1], "edge"));
    for (std::size_t i = 2; i < w.size();) {
      if (d.closed) fail("segment after the outline of panel '" + d.panel.name + "' was closed");
      const std::string kind(w[i]);
      std::vector<Vec2d> pts;
      if (kind == "line" || kind == "quad" || kind == "cubic") {
        const std::size_t n = kind == "line" ? 2 : kind == "quad" ? 4 : 6;
        const auto v = numbers(w, i + 1, n, kind);
        std::vector<Vec2d> c;
        for (std::size_t k = 0; k + 2 < n; k += 2) c.push_back(Vec2d(v[k], v[k + 1]));
        const Vec2d to(v[n - 2], v[n - 1]);
        pts = c.empty() ? std::vector<Vec2d>{to} : flatten_bezier(d.cursor, c, to, curve_segments(d.cursor, c, to));
        i += n + 1;
      } else if (kind == "close") {
        pts = {d.start};
        i += 1;
      } else {
        fail("unknown segment '" + kind + "' (expected line, quad, cubic, close)");
      }
      for (const auto& p : pts) add_point(p);
    }
  }

  // segments for a curve: its control polygon divided into pieces of at most curve_step
  int curve_segments(const Vec2d& a, const std::vector<Vec2d>& c, const Vec2d& b) const {
    double len = (c.front() - a).norm() + (b - c.back()).norm();
    for (std::size_t k = 1; k < c.size(); ++k) len += (c[k] - c[k - 1]).norm();
    const double segments = std::ceil(len / curve_step_);
    if (!(segments <= kMaxOutlinePoints))
      fail("curve of panel '" + current_->panel.name + "' is " + format_number(len) + " cm long: more than " +
           std::to_string(kMaxOutlinePoints) + " pieces of curve_step " + format_number(curve_step_) + " cm");
    return std::max(2, static_cast<int>(segments));
  }

  void add_edge_name(const std::string& n) {
    PanelDraft& d = *current_;
    for (std::size_t e = 0; e < d.edge_names.size(); ++e)
      if (d.edge_names[e] == n)
        fail("panel '" + d.panel.name + "' has two edges named '" + n + "' (first at line " +
             std::to_string(d.edge_lines[e]) + ")");
    d.edge_names.push_back(n);
    d.edge_lines.push_back(line_);
    d.panel.edge_begin.push_back(static_cast<int>(d.panel.outline.size()) - 1);
  }

  // appends one outline point; reaching the start point closes the outline
  void add_point(const Vec2d& p) {
    PanelDraft& d = *current_;
    const double scale = 1 + d.cursor.norm() + p.norm();
    if ((p - d.cursor).norm() <= 1e-9 * scale)
      fail("zero-length segment at (" + format_number(p.x()) + ", " + format_number(p.y()) + ") in panel '" +
           d.panel.name + "'");
    d.segment_edge.push_back(static_cast<int>(d.edge_names.size()) - 1);
    d.cursor = p;
    if ((p - d.start).norm() <= 1e-9 * scale) {
      d.closed = true;
      return;
    }
    if (d.panel.outline.size() >= static_cast<std::size_t>(kMaxOutlinePoints))
      fail("outline of panel '" + d.panel.name + "' has more than " + std::to_string(kMaxOutlinePoints) + " points");
    d.panel.outline.push_back(p);
  }

  // rect W H: a W x H rectangle, bottom edge centred on the origin
  void rect(const std::vector<std::string_view>& w) {
    PanelDraft& d = *current_;
    if (d.started) fail("'rect' in panel '" + d.panel.name + "', which already has an outline");
    expect_count(w, 3, "rect WIDTH HEIGHT");
    const auto v = numbers(w, 1, 2, "rect");
    if (!(v[0] > 0) || !(v[1] > 0))
      fail("rect: width and height must be > 0 cm, got " + std::string(w[1]) + " x " + std::string(w[2]));
    d.started = true;
    d.start = d.cursor = Vec2d(-v[0] / 2, 0);
    d.panel.outline.push_back(d.start);
    const std::array<std::pair<const char*, Vec2d>, 4> sides{{{"bottom", Vec2d(v[0] / 2, 0)},
                                                              {"right", Vec2d(v[0] / 2, v[1])},
                                                              {"top", Vec2d(-v[0] / 2, v[1])},
                                                              {"left", d.start}}};
    for (const auto& [n, p] : sides) {
      add_edge_name(n);
      add_point(p);
    }
  }

  void attach(const std::vector<std::string_view>& w) {
    if (w.size() < 2) fail("expected 'attach EDGE...'");
    for (std::size_t i = 1; i < w.size(); ++i) {
      const int e = edge_index(*current_, std::string(w[i]));
      if (e < 0)
        fail("attach: panel '" + current_->panel.name + "' has no edge '" + std::string(w[i]) +
             "' (attach after the edges)");
      current_->panel.attached_edges.push_back(e);
    }
  }

  static int edge_index(const PanelDraft& d, const std::string& n) {
    const auto it = std::find(d.edge_names.begin(), d.edge_names.end(), n);
    return it == d.edge_names.end() ? -1 : static_cast<int>(it - d.edge_names.begin());
  }

  // end: the outline must be closed, have an area and not cross itself
  void end_panel(const std::vector<std::string_view>& w) {
    if (!current_) fail("'end' outside a panel");
    expect_count(w, 1, "end");
    PanelDraft& d = *current_;
    if (!d.started) fail("panel '" + d.panel.name + "' has no outline (use 'start' and 'edge', or 'rect')");
    if (!d.closed)
      fail("outline of panel '" + d.panel.name + "' is not closed: it ends at (" + format_number(d.cursor.x()) + ", " +
           format_number(d.cursor.y()) + ") but starts at (" + format_number(d.start.x()) + ", " +
           format_number(d.start.y()) + "); end the last edge at the start point or with 'close'");
    if (d.panel.outline.size() < 3) fail("outline of panel '" + d.panel.name + "' has fewer than 3 points");
    check_outline(d);
    current_ = nullptr;
  }

  // sim's outline_fault (Boost.Geometry's validity test), named by the edge at fault and its line
  void check_outline(const PanelDraft& d) {
    const OutlineFault f = outline_fault(d.panel.outline);
    if (f.what.empty()) return;
    std::string message = "outline of panel '" + d.panel.name + "' " + f.what;
    auto edge = [&](int segment) {
      return static_cast<std::size_t>(d.segment_edge[static_cast<std::size_t>(segment)]);
    };
    if (f.segment >= 0) {
      const std::size_t e = edge(f.segment);
      line_ = d.edge_lines[e];
      message += " at (" + format_number(f.at.x()) + ", " + format_number(f.at.y()) + ")";
      if (f.other_segment >= 0) {
        const std::size_t o = edge(f.other_segment);
        message += ": edge '" + d.edge_names[e] + "' meets " +
                   (o == e ? std::string("itself") : "edge '" + d.edge_names[o] + "'");
      } else {
        message += ", in edge '" + d.edge_names[e] + "'";
      }
    }
    fail(message);
  }

  // seam PANEL.EDGE PANEL.EDGE [reversed|aligned]
  void seam(const std::vector<std::string_view>& w) {
    if (current_) fail("'seam' inside panel '" + current_->panel.name + "' (seams go after 'end')");
    if (w.size() != 3 && w.size() != 4) fail("expected 'seam PANEL.EDGE PANEL.EDGE [reversed|aligned]'");
    SeamDraft s;
    s.line = line_;
    split_ref(w[1], s.panel_a, s.edge_a);
    split_ref(w[2], s.panel_b, s.edge_b);
    if (w.size() == 4) {
      if (w[3] != "reversed" && w[3] != "aligned")
        fail("seam orientation '" + std::string(w[3]) + "': expected reversed or aligned");
      s.reversed = w[3] == "reversed";
    }
    seams_.push_back(std::move(s));
  }

  void split_ref(std::string_view ref, std::string& panel, std::string& edge) const {
    const auto dot = ref.find('.');
    if (dot == std::string_view::npos || dot == 0 || dot + 1 == ref.size() ||
        ref.find('.', dot + 1) != std::string_view::npos)
      fail("seam side '" + std::string(ref) + "': expected PANEL.EDGE");
    panel = std::string(ref.substr(0, dot));
    edge = std::string(ref.substr(dot + 1));
  }

  // seams name panels and edges; each edge pair is sewn once
  void resolve_seams() {
    std::map<std::array<int, 4>, int> seen;
    for (const auto& s : seams_) {
      line_ = s.line;
      Seam seam;
      seam.reversed = s.reversed;
      seam.panel_a = panel_index(s.panel_a);
      seam.panel_b = panel_index(s.panel_b);
      seam.edge_a = resolve_edge(seam.panel_a, s.edge_a);
      seam.edge_b = resolve_edge(seam.panel_b, s.edge_b);
      if (seam.panel_a == seam.panel_b && seam.edge_a == seam.edge_b)
        fail("seam sews edge '" + s.edge_a + "' to itself");
      std::array<int, 4> key{seam.panel_a, seam.edge_a, seam.panel_b, seam.edge_b};
      if (key[0] > key[2] || (key[0] == key[2] && key[1] > key[3])) key = {key[2], key[3], key[0], key[1]};
      const auto [it, fresh] = seen.emplace(key, s.line);
      if (!fresh) fail("duplicated seam (the same edges are sewn at line " + std::to_string(it->second) + ")");
      pattern_.seams.push_back(seam);
    }
  }

  int panel_index(const std::string& n) const {
    std::string known;
    for (std::size_t p = 0; p < drafts_.size(); ++p) {
      if (drafts_[p].panel.name == n) return static_cast<int>(p);
      known += (p ? ", " : "") + drafts_[p].panel.name;
    }
    fail("seam names panel '" + n + "', which is not defined (panels: " + known + ")");
  }

  int resolve_edge(int panel, const std::string& n) const {
    const PanelDraft& d = drafts_[static_cast<std::size_t>(panel)];
    const int e = edge_index(d, n);
    if (e >= 0) return e;
    std::string known;
    for (std::size_t k = 0; k < d.edge_names.size(); ++k) known += (k ? ", " : "") + d.edge_names[k];
    fail("seam names edge '" + n + "' of panel '" + d.panel.name + "', which has no such edge (edges: " + known + ")");
  }

  std::string_view text_;
  std::string file_;
  int line_ = 0, last_line_ = 1;
  double curve_step_ = 1.0;  // default chord budget of a flattened curve [cm]
  Pattern pattern_;
  std::vector<PanelDraft> drafts_;
  PanelDraft* current_ = nullptr;  // drafts_.back() while a panel is open, else null
  std::vector<SeamDraft> seams_;
};

}  // namespace

Pattern validated_pattern(Pattern pattern, const std::string& file) {
  // the model's own checks back up the parsers'; their message has no line, so name the file
  try {
    validate_pattern(pattern);
  } catch (const std::invalid_argument& e) {
    throw InputError(located(file, 0, e.what()));
  }
  return pattern;
}

Pattern parse_pattern(std::string_view text, const std::string& name) { return Parser(text, name).run(); }

Pattern load_pattern_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(located(path, 0, "cannot open the pattern file"));
  std::ostringstream buf;
  buf << in.rdbuf();
  return parse_pattern(buf.str(), path);
}

std::string write_pattern(const Pattern& pattern) {
  std::ostringstream out;
  auto xy = [](const Vec2d& p) { return format_number(p.x()) + " " + format_number(p.y()); };
  auto real = [](Real v) { return format_number(static_cast<double>(v)); };
  out << "# written by clothbench (write_pattern)\ngarment " << pattern.name << "\n";
  for (const auto& p : pattern.panels) {
    const Placement& pl = p.placement;
    out << "\npanel " << p.name << "\n  place anchor " << real(pl.anchor.x()) << " " << real(pl.anchor.y()) << " "
        << real(pl.anchor.z()) << " offset " << real(pl.offset_cm.x()) << " " << real(pl.offset_cm.y()) << " "
        << real(pl.offset_cm.z()) << " yaw " << real(pl.yaw_deg) << " pitch " << real(pl.pitch_deg) << " roll "
        << real(pl.roll_deg) << " wrap " << real(pl.wrap_radius_cm) << "\n  start " << xy(p.outline[0]) << "\n";
    // each edge runs from its first point to the next edge's first point (the last one closes)
    const int n = static_cast<int>(p.outline.size());
    for (int e = 0; e < p.edge_count(); ++e) {
      const int s0 = p.edge_begin[static_cast<std::size_t>(e)];
      const int s1 = e + 1 < p.edge_count() ? p.edge_begin[static_cast<std::size_t>(e + 1)] : n;
      out << "  edge " << edge_name(p, e);
      for (int s = s0 + 1; s <= s1; ++s)
        out << (s == n ? " close" : " line " + xy(p.outline[static_cast<std::size_t>(s)]));
      out << "\n";
    }
    if (!p.attached_edges.empty()) {
      out << "  attach";
      for (int e : p.attached_edges) out << " " << edge_name(p, e);
      out << "\n";
    }
    out << "end\n";
  }
  if (!pattern.seams.empty()) out << "\n";
  for (const auto& s : pattern.seams)
    out << "seam " << edge_label(pattern, s.panel_a, s.edge_a) << " " << edge_label(pattern, s.panel_b, s.edge_b) << " "
        << (s.reversed ? "reversed" : "aligned") << "\n";
  return out.str();
}

}  // namespace clothbench
