// What the exact oracle says of a run, and where its worst spring, seam pair and vertex are.
#include "measurement.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "clothbench/bench/cloth_crossings.hpp"
#include "clothbench/bench/oracle.hpp"

namespace clothbench::runner_detail {

namespace {

// "vertex 812 at (0.180, 1.250, -0.020) m, 13.6 mm inside at t = 2.10 s; the collider answered contact at
// -2.1 mm": where and when a point is deepest, and what the collider under test said of it at its last step
std::string describe_vertex(const Simulator& sim, int v, double depth_mm, const std::string& when) {
  const auto p = sim.positions().col(v);
  const auto& contacts = sim.contacts();
  const bool hit = contacts.size() > static_cast<std::size_t>(v) && contacts[static_cast<std::size_t>(v)].hit;
  char text[200];
  std::snprintf(text, sizeof text, "vertex %d at (%.3f, %.3f, %.3f) m, %.1f mm inside %s; ", v, double(p(0)),
                double(p(1)), double(p(2)), depth_mm, when.c_str());
  std::string out = text;
  if (!hit) return out + "the collider answered no contact";
  std::snprintf(text, sizeof text, "the collider answered contact at %.1f mm",
                1e3 * double(contacts[static_cast<std::size_t>(v)].depth));
  return out + text;
}

// the oracle's deepest point at the end of a run: a vertex as describe_vertex, or a quad's midpoint (face queries)
std::string describe_point(const Simulator& sim, long k, double depth_mm) {
  const long n = sim.positions().cols();
  if (k < n) return describe_vertex(sim, static_cast<int>(k), depth_mm, "at the end");
  const int q = static_cast<int>(k - n);
  const auto p = sim.quad_midpoints().col(q);
  const auto& c = sim.mesh().quads;
  char text[200];
  std::snprintf(text, sizeof text,
                "the midpoint of quad %d (vertices %d, %d, %d, %d) at (%.3f, %.3f, %.3f) m, %.1f mm "
                "inside at the end",
                q, c(0, q), c(1, q), c(2, q), c(3, q), double(p(0)), double(p(1)), double(p(2)), depth_mm);
  return text;
}

std::string at_time(double t) {
  char text[32];
  std::snprintf(text, sizeof text, "at t = %.2f s", t);
  return text;
}

// "spring 40 (vertices 12-13), 1.32 m high, ends in contact 1/2, on a seam 0/2": where a spring is
std::string describe_spring(const Simulator& sim, int s) {
  if (s < 0) return "";
  const ClothMesh& mesh = sim.mesh();
  const int ends[2] = {mesh.springs(0, s), mesh.springs(1, s)};
  int in_contact = 0, on_seam = 0;
  for (int v : ends) {
    in_contact +=
        sim.contacts().size() > static_cast<std::size_t>(v) && sim.contacts()[static_cast<std::size_t>(v)].hit;
    on_seam += (mesh.seam_pairs.array() == v).any();
  }
  const double y = 0.5 * double(sim.positions()(1, ends[0]) + sim.positions()(1, ends[1]));
  char text[160];
  std::snprintf(text, sizeof text, "spring %d (vertices %d-%d), %.2f m high, ends in contact %d/2, on a seam %d/2", s,
                ends[0], ends[1], y, in_contact, on_seam);
  return text;
}

// "sleeve_l through front 40, front through back 12": the panels of the crossing springs and of the triangles they
// pass through, the most frequent three pairs ("" when none cross)
std::string describe_cloth_crossings(const ClothMesh& mesh, const Pairs& springs, const ClothCrossings& c) {
  std::map<std::pair<int, int>, int> pairs;
  for (const auto& [s, q] : c.where)
    ++pairs[{mesh.panel[std::size_t(springs(0, s))], mesh.panel[std::size_t(mesh.quads(0, q))]}];
  std::vector<std::pair<int, std::pair<int, int>>> by_count;
  for (const auto& [p, n] : pairs) by_count.emplace_back(-n, p);
  std::sort(by_count.begin(), by_count.end());
  std::string out;
  for (std::size_t i = 0; i < std::min<std::size_t>(3, by_count.size()); ++i)
    out += (i ? ", " : "") + mesh.panel_names[std::size_t(by_count[i].second.first)] + " through " +
           mesh.panel_names[std::size_t(by_count[i].second.second)] + " " + std::to_string(-by_count[i].first);
  return out;
}

// the widest opening along the seams: its vertices, their panels and the gap ("" when all are within 0.01 mm)
std::string describe_seam_gap(const Simulator& sim) {
  const ClothMesh& mesh = sim.mesh();
  const SeamGap w = sim.widest_seam_gap();
  if (w.vertex < 0 || !(w.gap > 1e-5f)) return "";
  const auto panel = [&](int v) {
    return mesh.panel_names[static_cast<std::size_t>(mesh.panel[static_cast<std::size_t>(v)])];
  };
  char text[240];
  if (w.loose)
    std::snprintf(text, sizeof text,
                  "vertex %d (panel %s, no partner) %.2f mm from its partner edge (panel %s, near vertex %d)", w.vertex,
                  panel(w.vertex).c_str(), 1e3 * double(w.gap), panel(w.partner).c_str(), w.partner);
  else
    std::snprintf(text, sizeof text, "seam pair (vertices %d-%d, panels %s and %s), %.2f mm apart", w.vertex, w.partner,
                  panel(w.vertex).c_str(), panel(w.partner).c_str(), 1e3 * double(w.gap));
  return text;
}

}  // namespace

double proxy_deviation_mm(const BodyFrame& proxy, const BodyFrame& exact) {
  std::vector<Real> d;
  Oracle(proxy).signed_distance(exact.positions, d);
  Real m = 0;
  for (const Real x : d) m = std::max(m, std::abs(x));
  return 1e3 * double(m);
}

void note_frame_strain(const Simulator& sim, const StrainStats& strain, double t, RunResult& r) {
  if (double(strain.max) <= r.animate_strain_max) return;
  r.animate_strain_max = double(strain.max);
  r.animate_strain_max_where = describe_spring(sim, strain.max_spring) + " " + at_time(t);
}

void measure_frame(const BodyFrame& frame, const Simulator& sim, const StrainStats& strain, double t, RunResult& r) {
  const Oracle oracle(frame);
  Accuracy a = oracle.measure(sim.positions());
  const Pairs springs = structural_springs(sim.mesh());
  oracle.measure_crossings(sim.positions(), springs, a);
  const ClothCrossings self = cloth_crossings(sim.positions(), springs, sim.mesh().quads, sim.sewn_points());
  if (a.depth_max_mm > r.frame_max(&FrameSample::depth_max_mm))
    r.depth_max_where = describe_vertex(sim, static_cast<int>(a.deepest), a.depth_max_mm, at_time(t));
  r.frame_samples.push_back(
      {t, a.inside_pct, a.depth_max_mm, a.crossings_pct, double(strain.max), double(strain.p99), self.pct});
}

void measure(const Scene& scene, const Simulator& sim, RunResult& r) {
  // the oracle: the points (with face queries the quad midpoints too), the springs' crossings, the faces
  Oracle oracle(r.final_body);
  Points3 points = sim.positions();
  if (scene.solver.face_queries && sim.quad_midpoints().cols() > 0) {
    Points3 all(3, points.cols() + sim.quad_midpoints().cols());
    all << points, sim.quad_midpoints();
    points = std::move(all);
  }
  r.accuracy = oracle.measure(points);
  if (r.accuracy.deepest >= 0 && r.accuracy.depth_max_mm > r.frame_max(&FrameSample::depth_max_mm))
    r.depth_max_where = describe_point(sim, r.accuracy.deepest, r.accuracy.depth_max_mm);
  const Pairs springs = structural_springs(sim.mesh());
  oracle.measure_crossings(sim.positions(), springs, r.accuracy);
  oracle.measure_faces(sim.positions(), sim.mesh().quads, r.accuracy);
  const ClothCrossings self = cloth_crossings(sim.positions(), springs, sim.mesh().quads, sim.sewn_points());
  r.accuracy.cloth_crossings = self.crossings, r.accuracy.cloth_crossings_pct = self.pct;
  // the seams, the strain and the motion left
  r.seam_gap_max_mm = 1e3 * double(sim.seam_gap_max());
  r.seam_gap_where = describe_seam_gap(sim);
  const StrainStats strain = sim.strain();
  r.strain_max = strain.max;
  r.strain_p99 = strain.p99;
  r.strain_over = strain.over;
  r.strain_max_where = describe_spring(sim, strain.max_spring);
  r.cloth_crossings_where = describe_cloth_crossings(sim.mesh(), springs, self);
  r.kinetic_energy = sim.kinetic_energy();
}

}  // namespace clothbench::runner_detail
