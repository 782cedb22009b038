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

// one edge of a panel from the outline's current end through `points`
void edge(Panel& p, const std::string& name, const std::vector<Vec2d>& points) {
  p.edge_begin.push_back(static_cast<int>(p.outline.size()) - 1);
  p.edge_names.push_back(name);
  for (const Vec2d& q : points) p.outline.push_back(q);
}

// a skirt panel: hem, right side, waist, left side, counter-clockwise from the hem's left corner [cm]
Panel skirt_panel(const std::string& name, double hem_w, double hip_w, double waist_w, double hip_y, double length) {
  Panel p;
  p.name = name;
  p.outline.push_back({-hem_w / 2, 0});
  edge(p, "hem", {{hem_w / 2, 0}});
  edge(p, "side_r", {{hip_w / 2, hip_y}, {waist_w / 2, length}});
  edge(p, "waist", {{-waist_w / 2, length}});
  edge(p, "side_l", {{-hip_w / 2, hip_y}});  // and back to the start: the outline closes
  return p;
}

Pattern draft_skirt(const BodyFrame& body, const BodyMeasurements& m, double ease_cm) {
  const Box3 box = bounding_box(body.positions);
  const double hem_h = m["knee girth"].height_m + kHemAboveKnee;
  const double length = 100 * (m["waist girth"].height_m - hem_h), hip_y = 100 * (m["hip girth"].height_m - hem_h);
  const double hip_w = (100 * m["hip girth"].value_m + ease_cm) / 2;
  const double waist_w = (100 * m["waist girth"].value_m + kWaistEaseCm) / 2;
  // the panels wrap round a vertical axis through the hip section's centre, on a cylinder that holds half the hip's
  // width across each panel and clears the section by kClearanceCm on every side (the side seams then start apart
  // where the body is wider than deep, and sewing closes them)
  const auto hips = cross_section(body, m["hip girth"].height_m);
  const Eigen::Vector2d centre = hips.front().centroid();
  double reach_cm = 0;
  for (const auto& q : hips.front().points) reach_cm = std::max(reach_cm, 100 * (q - centre).norm());
  const double radius = std::max(hip_w / M_PI, reach_cm + kClearanceCm);
  const Vec3 size = box.size();
  Placement front;
  front.anchor = Vec3(Real((centre.x() - box.min.x()) / size.x()), Real((hem_h - box.min.y()) / size.y()),
                      Real((centre.y() - box.min.z()) / size.z()));
  front.offset_cm = Vec3(0, 0, Real(radius));
  front.wrap_radius_cm = Real(radius);
  Placement back = front;
  back.offset_cm.z() = -Real(radius);
  back.yaw_deg = 180;
  Pattern p;
  p.name = "skirt";
  p.panels = {skirt_panel("front", kHemFlare * hip_w, hip_w, waist_w, hip_y, length),
              skirt_panel("back", kHemFlare * hip_w, hip_w, waist_w, hip_y, length)};
  p.panels[0].placement = front;
  p.panels[1].placement = back;
  p.seams = {{0, 1, 1, 3, true}, {0, 3, 1, 1, true}};  // front.side_r to back.side_l, front.side_l to back.side_r
  return p;
}

}  // namespace

std::vector<std::string> draft_sizes() { return {"S", "M", "L", "XL"}; }

double size_ease_cm(const std::string& size) {
  const std::vector<std::string> sizes = draft_sizes();
  for (std::size_t k = 0; k < sizes.size(); ++k)
    if (size == sizes[k]) return 4.0 * double(k + 1);
  throw std::invalid_argument("size: unknown size '" + size + "' (S, M, L, XL)");
}

std::vector<std::string> draft_types() { return {"skirt"}; }

Pattern draft_garment(const std::string& type, const BodyFrame& body, const BodyMeasurements& m, double ease_cm) {
  if (!(ease_cm >= 0 && ease_cm <= 100))
    throw std::invalid_argument("ease: " + std::to_string(ease_cm) + " cm is outside [0, 100]");
  if (type != "skirt") throw std::invalid_argument("draft: unknown garment type '" + type + "' (skirt)");
  Pattern p = draft_skirt(body, m, ease_cm);
  validate_pattern(p);
  return p;
}

}  // namespace clothbench
