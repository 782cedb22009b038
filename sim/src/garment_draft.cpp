// Garments drafted from a body's measurements (Durupinar section 2): a panel's corners from girths and lengths.
#include "clothbench/sim/garment_draft.hpp"

#include <algorithm>
#include <array>
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
// the waistband's ease [cm], whatever the size: sewing closes it round the waist, where it is bound to the body. With
// a size's ease it hangs centimetres off the body
constexpr double kWaistEaseCm = 2;
// the trousers' waistband's ease [cm]: four panels wrapped round the legs, not round the hip as the skirt's two, come
// to the waist from farther off (with 2 cm, the walking body's left the side seams 3.4 mm open at the waist)
constexpr double kTrousersWaistEaseCm = 4;
// how far below the body's crotch the trousers' crotch seam is cut [m]: the front and back crotch seams pass under
// the body between the legs (cut at the body's crotch, the strain limit held them too short to close round it: seams
// 5-14 mm open where the four panels meet; cut 4 cm below, 3-5 mm)
constexpr double kCrotchDrop = 0.08;
// how far below the knee's section the trousers end [m]
constexpr double kHemBelowKnee = 0.04;
// a sleeve's length under the arm, from the cuff to the armpit [cm]: a short sleeve over the upper arm
constexpr double kSleeveUnderCm = 10;
// the arm's axis is taken between the section the upper arm's girth is measured at and one this far below it [m]
constexpr double kArmSectionSpan = 0.12;
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

// a front and a back panel wrapped on a cylinder of `radius` [cm] round the axis through `axis` (x, z) [m], their
// lowest edge at `hem_h` [m], tilted by `roll_deg` (the back, turned by its yaw, the other way: roll turns a panel
// before yaw)
void place_front_and_back(const BodyFrame& body, const Eigen::Vector2d& axis, double hem_h, double radius,
                          double roll_deg, Panel& front, Panel& back) {
  const Box3 box = bounding_box(body.positions);
  const Vec3 size = box.size();
  Placement& f = front.placement;
  f.anchor = Vec3(Real((axis.x() - box.min.x()) / size.x()), Real((hem_h - box.min.y()) / size.y()),
                  Real((axis.y() - box.min.z()) / size.z()));
  f.offset_cm = Vec3(0, 0, Real(radius));
  f.wrap_radius_cm = Real(radius);
  f.roll_deg = Real(roll_deg);
  back.placement = f;
  back.placement.offset_cm.z() = -Real(radius);
  back.placement.yaw_deg = 180;
  back.placement.roll_deg = Real(0) - f.roll_deg;  // 0 - 0 is +0: an upright pattern file says roll 0
}

// a front and a back panel wrapped round a vertical axis through `centre` (x, z) [m], their lowest edge at
// `hem_h` [m]: on a cylinder that holds half the widest girth across each panel and clears the body's sections
// between `lo` and `hi` by kClearanceCm on every side (the side seams then start apart where the body is wider
// than deep, and sewing closes them)
void wrap_front_and_back(const BodyFrame& body, const Eigen::Vector2d& centre, double hem_h, double half_girth_cm,
                         double lo, double hi, Panel& front, Panel& back) {
  const double radius = std::max(half_girth_cm / M_PI, 100 * reach_from(body, centre, lo, hi) + kClearanceCm);
  place_front_and_back(body, centre, hem_h, radius, 0, front, back);
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

// the index of the panel's edge named `name` (its edge count when it has none)
int edge_named(const Panel& panel, const std::string& name) {
  return static_cast<int>(std::find(panel.edge_names.begin(), panel.edge_names.end(), name) - panel.edge_names.begin());
}

// every panel's waist bound to the body once dressed (Durupinar 3.2, as garments/skirt.pattern and trousers.pattern
// have it): a waistband held by friction alone slid down the hip for as long as the drape ran, so that the fit at
// the hip told how long that was rather than the size
void attach_waist(Pattern& p) {
  for (Panel& q : p.panels) q.attached_edges.push_back(edge_named(q, "waist"));
}

// sews edge `ea` of panel a to edge `eb` of panel b, one against the other (the drafts' panels mirror each other),
// where panel a has that edge
void sew(Pattern& p, int a, const std::string& ea, int b, const std::string& eb) {
  const Panel &pa = p.panels[static_cast<std::size_t>(a)], &pb = p.panels[static_cast<std::size_t>(b)];
  if (edge_named(pa, ea) < pa.edge_count()) p.seams.push_back({a, edge_named(pa, ea), b, edge_named(pb, eb), true});
}

Pattern sewn_front_and_back(const std::string& name, Panel front, Panel back) {
  Pattern p;
  p.name = name;
  p.panels = {std::move(front), std::move(back)};
  // the back is turned (yaw 180): its left edges lie beside the front's right ones
  sew(p, 0, "side_r", 1, "side_l"), sew(p, 0, "side_l", 1, "side_r");
  sew(p, 0, "shoulder_r", 1, "shoulder_l"), sew(p, 0, "shoulder_l", 1, "shoulder_r");
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
  Pattern p = sewn_front_and_back("skirt", std::move(front), std::move(back));
  attach_waist(p);
  return p;
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

// the panel mirrored across x = 0, its outline reversed so that it still turns counter-clockwise, its edges kept
Panel mirrored(const Panel& p, const std::string& name) {
  const int n = static_cast<int>(p.outline.size()), m = p.edge_count();
  Panel q;
  q.name = name;
  for (int i = 0; i < n; ++i) {
    const Vec2d& a = p.outline[static_cast<std::size_t>(i == 0 ? 0 : n - i)];
    q.outline.push_back({-a.x(), a.y()});
  }
  // edge j ran from point b_j to b_(j+1); reversed, the edges come last to first, edge j from point b_(j+1)
  for (int j = m - 1; j >= 0; --j) {
    const int next = j + 1 < m ? p.edge_begin[static_cast<std::size_t>(j + 1)] : n;
    q.edge_begin.push_back(next == n ? 0 : n - next);
    q.edge_names.push_back(p.edge_names[static_cast<std::size_t>(j)]);
  }
  return q;
}

// the two legs' sections at height h (the two largest loops nearest the middle: the hands may hang as low), left
// (x > 0) first
std::array<SectionLoop, 2> legs_at(const BodyFrame& body, double h) {
  auto loops = cross_section(body, h);
  const double big = loops.empty() ? 0 : loops.front().area();
  loops.erase(std::remove_if(loops.begin(), loops.end(), [&](const SectionLoop& l) { return l.area() < 0.2 * big; }),
              loops.end());
  std::sort(loops.begin(), loops.end(), [](const SectionLoop& a, const SectionLoop& b) {
    return std::abs(a.centroid().x()) < std::abs(b.centroid().x());
  });
  if (loops.size() < 2 || loops[0].centroid().x() * loops[1].centroid().x() >= 0)
    throw std::invalid_argument("draft: no two legs apart " + std::to_string(static_cast<int>(100 * h)) +
                                " cm above the soles");
  if (loops[0].centroid().x() < 0) std::swap(loops[0], loops[1]);
  return {loops[0], loops[1]};
}

// knee-length trousers: four panels, the front and back of each leg, sewn along the outside and inside of each leg
// and at the centre front and back (as garments/trousers.pattern). A panel spans half a leg below the crotch (the
// thigh girth plus the ease, halved) and a quarter of the hip above it (the hip girth plus the ease), the waist's
// quarter (plus kTrousersWaistEaseCm round) at the top, the crotch curving in from the centre seam at the hip to the
// inside leg at the crotch. The left front panel, counter-clockwise from the hem's inner corner [cm]; x = 0 is the
// leg's axis
Panel trousers_panel(const BodyMeasurements& m, double ease_cm, double hem_h) {
  const double leg_half = (100 * m["thigh girth"].value_m + ease_cm) / 4;  // a quarter of the leg round
  const double hip_quarter = (100 * m["hip girth"].value_m + ease_cm) / 4;
  const double waist_quarter = (100 * m["waist girth"].value_m + kTrousersWaistEaseCm) / 4;
  const double crotch_y = 100 * (m["crotch height"].height_m - kCrotchDrop - hem_h);
  const double hip_y = 100 * (m["hip girth"].height_m - hem_h);
  const double waist_y = 100 * (m["waist girth"].height_m - hem_h);
  const double centre_x = leg_half - hip_quarter;  // the centre front seam, inside the leg's axis
  Panel p;
  p.name = "front_l";
  p.outline.push_back({-leg_half, 0});
  edge(p, "hem", {{leg_half, 0}});
  edge(p, "outseam", {{leg_half, crotch_y}, {leg_half, hip_y}, {centre_x + waist_quarter, waist_y}});
  edge(p, "waist", {{centre_x, waist_y}});
  edge(p, "fly", {{centre_x, hip_y}});
  edge(p, "crotch", quad({centre_x, hip_y}, {centre_x, crotch_y}, {-leg_half, crotch_y}));
  edge(p, "inseam", {});  // back down to the hem's inner corner
  return p;
}

Pattern draft_trousers(const BodyFrame& body, const BodyMeasurements& m, double ease_cm) {
  const double knee_h = m["knee girth"].height_m, thigh_h = m["thigh girth"].height_m;
  const double hem_h = knee_h - kHemBelowKnee;
  const Panel front_l = trousers_panel(m, ease_cm, hem_h);
  Pattern p;
  p.name = "trousers";
  p.panels = {front_l, mirrored(front_l, "front_r"), mirrored(front_l, "back_l"), front_l};
  p.panels[3].name = "back_r";
  // each panel wrapped round its leg's axis (through the leg's section under the crotch), tilted as the leg is
  // between there and the knee, on a cylinder that holds a quarter of the leg round across half its width and
  // clears the thigh by kClearanceCm
  const auto thighs = legs_at(body, thigh_h), knees = legs_at(body, knee_h);
  const double leg_half = (100 * m["thigh girth"].value_m + ease_cm) / 4;
  for (int side = 0; side < 2; ++side) {  // 0: left (+x), 1: right
    const Eigen::Vector2d axis = thighs[static_cast<std::size_t>(side)].centroid();
    // the leg's half of the body from the thigh up to the waist, which the panel covers (the legs' and the pelvis's
    // sections: the hands' are smaller): the hip reaches beyond the thigh (clearing the thigh alone, a sixth of the
    // trousers started inside the hips)
    double reach = 0;
    for (double h = thigh_h; h <= m["waist girth"].height_m; h += 0.02) {
      const auto loops = cross_section(body, h);
      for (const auto& loop : loops)
        for (const auto& q : loop.points)
          if (loop.area() > 0.2 * loops.front().area() && (side == 0) == (q.x() > 0))
            reach = std::max(reach, (q - axis).norm());
    }
    const double radius = std::max(2 * leg_half / M_PI, 100 * reach + kClearanceCm);
    const double tilt =
        180 / M_PI * std::atan((knees[static_cast<std::size_t>(side)].centroid().x() - axis.x()) / (thigh_h - knee_h));
    place_front_and_back(body, axis, hem_h, radius, tilt, p.panels[side == 0 ? 0 : 1], p.panels[side == 0 ? 2 : 3]);
  }
  attach_waist(p);
  sew(p, 0, "outseam", 2, "outseam"), sew(p, 0, "inseam", 2, "inseam");  // the left leg
  sew(p, 1, "outseam", 3, "outseam"), sew(p, 1, "inseam", 3, "inseam");  // the right leg
  sew(p, 0, "crotch", 1, "crotch"), sew(p, 0, "fly", 1, "fly");          // the centre front
  sew(p, 2, "crotch", 3, "crotch"), sew(p, 2, "fly", 3, "fly");          // the centre back
  return p;
}

// the arm's section at height h on one side (side > 0: the left, +x): of the loops besides the torso's, the one
// farthest out on that side
SectionLoop arm_at(const BodyFrame& body, double h, int side) {
  const auto loops = cross_section(body, h);
  const SectionLoop* best = nullptr;
  for (std::size_t k = 1; k < loops.size(); ++k)
    if (loops[k].area() > 0.01 * loops[0].area() && side * loops[k].centroid().x() > 0 &&
        (!best || side * loops[k].centroid().x() > side * best->centroid().x()))
      best = &loops[k];
  if (!best)
    throw std::invalid_argument("draft: no arm apart from the torso " + std::to_string(static_cast<int>(100 * h)) +
                                " cm above the soles");
  return *best;
}

// the cap's height whose edge, a quadratic curve from the underarm corner across half the sleeve's width to the cap's
// top, is `length` long [cm] (its control at the top's height, 0.45 of the way across, as garments/shirt_sleeves has
// it); a cap narrower than the armhole is long, one wider is given a spacing's rise
double cap_height(double half_width, double length) {
  const auto curve_length = [&](double height) {
    const std::vector<Vec2d> q = quad({0, 0}, {0.45 * half_width, height}, {half_width, height});
    double l = 0;
    Vec2d at(0, 0);
    for (const Vec2d& p : q) l += (p - at).norm(), at = p;
    return l;
  };
  double lo = 1, hi = 3 * length;
  if (curve_length(lo) >= length) return lo;
  for (int k = 0; k < 60; ++k) (curve_length(0.5 * (lo + hi)) < length ? lo : hi) = 0.5 * (lo + hi);
  return 0.5 * (lo + hi);
}

// short sleeves for a shirt (Durupinar section 2's sleeve from the upper arm's girth): one panel per arm, wrapped
// into a tube round the upper arm (its girth plus the ease) and sewn to itself under the arm, its cap's two edges
// sewn to the front's and the back's armholes, tilted as the arm is between two sections below the armpit (as
// garments/shirt_sleeves.pattern is laid out: u round the arm, the two under edges meeting under it, v up the arm)
void add_sleeves(Pattern& p, const BodyFrame& body, const BodyMeasurements& m, double ease_cm) {
  const double r = (100 * m["upper arm girth"].value_m + ease_cm) / (2 * M_PI), turn = 2 * M_PI * r;
  const double u0 = -2.5 * M_PI * r;  // the under edges face the armpit once the tube is tilted
  const double armhole = edge_length_cm(p.panels[0], edge_named(p.panels[0], "armhole_r"));
  const double cap = cap_height(turn / 2, armhole), top = kSleeveUnderCm + cap;
  Panel left;
  left.name = "sleeve_l";
  left.outline.push_back({u0, 0});
  edge(left, "cuff", {{u0 + turn, 0}});
  edge(left, "under_a", {{u0 + turn, kSleeveUnderCm}});
  edge(left, "cap_back", quad({u0 + turn, kSleeveUnderCm}, {u0 + turn - 0.45 * turn / 2, top}, {u0 + turn / 2, top}));
  edge(left, "cap_front", quad({u0 + turn / 2, top}, {u0 + 0.45 * turn / 2, top}, {u0, kSleeveUnderCm}));
  edge(left, "under_b", {});
  Panel right = mirrored(left, "sleeve_r");
  const Box3 box = bounding_box(body.positions);
  const double h1 = m["upper arm girth"].height_m, h2 = h1 - kArmSectionSpan;
  for (Panel* sleeve : {&left, &right}) {
    const int side = sleeve == &left ? 1 : -1;
    const Eigen::Vector2d a = arm_at(body, h1, side).centroid(), b = arm_at(body, h2, side).centroid();
    // the arm's direction down from the armpit, in the body's front plane; the cuff's centre kSleeveUnderCm down it
    const Vec3 down = Vec3(Real(b.x() - a.x()), Real(h2 - h1), 0).normalized();
    const Vec3 cuff = Vec3(Real(a.x()), Real(h1), Real(a.y())) + Real(kSleeveUnderCm / 100) * down;
    Placement& pl = sleeve->placement;
    pl.anchor = (cuff - box.min).cwiseQuotient(box.size());
    pl.offset_cm = Vec3(0, 0, Real(r));  // the tube's axis lies r behind the panel's origin
    pl.wrap_radius_cm = Real(r);
    pl.roll_deg = Real(180 / M_PI * std::atan2(down.x(), -down.y()));  // +v turned up the arm
  }
  p.panels.push_back(std::move(left));
  p.panels.push_back(std::move(right));
  sew(p, 2, "under_a", 2, "under_b"), sew(p, 3, "under_a", 3, "under_b");
  sew(p, 2, "cap_front", 0, "armhole_r"), sew(p, 2, "cap_back", 1, "armhole_l");
  sew(p, 3, "cap_front", 0, "armhole_l"), sew(p, 3, "cap_back", 1, "armhole_r");
  p.name = "shirt_sleeves";
}

}  // namespace

std::vector<std::string> draft_sizes() { return {"S", "M", "L", "XL"}; }

double size_ease_cm(const std::string& size) {
  const std::vector<std::string> sizes = draft_sizes();
  for (std::size_t k = 0; k < sizes.size(); ++k)
    if (size == sizes[k]) return 4.0 * double(k + 1);
  throw std::invalid_argument("size: unknown size '" + size + "' (S, M, L, XL)");
}

std::vector<std::string> draft_types() { return {"skirt", "shirt", "shirt_sleeves", "dress", "trousers"}; }

Pattern draft_garment(const std::string& type, const BodyFrame& body, const BodyMeasurements& m, double ease_cm) {
  if (!(ease_cm >= 0 && ease_cm <= 100))
    throw std::invalid_argument("ease: " + std::to_string(ease_cm) + " cm is outside [0, 100]");
  const std::vector<std::string> types = draft_types();
  if (std::find(types.begin(), types.end(), type) == types.end()) {
    std::string known;
    for (const std::string& t : types) known += (known.empty() ? "" : ", ") + t;
    throw std::invalid_argument("draft: unknown garment type '" + type + "' (" + known + ")");
  }
  Pattern p = type == "skirt"      ? draft_skirt(body, m, ease_cm)
              : type == "trousers" ? draft_trousers(body, m, ease_cm)
                                   : draft_bodice(type == "dress" ? type : "shirt", body, m, ease_cm);
  if (type == "shirt_sleeves") add_sleeves(p, body, m, ease_cm);
  validate_pattern(p);
  return p;
}

}  // namespace clothbench
