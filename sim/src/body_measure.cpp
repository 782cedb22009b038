// A body's girths and lengths from its closed mesh: horizontal cross-sections, landmark heights found by searching
// them (the narrowest, the widest, where the legs part and where the arms join the torso), a girth the perimeter of
// a section's convex hull (a tape measure spans the hollows).
#include "clothbench/sim/body_measure.hpp"

#include <algorithm>
#include <array>
#include <boost/geometry/algorithms/convex_hull.hpp>
#include <boost/geometry/algorithms/perimeter.hpp>
#include <boost/geometry/geometries/multi_point.hpp>
#include <boost/geometry/geometries/point_xy.hpp>
#include <boost/geometry/geometries/polygon.hpp>
#include <boost/geometry/strategies/strategies.hpp>
#include <cmath>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <unordered_map>

namespace clothbench {

namespace {

namespace bg = boost::geometry;
using HullPoint = bg::model::d2::point_xy<double>;

constexpr double kStep = 0.002;  // the searches' spacing of sections [m]

std::uint64_t edge_key(int a, int b) {
  const auto lo = static_cast<std::uint64_t>(std::min(a, b)), hi = static_cast<std::uint64_t>(std::max(a, b));
  return lo << 32 | hi;
}

// the segments where the plane cuts the triangles, each between the points on two edges
struct Cut {
  std::vector<std::array<std::uint64_t, 2>> segments;
  std::unordered_map<std::uint64_t, Eigen::Vector2d> points;                // per cut edge: where the plane cuts it
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> segments_at;  // per cut edge: its segments
};

Cut cut_triangles(const BodyFrame& body, double h) {
  Cut cut;
  const auto y = [&](int i) { return double(body.positions(1, i)); };
  const auto point = [&](int a, int b) {
    if (y(a) > y(b)) std::swap(a, b);
    const double t = (h - y(a)) / (y(b) - y(a));
    const Vec3 p = body.positions.col(a) + Real(t) * (body.positions.col(b) - body.positions.col(a));
    return Eigen::Vector2d(p.x(), p.z());
  };
  for (Eigen::Index t = 0; t < body.triangles.cols(); ++t) {
    std::array<std::uint64_t, 2> ends{};
    int found = 0;
    for (int k = 0; k < 3; ++k) {
      const int a = body.triangles(k, t), b = body.triangles((k + 1) % 3, t);
      if ((y(a) > h) == (y(b) > h)) continue;
      const std::uint64_t key = edge_key(a, b);
      if (!cut.points.count(key)) cut.points.emplace(key, point(a, b));
      if (found < 2) ends[static_cast<std::size_t>(found)] = key;
      ++found;
    }
    if (found != 2) continue;
    for (std::uint64_t key : ends) cut.segments_at[key].push_back(cut.segments.size());
    cut.segments.push_back(ends);
  }
  return cut;
}

// the segments chained into closed loops through the edges they share (an open chain, on a mesh that is not closed
// there, is dropped)
std::vector<SectionLoop> chain(const Cut& cut) {
  std::vector<SectionLoop> loops;
  std::vector<char> used(cut.segments.size(), 0);
  for (std::size_t first = 0; first < cut.segments.size(); ++first) {
    if (used[first]) continue;
    SectionLoop loop;
    std::size_t s = first;
    std::uint64_t at = cut.segments[first][1];
    bool closed = false;
    used[first] = 1;
    while (true) {
      loop.points.push_back(cut.points.at(at));
      const auto& next = cut.segments_at.at(at);
      if (next.size() != 2) break;
      s = next[0] == s ? next[1] : next[0];
      if (s == first) {
        closed = true;
        break;
      }
      if (used[s]) break;
      used[s] = 1;
      at = cut.segments[s][0] == at ? cut.segments[s][1] : cut.segments[s][0];
    }
    if (closed && loop.points.size() >= 3) loops.push_back(std::move(loop));
  }
  return loops;
}

// a section's largest loop (the torso above the crotch, a leg below it), or nullptr where the plane misses the body
const SectionLoop* largest(const std::vector<SectionLoop>& loops) { return loops.empty() ? nullptr : &loops.front(); }

// the height in [lo, hi] where `value` of the largest loop is least (`least`) or greatest
double search(const BodyFrame& body, double lo, double hi, bool least,
              const std::function<double(const SectionLoop&)>& value) {
  double best_h = -1, best = least ? 1e300 : -1e300;
  for (double h = lo; h <= hi; h += kStep) {
    const auto loops = cross_section(body, h);
    const SectionLoop* l = largest(loops);
    if (!l) continue;
    const double v = value(*l);
    if (least ? v < best : v > best) best = v, best_h = h;
  }
  return best_h;
}

// a search's height, or the error naming the landmark whose window held no section of the body
double found(const char* landmark, double h) {
  if (h < 0)
    throw std::invalid_argument(std::string("measure: no section of the body where the ") + landmark +
                                " should be (is it standing upright, soles at y = 0?)");
  return h;
}

double girth_at(const BodyFrame& body, double h) {
  const auto loops = cross_section(body, h);
  return loops.empty() ? 0 : loops.front().girth();
}

// "37 cm" for a height [m]
std::string cm(double m) { return std::to_string(static_cast<int>(std::lround(100 * m))) + " cm"; }

// where the legs join: going up from lo, past sections with two legs (two loops of more than a fifth of the
// largest's area: hands are less), the first in which one loop carries the body across the middle (the |x| of its
// centroid under 3 cm)
double crotch_height(const BodyFrame& body, double lo, double hi) {
  bool legs = false;
  for (double h = lo; h <= hi; h += kStep) {
    const auto loops = cross_section(body, h);
    if (loops.empty()) continue;
    const double big = loops.front().area();
    const auto significant =
        std::count_if(loops.begin(), loops.end(), [&](const SectionLoop& l) { return l.area() > 0.2 * big; });
    if (significant >= 2) legs = true;
    if (legs && significant == 1 && std::abs(loops.front().centroid().x()) < 0.03) return h;
  }
  throw std::invalid_argument("measure: no legs that part and join between " + cm(lo) + " and " + cm(hi) +
                              " above the soles (no crotch): the body must stand with its legs apart");
}

// where the arms join the torso: going up from lo, the last section before the largest loop widens by more than
// 4 cm in one step
double armpit_height(const BodyFrame& body, double lo, double hi) {
  double last_width = -1;
  for (double h = lo; h <= hi; h += kStep) {
    const auto loops = cross_section(body, h);
    if (loops.empty()) continue;
    const double w = loops.front().width();
    if (last_width > 0 && w - last_width > 0.04) return h - kStep;
    last_width = w;
  }
  throw std::invalid_argument("measure: the arms do not join the torso between " + cm(lo) + " and " + cm(hi) +
                              " above the soles (no armpit): the arms must hang away from the torso");
}

// the top of the shoulder where a shoulder seam ends (a quarter of the shoulder width from the middle, at the arm's
// root): going up from lo, the first section whose largest loop (the torso and its arms) is narrower than half the
// shoulder width
double shoulder_top(const BodyFrame& body, double lo, double hi, double width) {
  for (double h = lo; h <= hi; h += kStep) {
    const auto loops = cross_section(body, h);
    if (!loops.empty() && loops.front().width() < width / 2) return h;
  }
  throw std::invalid_argument("measure: no shoulders between " + cm(lo) + " and " + cm(hi) + " above the soles");
}

// the upper arm's girth: the second largest loop just below the armpit (the torso is the largest)
double upper_arm_girth(const BodyFrame& body, double h) {
  const auto loops = cross_section(body, h);
  if (loops.size() < 2 || loops[1].area() < 0.05 * loops[0].area())
    throw std::invalid_argument("measure: no arm apart from the torso " + cm(h) + " above the soles");
  return loops[1].girth();
}

}  // namespace

double SectionLoop::area() const {
  double a = 0;
  for (std::size_t i = 0, n = points.size(); i < n; ++i) {
    const auto& p = points[i];
    const auto& q = points[(i + 1) % n];
    a += p.x() * q.y() - q.x() * p.y();
  }
  return std::abs(a) / 2;
}

double SectionLoop::girth() const {
  bg::model::multi_point<HullPoint> all;
  for (const auto& p : points) all.push_back(HullPoint(p.x(), p.y()));
  bg::model::polygon<HullPoint> hull;
  bg::convex_hull(all, hull);
  return bg::perimeter(hull);
}

Eigen::Vector2d SectionLoop::centroid() const {
  Eigen::Vector2d c = Eigen::Vector2d::Zero();
  for (const auto& p : points) c += p;
  return points.empty() ? c : Eigen::Vector2d(c / double(points.size()));
}

double SectionLoop::reach(int side) const {
  double z = side > 0 ? -1e300 : 1e300;
  for (const auto& p : points) z = side > 0 ? std::max(z, p.y()) : std::min(z, p.y());
  return z;
}

double SectionLoop::width() const {
  double lo = 1e300, hi = -1e300;
  for (const auto& p : points) lo = std::min(lo, p.x()), hi = std::max(hi, p.x());
  return points.empty() ? 0 : hi - lo;
}

std::vector<SectionLoop> cross_section(const BodyFrame& body, double height) {
  std::vector<SectionLoop> loops = chain(cut_triangles(body, height));
  std::sort(loops.begin(), loops.end(), [](const SectionLoop& a, const SectionLoop& b) { return a.area() > b.area(); });
  return loops;
}

const Measurement& BodyMeasurements::operator[](const std::string& name) const {
  for (const Measurement& m : all)
    if (m.name == name) return m;
  throw std::out_of_range("measure: no measurement named '" + name + "'");
}

BodyMeasurements measure_body(const BodyFrame& body) {
  validate_body(body, "measure");
  const double H = bounding_box(body.positions).max.y();
  BodyMeasurements out;
  const auto add = [&](const std::string& name, double value, double height, const std::string& how) {
    out.all.push_back({name, value, height, how});
  };
  const auto by_girth = [](const SectionLoop& l) { return l.girth(); };
  // the searches' windows are fractions of the stature, wide around the usual proportions (Drillis and Contini
  // 1966, Body segment parameters): crotch about 0.47 H, knee 0.28, hip 0.52, waist 0.63, armpit 0.73, neck 0.85
  const double crotch = crotch_height(body, 0.30 * H, 0.62 * H);
  // the hip and the bust where the body reaches farthest back (the seat) and forward (the chest), as a tailor finds
  // them; the widest section there would be the thighs' spread at the crotch and the shoulders' at the armpit
  const auto back_reach = [](const SectionLoop& l) { return -l.reach(-1); };
  const auto front_reach = [](const SectionLoop& l) { return l.reach(1); };
  const double hip = found("hip", search(body, crotch + 0.01, crotch + 0.15 * H, false, back_reach));
  const double armpit = armpit_height(body, hip, 0.88 * H);
  const double waist = found("waist", search(body, hip + 0.03, armpit - 0.08, true, by_girth));
  const double bust = found("bust", search(body, waist + 0.03, armpit - 0.01, false, front_reach));
  // under the breasts: the fold lies about 0.05 of the stature below the bust point (a mesh's fold is too shallow to
  // find on a flat chest or a coarse scan)
  const double underbust = std::max(waist + 0.01, bust - 0.05 * H);
  const double neck = found("neck", search(body, armpit + 0.02, 0.92 * H, true, by_girth));
  const double knee = found("knee", search(body, 0.22 * H, 0.33 * H, true, by_girth));
  const double thigh = crotch - 0.03;
  const double shoulder = armpit + 0.25 * (neck - armpit);
  add("stature", H, H, "the top of the body above the soles");
  add("neck girth", girth_at(body, neck), neck, "the narrowest section between the armpits and 0.92 of the stature");
  add("bust girth", girth_at(body, bust), bust,
      "where the chest reaches farthest forward between the waist and the armpits");
  add("under-bust girth", girth_at(body, underbust), underbust,
      "0.05 of the stature below the bust point (above the waist)");
  add("waist girth", girth_at(body, waist), waist, "the narrowest section of the torso between the hip and the bust");
  add("hip girth", girth_at(body, hip), hip,
      "where the seat reaches farthest back, within 0.15 of the stature above the crotch");
  add("thigh girth", girth_at(body, thigh), thigh, "one leg's section 3 cm below the crotch");
  add("knee girth", girth_at(body, knee), knee, "the narrowest leg section between 0.22 and 0.33 of the stature");
  add("upper arm girth", upper_arm_girth(body, armpit - 0.04), armpit - 0.04,
      "the arm's section 4 cm below the armpit (horizontal: a sloping arm's reads long)");
  add("crotch height", crotch, crotch, "the lowest section in which one loop carries the body (the legs join)");
  add("armpit height", armpit, armpit, "the last section before the arms join the torso (it widens 4 cm at once)");
  const auto across = cross_section(body, shoulder);
  add("shoulder width", across.empty() ? 0 : across.front().width(), shoulder,
      "across the shoulders and upper arms, a quarter of the way from the armpits to the neck");
  add("back length", neck - waist, neck, "from the neck's section down to the waist's");
  add("inseam", crotch, crotch, "from the crotch to the soles");
  add("waist to knee", waist - knee, waist, "from the waist's section down to the knee's");
  add("chest girth", girth_at(body, armpit), armpit, "the torso's section at the armpits, shoulder blades included");
  const double width = out["shoulder width"].value_m, top = shoulder_top(body, shoulder, neck, width);
  add("shoulder height", top, top, "the first section above the shoulder width's narrower than half of it");
  return out;
}

}  // namespace clothbench
