// write_map_pictures: depth, normal and velocity maps of collide_is's MapSet as PNG pairs.
#include "clothbench/render/map_pictures.hpp"

#include <algorithm>

#include "clothbench/collide_is/map_set.hpp"
#include "clothbench/render/image.hpp"

namespace clothbench {

namespace {

// colour of one element: depth as z-buffer value through the colour map (dark near, light far;
// walking Fig. 4), side layer red; empty pixels white
Rgb depth_colour(const MapSet& m, int view, std::size_t i) {
  if (m.mask[i] == MapSet::kEmpty) return {255, 255, 255};
  if (m.mask[i] == MapSet::kSide) return {220, 30, 30};
  const MapFrame& f = m.frame;
  const double zbuf =
      view == MapSet::kFront ? (f.z_max - m.z[i]) / f.depth_range() : (m.z[i] - f.z_min) / f.depth_range();
  return colormap(zbuf);
}

// a unit-range vector as its 8-bit colour (dressing Eq. 6, walking Eq. 9)
Rgb vector_colour(const Vec3& unit_range) {
  const auto c = [](Real x) {
    return static_cast<std::uint8_t>(std::clamp(0.5f * x + 0.5f, 0.0f, 1.0f) * 255.0f + 0.5f);
  };
  return {c(unit_range.x()), c(unit_range.y()), c(unit_range.z())};
}

// front (left) and back (right) side by side, each as its camera sees it, +y up
template <typename Colour>
void write_pair(const MapSet& m, const std::string& path, Colour colour) {
  const int n = m.frame.size;
  Image img(2 * n, n);
  for (int view = 0; view < 2; ++view)
    for (int row = 0; row < n; ++row)
      for (int col = 0; col < n; ++col) img.set(view * n + col, n - 1 - row, colour(view, m.index(view, col, row)));
  img.write_png(path);
}

}  // namespace

std::vector<std::string> write_map_pictures(const MapSet& m, const std::string& base) {
  std::vector<std::string> written{base + "_depth.png", base + "_normal.png"};
  write_pair(m, written[0], [&](int view, std::size_t i) { return depth_colour(m, view, i); });
  write_pair(m, written[1], [&](int, std::size_t i) {
    return m.mask[i] == MapSet::kEmpty ? Rgb{255, 255, 255} : vector_colour(m.normal_at(i));
  });
  if (m.has_velocity) {
    written.push_back(base + "_velocity.png");
    write_pair(m, written[2], [&](int, std::size_t i) {
      return m.mask[i] == MapSet::kEmpty ? Rgb{255, 255, 255} : vector_colour(m.velocity_at(i) / m.max_speed);
    });
  }
  return written;
}

}  // namespace clothbench
