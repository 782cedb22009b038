// Garments drafted from a body's measurements (Durupinar section 2): a panel's corners from girths and lengths.
#include "clothbench/sim/garment_draft.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace clothbench {

namespace {

// the hem's width over the hip's: a little A-line, room for a stride (a straighter small size on the walking body is
// stretched over the knees past the strain limit)
constexpr double kHemFlare = 1.2;
// how far above the knee's section the skirt ends [m]
constexpr double kHemAboveKnee = 0.06;
// how far the wrapped panels start outside the hip section on each side [cm]
constexpr double kClearanceCm = 3;
// the waistband's ease [cm], whatever the size: sewing closes it round the waist, where it holds the skirt up. With
// a size's ease it hangs centimetres off the body, and attached there it held the side seam's springs stretched past
// the strain limit
constexpr double kWaistEaseCm = 2;
// how far below the armpit a bodice's side seam ends [m]
constexpr double kBelowArmpit = 0.03;
// how far above the shoulder's top a bodice's shoulder seam is cut, as a fraction of the chest's depth at the
// armpits: the panel's way from the chest over to the shoulder's top
constexpr double kOverShoulder = 0.35;
// the neckline: its corner this much wider than the neck's radius [cm], rising towards the neck by this fraction of
// the shoulder seam's length, dipping at the middle this many neck radii at the front and at the back
constexpr double kNeckEaseCm = 2.5;
constexpr double kNeckRise = 0.5;
constexpr double kFrontNeckDrop = 1.7;
constexpr double kBackNeckDrop = 0.55;

// one edge of a panel from the outline's current end through `points`
void edge(Panel& p, const std::string& name, const std::vector<Vec2d>& points) {
  p.edge_begin.push_back(static_cast<int>(p.outline.size()) - 1);
  p.edge_names.push_back(name);
  for (const Vec2d& q : points) p.outline.push_back(q);
}

// points of a quadratic Bezier curve from a (not included) through control c to b, one about every 1.5 cm
std::vector<Vec2d> quad(const Vec2d& a, const Vec2d& c, const Vec2d& b) {
  const int n = std::max(2, static_cast<int>(std::ceil(((c - a).norm() + (b - c).norm()) / 1.5)));
  std::vector<Vec2d> out;
  for (int k = 1; k <= n; ++k) {
    const double t = double(k) / n;
    out.push_back((1 - t) * (1 - t) * a + 2 * (1 - t) * t * c + t * t * b);
  }
  return out;
}

// a panel symmetric about x = 0, counter-clockwise from the hem's left corner: the hem, then the right side up
// through `side` (x > 0, y ascending), then `top`: the edges above the side, each as (name, points), from the
// side's last point to the mirror of the hem's left corner's side; the left half mirrors the right [cm]
Panel symmetric_panel(const std::string& name, const std::vector<Vec2d>& side,
                      const std::vector<std::pair<std::string, std::vector<Vec2d>>>& top) {
  Panel p;
  p.name = name;
  p.outline.push_back({-side.front().x(), 0});
  edge(p, "hem", {{side.front().x(), 0}});
  edge(p, "side_r", {side.begin() + 1, side.end()});
  for (const auto& [edge_name, points] : top) edge(p, edge_name, points);
  std::vector<Vec2d> left;  // down the left side to the hem's corner, which closes the outline
  for (auto q = side.rbegin() + 1; q + 1 != side.rend(); ++q) left.push_back({-q->x(), q->y()});
  edge(p, "side_l", left);
  return p;
}

// the round of the body a wrapped panel must clear: the largest distance from the axis (x, z) [m] of any section
// between the heights lo and hi
double reach_from(const BodyFrame& body, const Eigen::Vector2d& axis, double lo, double hi) {
  double r = 0;
  for (double h = lo; h <= hi; h += 0.02) {
    const auto loops = cross_section(body, h);
    if (loops.empty()) continue;
    for (const auto& q : loops.front().points) r = std::max(r, (q - axis).norm());
  }
  return r;
}

// a front and a back panel wrapped round a vertical axis through `centre` (x, z) [m], their lowest edge at
// `hem_h` [m]: on a cylinder that holds half the widest girth across each panel and clears the body's sections
// between `lo` and `hi` by kClearanceCm on every side (the side seams then start apart where the body is wider
// than deep, and sewing closes them)
void wrap_front_and_back(const BodyFrame& body, const Eigen::Vector2d& centre, double hem_h, double half_girth_cm,
                         double lo, double hi, Panel& front, Panel& back) {
  const Box3 box = bounding_box(body.positions);
  const double radius = std::max(half_girth_cm / M_PI, 100 * reach_from(body, centre, lo, hi) + kClearanceCm);
  const Vec3 size = box.size();
  Placement& f = front.placement;
  f.anchor = Vec3(Real((centre.x() - box.min.x()) / size.x()), Real((hem_h - box.min.y()) / size.y()),
                  Real((centre.y() - box.min.z()) / size.z()));
  f.offset_cm = Vec3(0, 0, Real(radius));
  f.wrap_radius_cm = Real(radius);
  back.placement = f;
  back.placement.offset_cm.z() = -Real(radius);
  back.placement.yaw_deg = 180;
}

// the edges above the side seam of a front or back bodice, from the side's top (chest_half, armpit_y): the armhole
// curving in to the shoulder's end, the shoulder seam up to the neck's corner, the neckline dipping `neck_drop` at
// the middle, and back down the other shoulder and armhole [cm]
std::vector<std::pair<std::string, std::vector<Vec2d>>> bodice_top(double chest_half, double armpit_y,
                                                                   double shoulder_x, double shoulder_y, double neck_x,
                                                                   double neck_y, double neck_drop) {
  const Vec2d side_top(chest_half, armpit_y), shoulder(shoulder_x, shoulder_y), neck(neck_x, neck_y);
  // the armhole's control point: a little outside the shoulder's end, a little above the armpit
  const Vec2d bend(shoulder_x + 0.18 * (chest_half - shoulder_x), armpit_y + 0.08 * (shoulder_y - armpit_y));
  const auto mirror = [](Vec2d q) { return Vec2d(-q.x(), q.y()); };
  std::vector<Vec2d> armhole_l = quad(mirror(shoulder), mirror(bend), mirror(side_top));
  return {{"armhole_r", quad(side_top, bend, shoulder)},
          {"shoulder_r", {neck}},
          {"neck", quad(neck, {0, neck_y - 2 * neck_drop}, mirror(neck))},
          {"shoulder_l", {mirror(shoulder)}},
          {"armhole_l", armhole_l}};
}

Pattern sewn_front_and_back(const std::string& name, Panel front, Panel back) {
  Pattern p;
  p.name = name;
  p.panels = {std::move(front), std::move(back)};
  // the back is turned (yaw 180): its left edges lie beside the front's right ones
  const auto edge_of = [&](const std::string& e) {
    const auto& names = p.panels[0].edge_names;
    return static_cast<int>(std::find(names.begin(), names.end(), e) - names.begin());
  };
  for (const auto& [a, b] : std::vector<std::pair<std::string, std::string>>{
           {"side_r", "side_l"}, {"side_l", "side_r"}, {"shoulder_r", "shoulder_l"}, {"shoulder_l", "shoulder_r"}})
    if (edge_of(a) < p.panels[0].edge_count()) p.seams.push_back({0, edge_of(a), 1, edge_of(b), true});
  return p;
}

// a skirt panel: hem, right side through the hip, waist, left side [cm]
Panel skirt_panel(const std::string& name, double hem_w, double hip_w, double waist_w, double hip_y, double length) {
  return symmetric_panel(name, {{hem_w / 2, 0}, {hip_w / 2, hip_y}, {waist_w / 2, length}},
                         {{"waist", {{-waist_w / 2, length}}}});
}

Pattern draft_skirt(const BodyFrame& body, const BodyMeasurements& m, double ease_cm) {
  const double hem_h = m["knee girth"].height_m + kHemAboveKnee;
  const double length = 100 * (m["waist girth"].height_m - hem_h), hip_y = 100 * (m["hip girth"].height_m - hem_h);
  const double hip_w = (100 * m["hip girth"].value_m + ease_cm) / 2;
  const double waist_w = (100 * m["waist girth"].value_m + kWaistEaseCm) / 2;
  const double hip_h = m["hip girth"].height_m;
  const Eigen::Vector2d centre = cross_section(body, hip_h).front().centroid();
  Panel front = skirt_panel("front", kHemFlare * hip_w, hip_w, waist_w, hip_y, length);
  Panel back = skirt_panel("back", kHemFlare * hip_w, hip_w, waist_w, hip_y, length);
  wrap_front_and_back(body, centre, hem_h, hip_w, hip_h, hip_h, front, back);
  return sewn_front_and_back("skirt", std::move(front), std::move(back));
}

// a shirt (hem between the waist and the hip) or a dress (hem above the knee, flared): a front and a back panel
// sewn at the sides and shoulders, the chest girth at the armpits plus the ease round the top, the hip girth plus
// the ease below
Pattern draft_bodice(const std::string& type, const BodyFrame& body, const BodyMeasurements& m, double ease_cm) {
  const bool dress = type == "dress";
  const double hip_h = m["hip girth"].height_m, armpit_h = m["armpit height"].height_m;
  const double hem_h = dress ? m["knee girth"].height_m + kHemAboveKnee : (m["waist girth"].height_m + hip_h) / 2;
  const double chest_half = (100 * m["chest girth"].value_m + ease_cm) / 4;
  const double hip_half = std::max((100 * m["hip girth"].value_m + ease_cm) / 4, dress ? 0 : chest_half);
  const double armpit_y = 100 * (armpit_h - kBelowArmpit - hem_h);
  // the shoulder seam ends at the arm's root, a quarter of the width across the shoulders and upper arms from the
  // middle, and lies kOverShoulder of the chest's depth above the shoulder's top, so that front and back close over
  // the shoulder before gravity lays them on it
  const auto chest = cross_section(body, armpit_h);
  const double depth_cm = 100 * (chest.front().reach(1) - chest.front().reach(-1));
  const double shoulder_x = 100 * m["shoulder width"].value_m / 4;
  const double shoulder_y = 100 * (m["shoulder height"].height_m - hem_h) + kOverShoulder * depth_cm;
  const double neck_r = 100 * m["neck girth"].value_m / (2 * M_PI);
  const double neck_x = neck_r + kNeckEaseCm, neck_y = shoulder_y + kNeckRise * (shoulder_x - neck_x);
  std::vector<Vec2d> side{{dress ? kHemFlare * hip_half : hip_half, 0}};
  if (dress) side.push_back({hip_half, 100 * (hip_h - hem_h)});
  side.push_back({chest_half, armpit_y});
  Panel front = symmetric_panel(
      "front", side, bodice_top(chest_half, armpit_y, shoulder_x, shoulder_y, neck_x, neck_y, kFrontNeckDrop * neck_r));
  Panel back = symmetric_panel(
      "back", side, bodice_top(chest_half, armpit_y, shoulder_x, shoulder_y, neck_x, neck_y, kBackNeckDrop * neck_r));
  const Eigen::Vector2d centre = chest.front().centroid();
  wrap_front_and_back(body, centre, hem_h, 2 * std::max(chest_half, hip_half), dress ? hip_h : hem_h, armpit_h, front,
                      back);
  return sewn_front_and_back(type, std::move(front), std::move(back));
}

}  // namespace

std::vector<std::string> draft_sizes() { return {"S", "M", "L", "XL"}; }

double size_ease_cm(const std::string& size) {
  const std::vector<std::string> sizes = draft_sizes();
  for (std::size_t k = 0; k < sizes.size(); ++k)
    if (size == sizes[k]) return 4.0 * double(k + 1);
  throw std::invalid_argument("size: unknown size '" + size + "' (S, M, L, XL)");
}

std::vector<std::string> draft_types() { return {"skirt", "shirt", "dress"}; }

Pattern draft_garment(const std::string& type, const BodyFrame& body, const BodyMeasurements& m, double ease_cm) {
  if (!(ease_cm >= 0 && ease_cm <= 100))
    throw std::invalid_argument("ease: " + std::to_string(ease_cm) + " cm is outside [0, 100]");
  const std::vector<std::string> types = draft_types();
  if (std::find(types.begin(), types.end(), type) == types.end()) {
    std::string known;
    for (const std::string& t : types) known += (known.empty() ? "" : ", ") + t;
    throw std::invalid_argument("draft: unknown garment type '" + type + "' (" + known + ")");
  }
  Pattern p = type == "skirt" ? draft_skirt(body, m, ease_cm) : draft_bodice(type, body, m, ease_cm);
  validate_pattern(p);
  return p;
}

}  // namespace clothbench
