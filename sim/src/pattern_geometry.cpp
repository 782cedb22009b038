// Outline geometry of garment patterns: closest points, inside tests, areas, validity (Boost.Geometry),
// flattened curves, validate_pattern.
#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>
#include <typeinfo>
#include <utility>

#include <boost/geometry/algorithms/is_valid.hpp>
#include <boost/geometry/geometries/point_xy.hpp>
#include <boost/geometry/geometries/ring.hpp>

#include "clothbench/sim/garment.hpp"
#include "garment_internal.hpp"

namespace clothbench {

namespace garment_detail {

Closest closest_on_outline(const std::vector<Vec2d>& o, const Vec2d& p) {
  Closest best;
  const int n = static_cast<int>(o.size());
  for (int i = 0; i < n; ++i) {
    const Vec2d a = o[static_cast<std::size_t>(i)], b = o[static_cast<std::size_t>((i + 1) % n)];
    const Vec2d d = b - a;
    const double len2 = d.squaredNorm();
    const double t = len2 > 0 ? std::clamp((p - a).dot(d) / len2, 0.0, 1.0) : 0.0;
    const Vec2d q = a + t * d;
    const double dist = (p - q).norm();
    if (dist < best.dist) best = {q, dist, i, t};
  }
  return best;
}

bool inside(const std::vector<Vec2d>& o, const Vec2d& p) {
  bool in = false;
  const std::size_t n = o.size();
  for (std::size_t i = 0, j = n - 1; i < n; j = i++)
    if ((o[i].y() > p.y()) != (o[j].y() > p.y()) &&
        p.x() < (o[j].x() - o[i].x()) * (p.y() - o[i].y()) / (o[j].y() - o[i].y()) + o[i].x())
      in = !in;
  return in;
}

double cross(const Vec2d& a, const Vec2d& b) { return a.x() * b.y() - a.y() * b.x(); }

// Twice the signed area of a closed outline (shoelace): > 0 counter-clockwise [cm^2].
double twice_signed_area(const std::vector<Vec2d>& o) {
  double a = 0;
  for (std::size_t i = 0; i < o.size(); ++i) a += cross(o[i], o[(i + 1) % o.size()]);
  return a;
}

}  // namespace garment_detail

namespace {

using namespace garment_detail;

namespace bg = boost::geometry;

// Boost.Geometry's is_valid visitor: keeps the failure it reports (it stops at the first) and where it
// is: the two segments of a self-intersection, the apex of a spike. Consecutive duplicate points are
// no failure.
class FaultVisitor {
 public:
  bg::validity_failure_type failure = bg::no_failure;
  int segment = -1, other_segment = -1;  // of a self-intersection
  bool located = false;                  // `at` holds the self-intersection point or spike apex
  Vec2d at = Vec2d::Zero();

  template <bg::validity_failure_type Failure>
  bool apply() {
    return keep(Failure);
  }
  // self-intersections come with their turns, duplicate points with one of them
  template <bg::validity_failure_type Failure, typename Data>
  bool apply(const Data& data) {
    if constexpr (Failure == bg::failure_self_intersections) {
      if (!data.empty()) {
        const auto& turn = *data.begin();
        const int a = static_cast<int>(turn.operations[0].seg_id.segment_index);
        const int b = static_cast<int>(turn.operations[1].seg_id.segment_index);
        segment = std::max(a, b), other_segment = std::min(a, b);
        locate(turn.point);
      }
    }
    return keep(Failure);
  }
  // spikes come with (is the geometry linear, the spike's apex)
  template <bg::validity_failure_type Failure, typename Data1, typename Data2>
  bool apply(const Data1&, const Data2& apex) {
    if constexpr (Failure == bg::failure_spikes) locate(apex);
    return keep(Failure);
  }

 private:
  bool keep(bg::validity_failure_type f) {
    failure = f == bg::failure_duplicate_points ? bg::no_failure : f;
    return failure == bg::no_failure;
  }
  template <typename Point>
  void locate(const Point& p) {
    at = Vec2d(bg::get<0>(p), bg::get<1>(p));
    located = true;
  }
};

// Runs is_valid on the outline as an open ring of the given orientation.
template <bool Clockwise>
FaultVisitor check_ring(const std::vector<Vec2d>& o) {
  bg::model::ring<bg::model::d2::point_xy<double>, Clockwise, false> ring;
  for (const auto& p : o) ring.push_back({p.x(), p.y()});
  FaultVisitor visitor;
  bg::is_valid(ring, visitor, bg::default_strategy());
  return visitor;
}

}  // namespace

OutlineFault outline_fault(const std::vector<Vec2d>& o) {
  OutlineFault f;
  for (std::size_t i = 0; i < o.size(); ++i)
    if (!(o[i].cwiseAbs().maxCoeff() <= kMaxOutlineCoordinateCm)) {  // NaN too
      f.what = o[i].allFinite() ? "has a point beyond +-1e6 cm (10 km)" : "has a point that is not finite";
      f.segment = static_cast<int>(i), f.at = o[i];
      return f;
    }
  // Boost's polygons have one orientation: take the outline's own (a zero area fails anyway)
  FaultVisitor v;
  try {
    v = twice_signed_area(o) < 0 ? check_ring<true>(o) : check_ring<false>(o);
  } catch (const std::bad_cast& e) {  // Boost rescales the outline to integers: a factor out of range
    f.what = "is too small to check (" + std::string(e.what()) + ")";
    return f;
  }
  switch (v.failure) {
    case bg::no_failure: return f;
    case bg::failure_few_points: f.what = "has fewer than 3 points"; break;
    case bg::failure_wrong_topological_dimension: f.what = "has no area (fewer than 3 distinct points)"; break;
    case bg::failure_spikes: f.what = "runs back along itself"; break;
    case bg::failure_self_intersections: f.what = "intersects itself"; break;
    case bg::failure_wrong_orientation: f.what = "has no area"; break;
    default: f.what = "is not a simple polygon (Boost.Geometry validity failure " + std::to_string(v.failure) + ")";
  }
  if (!v.located) return f;
  f.at = v.at;
  if (v.failure == bg::failure_self_intersections) {
    f.segment = v.segment, f.other_segment = v.other_segment;
  } else {
    // a spike: the segment leaving its apex runs back along the one arriving there
    const int n = static_cast<int>(o.size());
    for (int i = 0; i < n && f.segment < 0; ++i)
      if (o[static_cast<std::size_t>(i)] == v.at) f.segment = i, f.other_segment = (i + n - 1) % n;
  }
  return f;
}

bool outline_self_intersects(const std::vector<Vec2d>& o) { return !outline_fault(o).what.empty(); }

double distance_to_outline(const std::vector<Vec2d>& outline, const Vec2d& p) {
  return closest_on_outline(outline, p).dist;
}

std::vector<Vec2d> flatten_bezier(const Vec2d& a, const std::vector<Vec2d>& c, const Vec2d& b, int segments) {
  std::vector<Vec2d> out;
  for (int s = 1; s <= segments; ++s) {
    const double t = double(s) / segments, u = 1 - t;
    if (c.size() == 1)
      out.push_back(u * u * a + 2 * u * t * c[0] + t * t * b);
    else if (c.size() == 2)
      out.push_back(u * u * u * a + 3 * u * u * t * c[0] + 3 * u * t * t * c[1] + t * t * t * b);
    else
      out.push_back(u * a + t * b);
  }
  return out;
}

void validate_pattern(const Pattern& pat) {
  auto fail = [&](const std::string& m) { throw std::invalid_argument("pattern " + pat.name + ": " + m); };
  if (pat.panels.empty()) fail("no panels");
  std::set<std::string> names;
  for (const auto& p : pat.panels) {
    if (!names.insert(p.name).second) fail("duplicate panel '" + p.name + "'");
    const int n = static_cast<int>(p.outline.size());
    if (n < 3) fail("panel '" + p.name + "' has fewer than 3 outline points");
    if (p.edge_begin.empty() || p.edge_begin[0] != 0) fail("panel '" + p.name + "': first edge must start at 0");
    for (std::size_t e = 1; e < p.edge_begin.size(); ++e)
      if (p.edge_begin[e] <= p.edge_begin[e - 1] || p.edge_begin[e] >= n)
        fail("panel '" + p.name + "': bad edge start");
    const OutlineFault fault = outline_fault(p.outline);
    if (!fault.what.empty()) fail("panel '" + p.name + "' outline " + fault.what);
    for (int e : p.attached_edges)
      if (e < 0 || e >= p.edge_count()) fail("panel '" + p.name + "': attached edge out of range");
  }
  std::set<std::array<int, 4>> seen;
  for (const auto& s : pat.seams) {
    const int np = static_cast<int>(pat.panels.size());
    if (s.panel_a < 0 || s.panel_a >= np || s.panel_b < 0 || s.panel_b >= np) fail("seam names a missing panel");
    if (s.edge_a < 0 || s.edge_a >= pat.panels[static_cast<std::size_t>(s.panel_a)].edge_count() || s.edge_b < 0 ||
        s.edge_b >= pat.panels[static_cast<std::size_t>(s.panel_b)].edge_count())
      fail("seam names a missing edge");
    std::array<int, 4> key{s.panel_a, s.edge_a, s.panel_b, s.edge_b};
    if (key[0] > key[2] || (key[0] == key[2] && key[1] > key[3])) key = {s.panel_b, s.edge_b, s.panel_a, s.edge_a};
    if (!seen.insert(key).second) fail("duplicated seam");
  }
}

}  // namespace clothbench
