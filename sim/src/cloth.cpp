#include "clothbench/sim/cloth.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace clothbench {

const char* to_string(SpringKind kind) {
  switch (kind) {
    case SpringKind::kStructural: return "structural";
    case SpringKind::kShear: return "shear";
    case SpringKind::kFlexion: return "flexion";
  }
  return "?";
}

int ClothMesh::count(SpringKind k) const { return static_cast<int>(std::count(kind.begin(), kind.end(), k)); }

Real ClothMesh::shortest(SpringKind k) const {
  Real shortest = 0;
  for (Eigen::Index s = 0; s < springs.cols(); ++s)
    if (kind[static_cast<std::size_t>(s)] == k && (shortest == 0 || rest_length[s] < shortest))
      shortest = rest_length[s];
  return shortest;
}

namespace {

// appends the columns of b to a, adding `shift` to every entry
template <class M>
void append_cols(M& a, const M& b, typename M::Scalar shift) {
  const Eigen::Index n = a.cols();
  a.conservativeResize(a.rows(), n + b.cols());
  a.rightCols(b.cols()) = b.array() + shift;
}

}  // namespace

void ClothMesh::append(const ClothMesh& o) {
  const auto shift = static_cast<std::int32_t>(vertex_count());
  const auto panel_shift = static_cast<std::int32_t>(panel_names.size());
  append_cols(positions, o.positions, Real(0));
  vertex_area.conservativeResize(vertex_area.size() + o.vertex_area.size());
  vertex_area.tail(o.vertex_area.size()) = o.vertex_area;
  append_cols(springs, o.springs, shift);
  rest_length.conservativeResize(rest_length.size() + o.rest_length.size());
  rest_length.tail(o.rest_length.size()) = o.rest_length;
  kind.insert(kind.end(), o.kind.begin(), o.kind.end());
  append_cols(quads, o.quads, shift);
  append_cols(seam_pairs, o.seam_pairs, shift);
  append_cols(seam_loose, o.seam_loose, shift);
  for (auto p : o.panel) panel.push_back(p + panel_shift);
  panel_names.insert(panel_names.end(), o.panel_names.begin(), o.panel_names.end());
  for (auto a : o.attached) attached.push_back(a + shift);
}

void ClothMesh::validate(const std::string& what) const {
  const Eigen::Index nv = positions.cols();
  auto fail = [&](const std::string& msg) { throw std::invalid_argument(what + ": " + msg); };
  if (nv == 0) fail("cloth has no vertices");
  if (vertex_area.size() != nv) fail("vertex_area size differs from the vertex count");
  if (!positions.allFinite()) fail("non-finite vertex position");
  if (!(vertex_area.array() > 0).all() || !vertex_area.allFinite()) fail("vertex area must be > 0");
  if (rest_length.size() != springs.cols() || static_cast<Eigen::Index>(kind.size()) != springs.cols())
    fail("spring arrays differ in length");
  if (springs.cols() && !(rest_length.array() > 0).all()) fail("spring natural length must be > 0");
  auto in_range = [&](const auto& m) { return m.size() == 0 || (m.minCoeff() >= 0 && m.maxCoeff() < nv); };
  if (!in_range(springs) || !in_range(quads) || !in_range(seam_pairs) || !in_range(seam_loose))
    fail("vertex index out of range");
  for (auto a : attached)
    if (a < 0 || a >= nv) fail("attached vertex index out of range");
}

Tris ClothMesh::surface_triangles() const { return clothbench::surface_triangles(quads); }

Tris surface_triangles(const Quads& quads) {
  std::vector<std::int32_t> t;
  for (Eigen::Index q = 0; q < quads.cols(); ++q) {
    const auto c = quads.col(q);
    t.insert(t.end(), {c(0), c(1), c(2)});
    if (c(3) != c(2)) t.insert(t.end(), {c(0), c(2), c(3)});
  }
  return Eigen::Map<const Tris>(t.data(), 3, static_cast<Eigen::Index>(t.size() / 3));
}

ClothMesh make_grid_cloth(int nx, int ny, Real spacing, const Vec3& origin, const Vec3& u, const Vec3& v) {
  if (nx < 2 || ny < 2 || !(spacing > 0)) throw std::invalid_argument("grid cloth: need nx, ny >= 2 and spacing > 0");
  ClothMesh c;
  const int nv = nx * ny;
  auto id = [nx](int i, int j) { return j * nx + i; };
  c.positions.resize(3, nv);
  c.vertex_area.resize(nv);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      c.positions.col(id(i, j)) = origin + spacing * (Real(i) * u + Real(j) * v);
      // a vertex carries a quarter of each adjacent cell
      const Real wx = (i == 0 || i == nx - 1) ? 0.5f : 1.f;
      const Real wy = (j == 0 || j == ny - 1) ? 0.5f : 1.f;
      c.vertex_area[id(i, j)] = wx * wy * spacing * spacing;
    }
  std::vector<std::array<int, 2>> ends;
  std::vector<Real> rest;
  auto add = [&](int a, int b, SpringKind k, Real l0) {
    ends.push_back({a, b});
    rest.push_back(l0);
    c.kind.push_back(k);
  };
  const Real diag = spacing * Real(M_SQRT2);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      if (i + 1 < nx) add(id(i, j), id(i + 1, j), SpringKind::kStructural, spacing);
      if (j + 1 < ny) add(id(i, j), id(i, j + 1), SpringKind::kStructural, spacing);
      if (i + 1 < nx && j + 1 < ny) {
        add(id(i, j), id(i + 1, j + 1), SpringKind::kShear, diag);
        add(id(i + 1, j), id(i, j + 1), SpringKind::kShear, diag);
      }
      if (i + 2 < nx) add(id(i, j), id(i + 2, j), SpringKind::kFlexion, 2 * spacing);
      if (j + 2 < ny) add(id(i, j), id(i, j + 2), SpringKind::kFlexion, 2 * spacing);
    }
  c.springs.resize(2, static_cast<Eigen::Index>(ends.size()));
  c.rest_length.resize(static_cast<Eigen::Index>(ends.size()));
  for (std::size_t s = 0; s < ends.size(); ++s) {
    c.springs.col(static_cast<Eigen::Index>(s)) << ends[s][0], ends[s][1];
    c.rest_length[static_cast<Eigen::Index>(s)] = rest[s];
  }
  c.quads.resize(4, (nx - 1) * (ny - 1));
  for (int j = 0; j + 1 < ny; ++j)
    for (int i = 0; i + 1 < nx; ++i)
      c.quads.col(j * (nx - 1) + i) << id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1);
  c.panel.assign(nv, 0);
  c.panel_names = {"grid"};
  c.seam_pairs.resize(2, 0);
  c.seam_loose.resize(3, 0);
  return c;
}

std::vector<int> sewn_point_of(std::size_t vertex_count, const std::vector<std::vector<int>>& groups) {
  std::vector<int> point(vertex_count);
  std::iota(point.begin(), point.end(), 0);
  for (const auto& group : groups)
    for (int i : group)
      if (i >= 0 && static_cast<std::size_t>(i) < vertex_count) point[static_cast<std::size_t>(i)] = group.front();
  return point;
}

}  // namespace clothbench
