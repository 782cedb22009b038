// `tethers`: long-range attachments (Kim, Chentanez, Mueller 2012) ahead of walking Eq. 5's sweep. If no spring is
// longer than (1 + threshold) l0, no point is farther from another than (1 + threshold) times the shortest path
// between them over the springs' rest lengths (the triangle inequality along the path): each free point is kept
// within that distance of its nearest held point (attached or in contact) on each of two fronts (groups of held
// points joined by springs), which stays where it is, in one pass that carries the cloth's weight to its supports
// however far they are; the sweep then mends the springs locally.
// The paths (multi-source Dijkstra over the structural and shear springs and the sewn seam pairs, at zero length)
// are found again when the set of held points changes.
#include <functional>
#include <limits>
#include <queue>

#include "limiters.hpp"
#include "stretch_rules.hpp"
#include "velocity_sweep.hpp"

namespace clothbench {

namespace {

class Tethers final : public VelocitySweep<Tethers> {
 public:
  using VelocitySweep::VelocitySweep;

  void limit_velocities(LimitState& s, bool contacts_hold) override {
    begin(s);
    if (held_ != anchors_held_) anchors_held_ = held_, find_anchors();
    pull_to_anchors();
    passes(contacts_hold);
  }

  std::pair<Real, Real> split(int a, int b, const Vec3&, Real va, Real vb, Real target) const {
    return stretch_rules::average(va, vb, mass(a), mass(b), target);  // walking Eq. 5
  }

 private:
  // every vertex's nearest held vertices on two fronts (groups of held vertices joined by springs) and the rest
  // lengths of the shortest paths to them: a multi-source Dijkstra in which a vertex is settled once per front, at
  // most twice (a cloth held on two sides, between the arm and the torso, is tied to both)
  void find_anchors() {
    const ClothMesh& mesh = s_->mesh;
    const std::size_t nv = anchors_held_.size();
    const auto ns = static_cast<std::size_t>(mesh.springs.cols());
    group_.assign(nv, -1);
    for (std::size_t g = 0; g < s_->merged.size(); ++g)
      for (int i : s_->merged[g]) group_[static_cast<std::size_t>(i)] = static_cast<int>(g);
    // the paths run over the structural and shear springs, and over a seam pair once sewn (one merged group), at
    // zero length
    const auto usable = [&](int i, int j, std::size_t e) {
      if (e < ns) return mesh.kind[e] != SpringKind::kFlexion;
      return group_[static_cast<std::size_t>(i)] >= 0 &&
             group_[static_cast<std::size_t>(i)] == group_[static_cast<std::size_t>(j)];
    };
    const auto length = [&](std::size_t e) { return e < ns ? mesh.rest_length[static_cast<Eigen::Index>(e)] : Real(0); };
    label_fronts(usable);
    tether_.assign(2 * nv, Tether{});
    struct Item {
      Real path;
      int vertex, anchor;
      bool operator>(const Item& o) const { return path > o.path; }
    };
    std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
    for (std::size_t i = 0; i < nv; ++i)
      if (anchors_held_[i]) queue.push({Real(0), static_cast<int>(i), static_cast<int>(i)});
    while (!queue.empty()) {
      const Item it = queue.top();
      queue.pop();
      Tether* t = &tether_[2 * static_cast<std::size_t>(it.vertex)];
      const int front = front_[static_cast<std::size_t>(it.anchor)];
      if (t[0].anchor >= 0 && (t[1].anchor >= 0 || front_[static_cast<std::size_t>(t[0].anchor)] == front)) continue;
      (t[0].anchor < 0 ? t[0] : t[1]) = {it.anchor, it.path};
      for_each_neighbour(it.vertex, [&](int j, std::size_t e) {
        if (usable(it.vertex, j, e)) queue.push({it.path + length(e), j, it.anchor});
      });
    }
  }

  // fronts: the groups of held vertices joined by springs or sewn seam pairs
  template <class Usable>
  void label_fronts(const Usable& usable) {
    const std::size_t nv = anchors_held_.size();
    front_.assign(nv, -1);
    std::vector<int> stack;
    int fronts = 0;
    for (std::size_t r = 0; r < nv; ++r) {
      if (!anchors_held_[r] || front_[r] >= 0) continue;
      front_[r] = fronts;
      stack.assign(1, static_cast<int>(r));
      while (!stack.empty()) {
        const int i = stack.back();
        stack.pop_back();
        for_each_neighbour(i, [&](int j, std::size_t e) {
          if (!anchors_held_[static_cast<std::size_t>(j)] || front_[static_cast<std::size_t>(j)] >= 0 || !usable(i, j, e)) return;
          front_[static_cast<std::size_t>(j)] = fronts;
          stack.push_back(j);
        });
      }
      ++fronts;
    }
  }

  // Kim et al. 2012: a free point ending the step farther from an anchor than (1 + threshold) times the path
  // between them is brought back onto that sphere; the anchor keeps its velocity
  void pull_to_anchors() {
    Points3& v = s_->v;
    const Points3& x = s_->x;
    const Real dt = s_->dt, factor = 1 + params_.threshold;
    for (Eigen::Index i = 0; i < x.cols(); ++i) {
      if (anchors_held_[static_cast<std::size_t>(i)] || s_->inv_m[i] == 0) continue;
      for (std::size_t k = 0; k < 2; ++k) {
        const Tether& t = tether_[2 * static_cast<std::size_t>(i) + k];
        if (t.anchor < 0) break;
        const Vec3 d = (x.col(i) + dt * v.col(i)) - (x.col(t.anchor) + dt * v.col(t.anchor));
        const Real len = d.norm(), max_len = factor * t.path;
        if (len > max_len) v.col(i) -= ((len - max_len) / (len * dt)) * d;
      }
    }
  }

  struct Tether {
    int anchor = -1;  // a held vertex (-1: none)
    Real path = 0;    // the rest length of the shortest path to it [m]
  };
  std::vector<std::uint8_t> anchors_held_;  // per vertex: held when the anchors were found
  std::vector<Tether> tether_;              // per vertex, two: its nearest anchors on two fronts
  std::vector<int> front_;                  // per held vertex: its front (work space)
  std::vector<int> group_;                  // per vertex: its merged group (-1: none; work space)
};

}  // namespace

std::unique_ptr<Limiter> make_tether_limit(const LimiterParams& params) { return std::make_unique<Tethers>(params); }

}  // namespace clothbench
