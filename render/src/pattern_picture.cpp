// draw_pattern: the meshed panels side by side (pattern view, v up), grid springs, outlines and seam pairs.
#include "clothbench/render/pattern_picture.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace clothbench {

Image draw_pattern(const Pattern& pat, const MeshedPattern& m) {
  if (pat.panels.empty()) throw std::invalid_argument("draw_pattern: the pattern has no panels");
  // each panel's outline box
  std::vector<Vec2d> lo, hi;
  for (const auto& p : pat.panels) {
    lo.push_back(p.outline[0]);
    hi.push_back(p.outline[0]);
    for (const Vec2d& a : p.outline) {
      lo.back() = lo.back().cwiseMin(a);
      hi.back() = hi.back().cwiseMax(a);
    }
  }
  // lay the panels out in a row, a gap of a tenth of the tallest between them
  double tallest = 0, width = 0;
  for (std::size_t p = 0; p < lo.size(); ++p) tallest = std::max(tallest, hi[p].y() - lo[p].y());
  const double gap = 0.1 * tallest;
  std::vector<double> shift;
  for (std::size_t p = 0; p < lo.size(); ++p) {
    shift.push_back(width - lo[p].x());
    width += (hi[p].x() - lo[p].x()) + gap;
  }
  width -= gap;
  const int max_w = 960, max_h = 480, margin = 12;
  const double scale = std::min((max_w - 2 * margin) / width, (max_h - 2 * margin) / tallest);
  Image img(static_cast<int>(std::ceil(width * scale)) + 2 * margin,
            static_cast<int>(std::ceil(tallest * scale)) + 2 * margin);
  auto px = [&](int panel, const Vec2d& uv) {
    const auto k = static_cast<std::size_t>(panel);
    return std::array<int, 2>{margin + static_cast<int>(std::lround((uv.x() + shift[k]) * scale)),
                              margin + static_cast<int>(std::lround((tallest - (uv.y() - lo[k].y())) * scale))};
  };
  auto vertex_px = [&](int v) { return px(m.mesh.panel[static_cast<std::size_t>(v)], m.uv.col(v)); };
  // structural springs
  for (int s = 0; s < m.mesh.spring_count(); ++s) {
    if (m.mesh.kind[static_cast<std::size_t>(s)] != SpringKind::kStructural) continue;
    const auto a = vertex_px(m.mesh.springs(0, s)), b = vertex_px(m.mesh.springs(1, s));
    img.line(a[0], a[1], b[0], b[1], {170, 170, 170});
  }
  // outlines
  for (std::size_t p = 0; p < pat.panels.size(); ++p) {
    const auto& o = pat.panels[p].outline;
    for (std::size_t i = 0; i < o.size(); ++i) {
      const auto a = px(static_cast<int>(p), o[i]), b = px(static_cast<int>(p), o[(i + 1) % o.size()]);
      img.line(a[0], a[1], b[0], b[1], {0, 0, 0});
    }
  }
  // seam pairs: both ends dotted in the seam's colour; the first, middle and last pair joined
  // by a line (they cross where a seam is reversed)
  Eigen::Index pair = 0;
  for (std::size_t s = 0; s < m.seam_pair_count.size(); ++s) {
    const Rgb c = colormap(m.seam_pair_count.size() > 1 ? double(s) / double(m.seam_pair_count.size() - 1) : 0.5);
    const int n = m.seam_pair_count[s];
    for (int k = 0; k < n; ++k, ++pair) {
      const auto a = vertex_px(m.mesh.seam_pairs(0, pair)), b = vertex_px(m.mesh.seam_pairs(1, pair));
      if (k == 0 || k == n / 2 || k == n - 1) img.line(a[0], a[1], b[0], b[1], c);
      img.dot(a[0], a[1], 1, c);
      img.dot(b[0], b[1], 1, c);
    }
  }
  // attached vertices in red
  for (int v : m.mesh.attached) {
    const auto a = vertex_px(v);
    img.dot(a[0], a[1], 1, {220, 30, 30});
  }
  return img;
}

}  // namespace clothbench
