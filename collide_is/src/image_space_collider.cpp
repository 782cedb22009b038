#include "clothbench/collide_is/image_space_collider.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "clothbench/collide_is/device_maps.hpp"
#include "clothbench/sim/timer.hpp"

namespace clothbench {

ImageSpaceCollider::ImageSpaceCollider(std::unique_ptr<MapRenderer> renderer, const ColliderOptions& options,
                                       double setup_ms, DepthTest test, ViewRule rule)
    : renderer_(std::move(renderer)), options_(options), test_(test), rule_(rule) {
  if (!renderer_) throw std::invalid_argument("ImageSpaceCollider: no renderer");
  check_view_options(options);
  if (!(options.max_speed > 0)) throw std::invalid_argument("ImageSpaceCollider: max_speed must be > 0");
  stats_.setup_ms = setup_ms;
  device_ = renderer_->device_maps();
}

const MapSet& ImageSpaceCollider::maps() const {
  if (!device_) return maps_;
  if (!copied_ && vertex_count_ > 0) device_->copy(slot_, copy_);
  copied_ = true;
  return copy_;
}

void ImageSpaceCollider::draw(const BodyFrame& body, MapSet& maps, int slot) {
  if (!device_) {
    render_maps_into(body, *renderer_, options_, maps, region_);
    return;
  }
  shape_maps(body, options_, maps, region_);
  device_->draw(body, maps, side_layer_rings(options_, maps.frame.pixel), slot);
  if (slot == slot_) copied_ = false;
}

std::string_view ImageSpaceCollider::name() const {
  const std::string_view r = renderer_->name();
  return r == "gl" ? "is-gl" : r == "egl" ? "is-egl" : "is-cpu";
}

std::string ImageSpaceCollider::device() const { return renderer_->device(); }

void ImageSpaceCollider::set_body(const BodyFrame& body) {
  validate_body(body, std::string(name()) + " set_body");
  Stopwatch watch;
  draw(body, maps_, slot_);
  vertex_count_ = body.vertex_count();
  prepared_ = false;
  stats_.setup_ms += watch.ms();
}

void ImageSpaceCollider::check_update(const BodyFrame& body) const {
  if (vertex_count_ == 0) throw std::logic_error(std::string(name()) + ": update_body before set_body");
  if (body.vertex_count() != vertex_count_)
    throw std::invalid_argument(std::string(name()) + ": update_body with a different vertex count");
}

bool ImageSpaceCollider::prepare_body(const BodyFrame& body) {
  check_update(body);
  // a static body keeps the maps of set_body
  if (!body.moving && !maps_.has_velocity) return false;
  Stopwatch watch;
  draw(body, next_, 1 - slot_);
  prepared_ = true;
  prepared_ms_ = watch.ms();
  return true;
}

void ImageSpaceCollider::update_body(const BodyFrame& body) {
  check_update(body);
  ++stats_.updates;
  if (prepared_) {
    std::swap(maps_, next_);
    slot_ = 1 - slot_;
    copied_ = false;
    prepared_ = false;
    stats_.update_ms += prepared_ms_;
    return;
  }
  // a static body keeps the maps of set_body
  if (!body.moving && !maps_.has_velocity) return;
  Stopwatch watch;
  draw(body, maps_, slot_);
  stats_.update_ms += watch.ms();
}

namespace {

// element of `view` at unmirrored column col (only the back map is mirrored, dressing Eq. 8)
inline std::size_t element(const MapSet& m, int view, int col, int row) {
  const int n = m.frame.size;
  return m.index(view, view == MapSet::kBack ? n - 1 - col : col, row);
}

// normal and velocity blended bilinearly over the four pixel centres around world (a, b), the
// view's column and row coordinates; false (outputs untouched) unless all four are body pixels
// (a view's map only: a peeled map's neighbours may hold another surface)
bool blend(const MapSet& m, int view, Real a_world, Real b_world, Vec3& normal, Vec3& velocity) {
  const MapFrame& f = m.frame;
  const Real u = (a_world - f.origin(MapFrame::column_axis(view))) / f.pixel - 0.5f;
  const Real v = (b_world - f.origin(MapFrame::row_axis(view))) / f.pixel - 0.5f;
  if (!(u >= 0 && v >= 0 && u < m.frame.size - 1 && v < m.frame.size - 1)) return false;
  const int col = static_cast<int>(u), row = static_cast<int>(v);
  const Real a = u - col, b = v - row;
  Vec3 n = Vec3::Zero(), vel = Vec3::Zero();
  for (int k = 0; k < 4; ++k) {
    const std::size_t j = element(m, view, col + (k & 1), row + (k >> 1));
    if (m.mask[j] != MapSet::kBody) return false;
    const Real w = ((k & 1) ? a : 1 - a) * ((k >> 1) ? b : 1 - b);
    n += w * m.raw_normal_at(j);
    if (m.has_velocity) vel += w * m.velocity_at(j);
  }
  if (!(n.norm() > 0)) return false;
  normal = n.normalized();
  velocity = vel;
  return true;
}

// one pair of opposite views' answer at a point (views 2 pair and 2 pair + 1)
struct PairAnswer {
  Real depth = 0;   // max(p - front surface, back surface - p) along the pair's axis [m]; +inf empty
  int map = 0;      // the map (a view, or a layer peeled from the front view) whose surface is nearer
  int col = 0, row = 0;  // the pixel (unmirrored window column and row)
  bool side = false;     // a side-layer pixel: the tolerance band outside the silhouette (dressing 5.4)
  // outside by a line that somewhere left the body more often than it had entered: a closed surface is not
  // crossed so, a skinned one folded through itself is (an armpit's crease), and that line's count says nothing
  bool folded = false;
  // seen from outside: beyond the pair's surfaces, nothing drawn, or the side layer
  bool outside() const { return depth > 0 || side; }
};

// With peeled layers the line through the pixel lists where it crosses the body's surface: layer 1
// (the front view's surface, largest coordinate), layer 2, ... Each crossing enters the body where its
// normal faces the front camera and leaves it otherwise; counting them (the winding number along the
// line, never below 0) gives where the line is inside the union of the body's parts, which a skinned
// body's overlapping parts (an arm pressed into the torso) make differ from alternating in and out. A
// point below layer 1 is inside between a crossing into the union and the next crossing out of it,
// outside in a gap between a crossing out and the next crossing in (depth > 0); its depth and map are
// the nearer of the two. The pair's answer stands where the layers cannot say: below the last
// surface of a line the peeling saw whole, or below the last layer kept when there may be more
// (then, as the pair: inside between the last crossing into the union, or the last layer, and the back view).
// Where two parts overlap, cloth between them is pinched (Baraff, Witkin and Kass 2003): the union has no
// way out for it but through one of the parts, which would carry it across a limb and stretch its springs
// around it. So a point inside the union nearer the middle of an overlap along the line than the union's
// surface is answered by that middle, where the parts meet: it is sent there along the line, by the
// overlap's far edge (the surface on the other side of the middle, facing the point), and held there.
struct Crossing {
  Real z;
  int map;
};
using Overlaps = std::array<std::array<Crossing, 2>, 4>;  // where the line is inside two parts: top and bottom

// a point inside the union between above_z and below_z: to the middle of an overlap there, where the parts meet,
// when it is nearer than the surface a answers by
void send_to_pinch(const Overlaps& overlaps, int n, Real x, Real above_z, Real below_z, PairAnswer& a) {
  for (int o = 0; o < n; ++o) {
    const auto& [top, bottom] = overlaps[static_cast<std::size_t>(o)];
    const Real middle = 0.5f * (top.z + bottom.z), to_middle = std::abs(x - middle);
    if (top.z > above_z || bottom.z < below_z || !(to_middle < -a.depth)) continue;
    a.depth = -to_middle;
    a.map = x < middle ? top.map : bottom.map;
  }
}

// (parts: ColliderOptions::overlapping_parts, the pinch and fold rules on)
void between_layers(const MapSet& m, bool parts, int front, int col, int row, Real x, PairAnswer& a) {
  const MapFrame& f = m.frame;
  const int axis = MapFrame::view_axis(front);
  std::array<Crossing, 8> union_crossings{};  // into the union, out of it, into it, ...
  Overlaps overlaps{};
  int crossings = 0, winding = 0, n_overlaps = 0;
  bool folded = false;
  Crossing last{};
  for (int layer = 1; layer <= f.layers; ++layer) {
    const int map = f.peel_map(front, layer);
    const std::size_t i = element(m, map, col, row);
    if (m.mask[i] != MapSet::kBody) break;
    last = {m.z[i], map};
    const bool enters = layer == 1 || m.raw_normal_at(i)[axis] > 0;
    const int before = winding;
    if (before == 0 && !enters) folded = true;
    winding = std::max(0, winding + (enters ? 1 : -1));
    if ((before == 0) != (winding == 0)) union_crossings[crossings++] = last;
    if (before < 2 && winding == 2 && n_overlaps < 4) overlaps[n_overlaps][0] = last;
    if (before == 2 && winding < 2 && n_overlaps < 4) overlaps[n_overlaps++][1] = last;
  }
  for (int k = 1; k < crossings; ++k) {
    if (x < union_crossings[k].z) continue;
    const Crossing& above = union_crossings[k - 1];
    const Crossing& below = union_crossings[k];
    const Real to_above = above.z - x, to_below = x - below.z;
    a.depth = k % 2 == 1 ? -std::min(to_above, to_below) : std::min(to_above, to_below);
    a.map = to_above <= to_below ? above.map : below.map;
    if (k % 2 == 1 && parts) send_to_pinch(overlaps, n_overlaps, x, above.z, below.z, a);
    a.folded = parts && folded && a.depth > 0;
    return;
  }
  const bool whole = f.layers == 1 || m.mask[element(m, f.peel_map(front, f.layers), col, row)] != MapSet::kBody;
  if (whole) return;
  const Crossing above = winding > 0 ? union_crossings[crossings - 1] : last;
  const Real back = m.z[element(m, front + 1, col, row)], d_back = back - x;
  a.depth = std::max(x - above.z, d_back);
  a.map = x - above.z >= d_back ? above.map : front + 1;
  if (a.depth < 0 && parts) send_to_pinch(overlaps, n_overlaps, x, above.z, back, a);
}

// dressing Eq. 5/9, walking Eq. 11/12 along the pair's axis; false when p is outside its image (the pair a
// template argument: its axes are constants, as they were before there were more views than the papers' two)
template <int Pair>
bool pair_answer(const MapSet& m, bool parts, const Vec3& p, PairAnswer& a) {
  const MapFrame& f = m.frame;
  constexpr int front = 2 * Pair, cu = MapFrame::column_axis(front), rv = MapFrame::row_axis(front);
  constexpr int axis = MapFrame::view_axis(front);
  // world -> map (dressing Eq. 8 / walking Eq. 11): front column u, back column size - 1 - u
  const Real u = (p[cu] - f.origin(cu)) / f.pixel, v = (p[rv] - f.origin(rv)) / f.pixel;
  if (!(u >= 0 && v >= 0 && u < f.size && v < f.size)) return false;
  a.col = static_cast<int>(u), a.row = static_cast<int>(v);
  const std::size_t fi = element(m, front, a.col, a.row), bi = element(m, front + 1, a.col, a.row);
  // between the front and back surfaces within tol (dressing Eq. 5/9, walking Eq. 12)
  const Real d_front = p[axis] - m.z[fi], d_back = m.z[bi] - p[axis];
  a.depth = std::max(d_front, d_back);
  // the nearer surface's map answers (beyond the local body centre: the front map)
  a.map = d_front >= d_back ? front : front + 1;
  a.side = m.mask[fi] == MapSet::kSide;
  a.folded = false;
  if (f.layers > 1 && d_front < 0 && m.mask[fi] == MapSet::kBody) between_layers(m, parts, front, a.col, a.row, p[axis], a);
  return true;
}

// whether pair answer `b` replaces `a` under `rule`
bool replaces(ViewRule rule, const PairAnswer& a, const PairAnswer& b) {
  if (rule == ViewRule::kAllPairs) return b.depth > a.depth;
  if (rule == ViewRule::kAnyPair) return b.depth < a.depth;
  // kHull: a pair that sees the point from outside wins: the nearest surface beyond which it lies,
  // else a side-layer answer (a guess of one pixel, not a bound), else a pair that sees nothing;
  // inside every pair, the pair whose surface is nearest along its axis. A pair outside only by a folded
  // line (PairAnswer::folded) wins over none: a pair inside outranks it
  const auto key = [](const PairAnswer& x) { return x.side ? 1e30f : x.depth; };
  const auto rank = [](const PairAnswer& x) { return x.outside() ? (x.folded ? 0 : 2) : 1; };
  if (rank(a) != rank(b)) return rank(b) > rank(a);
  if (a.outside()) return b.outside() && key(b) < key(a);
  return b.outside() || b.depth > a.depth;
}

// the answering pair of views at p; false when no pair's image holds p
bool choose(const MapSet& m, ViewRule rule, bool parts, const Vec3& p, PairAnswer& best) {
  if (m.frame.views == 2) return pair_answer<0>(m, parts, p, best);  // the papers' front/back: nothing to choose
  bool any = false;
  const auto consider = [&](bool inside_image, const PairAnswer& a) {
    if (inside_image && (!any || replaces(rule, best, a))) best = a, any = true;
  };
  PairAnswer a;
  consider(pair_answer<0>(m, parts, p, a), a);
  consider(pair_answer<1>(m, parts, p, a), a);
  if (m.frame.views == 6) consider(pair_answer<2>(m, parts, p, a), a);
  return any;
}

}  // namespace

bool ImageSpaceCollider::answer(const Vec3& p, Contact& c) const {
  const MapFrame& f = maps_.frame;
  const Real tol = options_.tol;
  c.depth = std::numeric_limits<float>::infinity();
  PairAnswer a;
  if (!choose(maps_, rule_, options_.overlapping_parts, p, a)) return false;
  const Real depth_z = a.depth;
  const bool plane = test_ == DepthTest::kTangentPlane;
  if (!(depth_z < (plane ? tol + f.pixel : tol))) {
    c.depth = std::max(depth_z, tol);
    return false;
  }
  const int view = f.view_of(a.map), cu = MapFrame::column_axis(view), rv = MapFrame::row_axis(view);
  const std::size_t i = element(maps_, a.map, a.col, a.row);
  c.depth = depth_z;
  c.normal = maps_.normal_at(i);
  bool blended = false;
  if (plane) {
    // signed distance to the tangent plane at the pixel centre's surface point; points between
    // the surfaces stay inside (the plane distance never exceeds the distance along the axis)
    Vec3 s;
    s[cu] = f.origin(cu) + (a.col + 0.5f) * f.pixel;
    s[rv] = f.origin(rv) + (a.row + 0.5f) * f.pixel;
    s[MapFrame::view_axis(view)] = maps_.z[i];
    const Real d = (p - s).dot(c.normal);
    c.depth = depth_z > 0 ? d : std::clamp(d, depth_z, 0.0f);
    if (!(c.depth < tol)) {
      c = Contact{};
      c.depth = std::max(d, tol);
      return false;
    }
    // normal and velocity at the foot of the perpendicular, blended over four pixel centres
    const Vec3 foot = p - d * c.normal;
    blended = a.map == view && blend(maps_, view, foot[cu], foot[rv], c.normal, c.body_velocity);
  }
  if (!blended) c.body_velocity = maps_.velocity_at(i);
  // side-layer pixels stand for the tolerance band outside the silhouette (dressing 5.4)
  if (maps_.mask[i] == MapSet::kSide) c.depth = std::max(c.depth, 0.0f);
  c.hit = true;
  return true;
}

void ImageSpaceCollider::query(PointsView points, ContactsOut out) {
  Stopwatch watch;
  std::int64_t hits = 0, degenerate = 0;
  if (device_ && vertex_count_ > 0) device_->query(slot_, points, {test_, rule_, options_.tol, options_.overlapping_parts}, out.data);
  for (std::size_t k = 0; k < points.count; ++k) {
    Contact& c = out[k];
    const Vec3 p = points[k];
    // NaN or infinite points cannot be answered
    if (!p.allFinite()) {
      ++degenerate;
      c = Contact{};
      c.depth = std::numeric_limits<float>::infinity();
      continue;
    }
    if (device_ && vertex_count_ > 0) {
      hits += c.hit;
      continue;
    }
    c = Contact{};
    hits += answer(p, c);
  }
  stats_.query_ms += watch.ms();
  ++stats_.queries;
  stats_.points += static_cast<std::int64_t>(points.count);
  stats_.hits += hits;
  stats_.degenerate += degenerate;
}

DepthTest image_space_depth_test(const ColliderOptions& o) {
  return o.tangent_plane ? DepthTest::kTangentPlane : DepthTest::kPapers;
}

std::unique_ptr<Collider> make_is_gl_collider(const ColliderOptions& options) {
  // context creation and shader compilation count as set-up
  Stopwatch watch;
  auto renderer = make_gl_map_renderer();
  return std::make_unique<ImageSpaceCollider>(std::move(renderer), options, watch.ms(),
                                              image_space_depth_test(options));
}

std::unique_ptr<Collider> make_is_cpu_collider(const ColliderOptions& options) {
  return std::make_unique<ImageSpaceCollider>(make_cpu_map_renderer(), options, 0.0, image_space_depth_test(options));
}

}  // namespace clothbench
