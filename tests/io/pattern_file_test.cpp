#include "clothbench/io/pattern_file.hpp"
#include "clothbench/io/pattern_loader.hpp"

#include <gtest/gtest.h>

#include <sys/wait.h>
#include "test_support.hpp"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include "clothbench/config.h"
#include "clothbench/io/errors.hpp"

namespace clothbench {
namespace {

const std::string kGarments = std::string(CLOTHBENCH_SOURCE_DIR) + "/scenes/garments/";
const std::string kBad = std::string(CLOTHBENCH_SOURCE_DIR) + "/tests/data/bad/";

// The message of the InputError that parsing `text` throws, or "" when it parses.
std::string parse_error(const std::string& text) {
  try {
    parse_pattern(text, "t.pattern");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

void expect_same(const Pattern& a, const Pattern& b) {
  EXPECT_EQ(a.name, b.name);
  ASSERT_EQ(a.panels.size(), b.panels.size());
  for (std::size_t p = 0; p < a.panels.size(); ++p) {
    const Panel &x = a.panels[p], &y = b.panels[p];
    EXPECT_EQ(x.name, y.name);
    ASSERT_EQ(x.outline.size(), y.outline.size()) << x.name;
    for (std::size_t i = 0; i < x.outline.size(); ++i)
      EXPECT_EQ(x.outline[i], y.outline[i]) << x.name << " point " << i;
    EXPECT_EQ(x.edge_begin, y.edge_begin) << x.name;
    EXPECT_EQ(x.attached_edges, y.attached_edges) << x.name;
    EXPECT_EQ(x.edge_names, y.edge_names) << x.name;
    EXPECT_EQ(x.placement.anchor, y.placement.anchor) << x.name;
    EXPECT_EQ(x.placement.offset_cm, y.placement.offset_cm) << x.name;
    EXPECT_EQ(x.placement.yaw_deg, y.placement.yaw_deg) << x.name;
    EXPECT_EQ(x.placement.pitch_deg, y.placement.pitch_deg) << x.name;
    EXPECT_EQ(x.placement.roll_deg, y.placement.roll_deg) << x.name;
    EXPECT_EQ(x.placement.wrap_radius_cm, y.placement.wrap_radius_cm) << x.name;
  }
  ASSERT_EQ(a.seams.size(), b.seams.size());
  for (std::size_t s = 0; s < a.seams.size(); ++s) {
    EXPECT_EQ(a.seams[s].panel_a, b.seams[s].panel_a);
    EXPECT_EQ(a.seams[s].edge_a, b.seams[s].edge_a);
    EXPECT_EQ(a.seams[s].panel_b, b.seams[s].panel_b);
    EXPECT_EQ(a.seams[s].edge_b, b.seams[s].edge_b);
    EXPECT_EQ(a.seams[s].reversed, b.seams[s].reversed);
  }
}

TEST(PatternFile, ParsesTheExpectedStructure) {
  const Pattern p = parse_pattern(R"(# a comment line
garment demo
curve_step 0.5
panel front   # trailing comment
  place anchor 0.5 0.25 1 offset 1 2 3 yaw 10 pitch 20 roll 30 wrap 15
  start -10 0
  edge hem  line 10 0
  edge side line 10 20
  edge top  quad 0 30 -10 20
  edge left close
  attach top
end
panel back
  rect 20 20
end
seam front.side back.left
seam front.left back.right aligned
)",
                                  "demo.pattern");
  EXPECT_EQ(p.name, "demo");
  ASSERT_EQ(p.panels.size(), 2u);
  const Panel& f = p.panels[0];
  EXPECT_EQ(f.edge_count(), 4);
  EXPECT_EQ(f.edge_begin, (std::vector<int>{0, 1, 2, static_cast<int>(f.outline.size()) - 1}));
  EXPECT_EQ(f.attached_edges, std::vector<int>{2});
  EXPECT_EQ(f.placement.anchor, Vec3(0.5f, 0.25f, 1.f));
  EXPECT_EQ(f.placement.offset_cm, Vec3(1, 2, 3));
  EXPECT_EQ(f.placement.yaw_deg, 10);
  EXPECT_EQ(f.placement.pitch_deg, 20);
  EXPECT_EQ(f.placement.roll_deg, 30);
  EXPECT_EQ(f.placement.wrap_radius_cm, 15);
  // the quadratic curve is flattened into chords no longer than curve_step, all on the curve
  const int curve_points = f.edge_begin[3] - f.edge_begin[2];
  EXPECT_GE(curve_points, 20);
  for (int i = f.edge_begin[2]; i <= f.edge_begin[3]; ++i) {
    const Vec2d q = f.outline[static_cast<std::size_t>(i)];
    // the parabola through (10, 20), control (0, 30), (-10, 20): y = 25 - x^2 / 20
    EXPECT_NEAR(q.y(), 25 - q.x() * q.x() / 20, 1e-9);
  }
  for (std::size_t i = static_cast<std::size_t>(f.edge_begin[2]); i < static_cast<std::size_t>(f.edge_begin[3]); ++i)
    EXPECT_LE((f.outline[i + 1] - f.outline[i]).norm(), 0.5 + 1e-9);
  // rect: bottom edge centred on the origin, edges bottom, right, top, left
  const Panel& b = p.panels[1];
  EXPECT_EQ(b.outline, (std::vector<Vec2d>{Vec2d(-10, 0), Vec2d(10, 0), Vec2d(10, 20), Vec2d(-10, 20)}));
  EXPECT_EQ(b.edge_begin, (std::vector<int>{0, 1, 2, 3}));
  ASSERT_EQ(p.seams.size(), 2u);
  EXPECT_EQ(p.seams[0].panel_a, 0);
  EXPECT_EQ(p.seams[0].edge_a, 1);
  EXPECT_EQ(p.seams[0].panel_b, 1);
  EXPECT_EQ(p.seams[0].edge_b, 3);
  EXPECT_TRUE(p.seams[0].reversed);
  EXPECT_FALSE(p.seams[1].reversed);
}

TEST(PatternFile, GarmentFilesRoundTrip) {
  for (const char* name : {"shirt", "shirt_sleeves", "skirt", "dress", "dress_sleeves", "trousers",
                           "durupinar_trousers", "durupinar_skirt", "tablecloth"}) {
    SCOPED_TRACE(name);
    const Pattern p = load_pattern(kGarments + name + ".pattern");
    const Pattern back = parse_pattern(write_pattern(p), "written.pattern");
    expect_same(p, back);
  }
}

// a seam sewing edges of different lengths is named, with both lengths, by the names the file gives its edges;
// no shipped garment has one
TEST(PatternFile, SeamsOfDifferentLengthsAreNamedWithTheirLengths) {
  const Pattern p = parse_pattern(
      "garment g\n"
      "panel a\n  start 0 0\n  edge bottom line 30 0\n  edge right line 30 56.6\n  edge top line 0 56.6\n"
      "  edge left close\nend\n"
      "panel b\n  start 0 0\n  edge bottom line 30 0\n  edge right line 30 30.3\n  edge top line 0 30.3\n"
      "  edge left close\nend\n"
      "seam a.right b.left\nseam a.bottom b.bottom\n",
      "t.pattern");
  EXPECT_EQ(edge_label(p, 0, 1), "a.right");
  EXPECT_NEAR(edge_length_cm(p.panels[0], 1), 56.6, 1e-9);
  const auto warnings = seam_length_warnings(p);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0], "seam a.right (56.6 cm) <-> b.left (30.3 cm): the edges differ by 46 % of the longer");
  for (const char* name : {"shirt", "shirt_sleeves", "skirt", "dress", "dress_sleeves", "trousers",
                           "durupinar_trousers", "durupinar_skirt", "tablecloth"})
    EXPECT_TRUE(seam_length_warnings(load_pattern(kGarments + name + ".pattern")).empty()) << name;
}

TEST(PatternFile, ErrorsNameTheLine) {
  struct Case {
    const char* text;
    int line;
    const char* says;
  };
  const Case cases[] = {
      {"panel a\n  start 0 0\n  edge e line 1 0 line 1 1\nend\n", 4, "not closed"},
      {"panel a\n  start 0 0\n  edge e line 4 4\n  edge f line 4 0\n  edge g line 0 4 close\nend\n", 5,
       "intersects itself"},
      {"panel a\n  rect 4 4\nend\nseam a.left b.right\n", 4, "panel 'b'"},
      {"panel a\n  rect 4 4\nend\nseam a.left a.armhole\n", 4, "no such edge"},
      {"panel a\n  rect 4 -4\nend\n", 2, "must be > 0"},
      {"panel a\n  place wrap -3\n  rect 4 4\nend\n", 2, "radius must be >= 0"},
      {"panel a\n  place anchor 0.5 nan 0.5\n  rect 4 4\nend\n", 2, "not a finite number"},
      {"panel a\n  place anchor 0.5 1.5 0.5\n  rect 4 4\nend\n", 2, "[0, 1]"},
      {"panel a\n  rect 4 4\nend\nseam a.left a.right\n\nseam a.right a.left\n", 6, "duplicated seam"},
      {"", 1, "empty pattern"},
      {"# only a comment\n\n", 2, "empty pattern"},
      {"panel a\n  rect 4 4\nend\n\x01\x02\x7f garbage", 4, "binary data"},
      {"panel a\n  rect 4 4\nend\n\xff\xfe", 4, "not UTF-8"},
      {"panel a\n  rect 4 4\nfinish\n", 3, "unknown keyword 'finish'"},
      {"panel a\n  rect 4 4\n", 1, "has no 'end'"},
      {"panel a\n  start 0 0\n  edge e line 1 0 spline 2 2\nend\n", 3, "unknown segment"},
      {"panel a\n  start 0 0\n  edge e line 1 0\n  edge e line 1 1 close\nend\n", 4, "two edges named 'e'"},
      {"panel a\n  start 0 0\n  edge e line 0 0\nend\n", 3, "zero-length segment"},
      {"panel a\n  rect 4 4\n  attach waist\nend\n", 3, "no edge 'waist'"},
      {"panel a\n  rect 4 4\nend\npanel a\n  rect 4 4\nend\n", 4, "defined twice"},
      {"panel a\n  rect 4 4\nend\nseam a.left.x a.right\n", 4, "expected PANEL.EDGE"},
      {"panel a\n  rect 4 4\nend\nseam a.left a.right sideways\n", 4, "reversed or aligned"},
      {"panel a\n  rect four 4\nend\n", 2, "'four' is not a number"},
      // outlines that touch themselves, run back along themselves or have no area: Boost.Geometry's
      // is_valid, at the line of the later edge at fault
      {"panel a\n  start 0 0\n  edge e line 20 0 line 20 20\n  edge f line 40 20 line 40 40 line 20 40\n"
       "  edge g line 20 20 line 0 20 close\nend\n",
       5, "intersects itself at (20, 20): edge 'g' meets edge 'e'"},
      {"panel a\n  start 0 0\n  edge e line 40 0\n  edge f line 40 40\n  edge g line 20 0\n  edge h line 0 40 "
       "close\nend\n",
       5, "intersects itself at (20, 0): edge 'g' meets edge 'e'"},
      {"panel a\n  start 0 0\n  edge e line 50 0\n  edge f line 40 0 line 40 50\n  edge g line 0 50 close\nend\n", 4,
       "runs back along itself at (50, 0): edge 'f' meets edge 'e'"},
      {"panel a\n  start 0 0\n  edge e line 10 0 line 10 10 line 10 5 line 0 5 close\nend\n", 3,
       "runs back along itself at (10, 10): edge 'e' meets itself"},
      {"panel a\n  start 0 0\n  edge e line 20 0 line 40 0\n  edge f close\nend\n", 4, "runs back along itself"},
      {"panel a\n  start 0 0\n  edge e line 2e6 0 line 0 10 close\nend\n", 3, "beyond +-1e6 cm"},
  };
  for (const auto& c : cases) {
    const std::string message = parse_error(c.text);
    EXPECT_NE(message.find("t.pattern:" + std::to_string(c.line) + ": "), std::string::npos)
        << c.text << "\n-> " << message;
    EXPECT_NE(message.find(c.says), std::string::npos) << c.text << "\n-> " << message;
  }
}

TEST(PatternFile, BadFilesNameFileAndLine) {
  const std::pair<const char*, int> files[] = {
      {"pattern_unclosed.pattern", 7},        {"pattern_self_intersecting.pattern", 6},
      {"pattern_missing_panel.pattern", 6},   {"pattern_missing_edge.pattern", 8},
      {"pattern_negative_size.pattern", 3},   {"pattern_nan.pattern", 2},
      {"pattern_duplicated_seam.pattern", 9}, {"pattern_empty.pattern", 1},
      {"pattern_binary.pattern", 2},          {"garmentcode_missing_panel.json", 17},
      {"garmentcode_broken_loop.json", 10},   {"garmentcode_not_json.json", 7},
      {"pattern_figure_eight.pattern", 6},    {"pattern_collinear_spike.pattern", 5},
      {"pattern_zero_area.pattern", 5},       {"garmentcode_figure_eight.json", 4},
  };
  for (const auto& [name, line] : files) {
    const std::string path = kBad + name;
    try {
      load_pattern(path);
      ADD_FAILURE() << name << " was accepted";
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()).rfind(path + ":" + std::to_string(line) + ": ", 0), 0u) << e.what();
    }
  }
  EXPECT_THROW(load_pattern(kBad + "no_such_file.pattern"), InputError);
}

TEST(PatternFile, SimpleOutlinesLoadEitherWayRound) {
  // counter-clockwise and clockwise, with straight runs of several points and a curve: all valid
  for (const char* outline :
       {"  start 0 0\n  edge a line 10 0 line 20 0\n  edge b line 20 10 quad 10 15 0 10 close\n",
        "  start 0 0\n  edge a line 0 10 quad 10 15 20 10\n  edge b line 20 0 line 10 0 close\n"}) {
    SCOPED_TRACE(outline);
    EXPECT_EQ(parse_error(std::string("panel a\n") + outline + "end\n"), "");
  }
  // every outline of the committed patterns and GarmentCode specifications passes the same test
  for (const char* name : {"shirt", "shirt_sleeves", "skirt", "dress", "dress_sleeves", "trousers",
                           "durupinar_trousers", "durupinar_skirt", "tablecloth"})
    for (const auto& panel : load_pattern(kGarments + name + ".pattern").panels)
      EXPECT_EQ(outline_fault(panel.outline).what, "") << name << " " << panel.name;
  const std::string specs = std::string(CLOTHBENCH_SOURCE_DIR) + "/scenes/data/garments/garmentcode/";
  for (const char* name : {"dress_pencil", "hoody_mean", "js_mean_all", "shirt_mean"})
    for (const auto& panel : load_pattern(specs + name + "_specification.json").panels)
      EXPECT_EQ(outline_fault(panel.outline).what, "") << name << " " << panel.name;
}

// Runs the clothbench binary (CLOTHBENCH_BIN, set by ctest) and returns its exit code and stderr.
std::pair<int, std::string> run_cli(const std::string& args) {
  const char* bin = std::getenv("CLOTHBENCH_BIN");
  if (!bin) return {-1, ""};
  const std::string err = test::temp_path("garment_cli_stderr.txt");
  const int status = std::system(("\"" + std::string(bin) + "\" " + args + " >/dev/null 2>\"" + err + "\"").c_str());
  std::ifstream in(err);
  std::stringstream s;
  s << in.rdbuf();
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, s.str()};
}

TEST(PatternFile, CliExitsTwoNamingFileAndLine) {
  if (!std::getenv("CLOTHBENCH_BIN")) GTEST_SKIP() << "CLOTHBENCH_BIN not set (run through ctest)";
  for (const auto& [name, line] : {std::pair<const char*, int>{"pattern_unclosed.pattern", 7},
                                   {"pattern_binary.pattern", 2},
                                   {"pattern_figure_eight.pattern", 6},
                                   {"garmentcode_missing_panel.json", 17}}) {
    const auto [code, err] = run_cli("garment \"" + kBad + name + "\"");
    EXPECT_EQ(code, 2) << name;
    EXPECT_NE(err.find(kBad + name + ":" + std::to_string(line) + ": "), std::string::npos) << err;
  }
  const auto [code, err] = run_cli("garment \"" + kGarments + "skirt.pattern\" --vertices 336 --json");
  EXPECT_EQ(code, 0) << err;
}

}  // namespace
}  // namespace clothbench
