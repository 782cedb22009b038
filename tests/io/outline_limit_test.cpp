#include <gtest/gtest.h>

#include <iomanip>
#include <sstream>
#include <string>

#include "clothbench/io/errors.hpp"
#include "clothbench/io/pattern_file.hpp"

namespace clothbench {
namespace {

// Line of the curved edge and of the straight edge after it in long_curve_pattern's text.
constexpr int kCurveLine = 4;
constexpr int kSideLine = 5;

// A one-panel pattern whose first edge is a quadratic curve that flattens into `segments` pieces:
// its control polygon is 100 cm long (two 3-4-5 legs of 50 cm) and curve_step is chosen so that
// 100 / curve_step = segments - 0.5, which rounds up to `segments`. The outline then holds the
// start point, the curve's `segments` points and the side's end point: segments + 2 points.
std::string long_curve_pattern(int segments) {
  std::ostringstream text;
  text << std::setprecision(17) << "curve_step " << 100.0 / (segments - 0.5) << "\n"
       << "panel long\n"
       << "  start 0 0\n"
       << "  edge hem quad 30 -40 60 0\n"
       << "  edge side line 30 40\n"
       << "  edge back close\n"
       << "end\n";
  return text.str();
}

// The message of the InputError that parsing `text` throws, or "" when it parses.
std::string parse_error(const std::string& text) {
  try {
    parse_pattern(text, "long.pattern");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(OutlineLimit, OutlineOfExactlyTheLimitIsAccepted) {
  const Pattern p = parse_pattern(long_curve_pattern(kMaxOutlinePoints - 2), "long.pattern");
  ASSERT_EQ(p.panels.size(), 1u);
  EXPECT_EQ(p.panels[0].outline.size(), static_cast<std::size_t>(kMaxOutlinePoints));
  EXPECT_EQ(p.panels[0].edge_count(), 3);
}

TEST(OutlineLimit, OnePointOverTheLimitIsRejectedAtItsLine) {
  const std::string e = parse_error(long_curve_pattern(kMaxOutlinePoints - 1));
  EXPECT_EQ(e.rfind("long.pattern:" + std::to_string(kSideLine) + ": ", 0), 0u) << e;
  EXPECT_NE(e.find("panel 'long'"), std::string::npos) << e;
  EXPECT_NE(e.find("more than " + std::to_string(kMaxOutlinePoints) + " points"), std::string::npos) << e;
}

TEST(OutlineLimit, CurveOfExactlyTheLimitInPiecesPassesTheCurveCheck) {
  // the curve alone may flatten into the limit; the outline it leaves is then too long
  const std::string e = parse_error(long_curve_pattern(kMaxOutlinePoints));
  EXPECT_EQ(e.find("pieces"), std::string::npos) << e;
  EXPECT_NE(e.find("more than " + std::to_string(kMaxOutlinePoints) + " points"), std::string::npos) << e;
}

TEST(OutlineLimit, CurvePastTheLimitIsRejectedAtItsLine) {
  const std::string e = parse_error(long_curve_pattern(kMaxOutlinePoints + 1));
  EXPECT_EQ(e.rfind("long.pattern:" + std::to_string(kCurveLine) + ": ", 0), 0u) << e;
  EXPECT_NE(e.find("curve of panel 'long'"), std::string::npos) << e;
  EXPECT_NE(e.find("more than " + std::to_string(kMaxOutlinePoints) + " pieces"), std::string::npos) << e;
}

}  // namespace
}  // namespace clothbench
