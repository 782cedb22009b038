// Layers of garments: an outer garment's start moved out of the dressed cloth under it.
#include "clothbench/sim/layers.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace clothbench {

namespace {

// each point's normal: the sum of its cells' (the cross product of a cell's diagonals), normalised
Points3 cell_normals(const Points3& x, const Quads& cells) {
  Points3 n = Points3::Zero(3, x.cols());
  for (Eigen::Index c = 0; c < cells.cols(); ++c) {
    const Vec3 d1 = x.col(cells(2, c)) - x.col(cells(0, c)), d2 = x.col(cells(3, c)) - x.col(cells(1, c));
    const Vec3 face =
        cells(3, c) == cells(2, c) ? Vec3((x.col(cells(1, c)) - x.col(cells(0, c))).cross(d1)) : Vec3(d1.cross(d2));
    for (int k = 0; k < 4; ++k) n.col(cells(k, c)) += face;
  }
  for (Eigen::Index i = 0; i < x.cols(); ++i)
    if (n.col(i).squaredNorm() > 0) n.col(i).normalize();
  return n;
}

// whether most of the normals `n` of the points `x` face away from the middle (x, z) of the cloth
bool faces_out(const Points3& x, const Points3& n) {
  const Vec3 middle = x.rowwise().mean();
  long out = 0;
  for (Eigen::Index i = 0; i < x.cols(); ++i) {
    const Vec3 from(x(0, i) - middle.x(), 0, x(2, i) - middle.z());
    out += n.col(i).dot(from) > 0 ? 1 : -1;
  }
  return out >= 0;
}

// each point's normal, turned so that most point away from the middle of the cloth
Points3 vertex_normals(const Points3& x, const Quads& cells) {
  const Points3 n = cell_normals(x, cells);
  return faces_out(x, n) ? n : Points3(-n);
}

// the cells whose corners are all before `under`
Quads cells_under(const Quads& cells, Eigen::Index under) {
  Quads kept(4, cells.cols());
  Eigen::Index k = 0;
  for (Eigen::Index c = 0; c < cells.cols(); ++c)
    if (cells.col(c).maxCoeff() < under) kept.col(k++) = cells.col(c);
  return kept.leftCols(k);
}

}  // namespace

long clear_of_layer(const Points3& inner, const Quads& inner_cells, Points3& outer, Real clearance, Real reach) {
  const Points3 normal = vertex_normals(inner, inner_cells);
  long moved = 0;
  for (Eigen::Index i = 0; i < outer.cols(); ++i) {
    const Vec3 p = outer.col(i);
    Eigen::Index nearest = -1;
    Real best = reach * reach;
    for (Eigen::Index k = 0; k < inner.cols(); ++k) {
      const Real d = (inner.col(k) - p).squaredNorm();
      if (d < best && normal.col(k).squaredNorm() > 0) best = d, nearest = k;
    }
    if (nearest < 0) continue;
    const Real outside = (p - inner.col(nearest)).dot(normal.col(nearest));
    if (outside >= clearance) continue;
    outer.col(i) += (clearance - outside) * normal.col(nearest);
    ++moved;
  }
  return moved;
}

LayersUnder::LayersUnder(Collider& collider, const ClothMesh& mesh, Eigen::Index under, Real redraw, bool faces)
    : collider_(collider), under_(under), redraw_(redraw), first_quad_(mesh.quads.cols()) {
  if (under <= 0 || under >= mesh.positions.cols())
    throw std::invalid_argument("LayersUnder: the layers under must be some of the cloth's vertices, not all");
  while (first_quad_ > 0 && mesh.quads.col(first_quad_ - 1).minCoeff() >= under) --first_quad_;
  if (faces) above_ = mesh.quads.rightCols(mesh.quads.cols() - first_quad_);
  const Points3 x = mesh.positions.leftCols(under);
  const Quads cells = cells_under(mesh.quads, under);
  frame_.triangles = surface_triangles(cells);
  // a body's triangles wind counter-clockwise seen from outside: away from the cloth's middle
  if (!faces_out(x, cell_normals(x, cells))) frame_.triangles.row(1).swap(frame_.triangles.row(2));
  frame_.moving = true;
}

void LayersUnder::detect(const Points3& x, const Points3& v) {
  const bool moved =
      draws_ == 0 || !((x.leftCols(under_) - frame_.positions).colwise().squaredNorm().maxCoeff() < redraw_ * redraw_);
  if (moved) {
    frame_.positions = x.leftCols(under_);
    frame_.velocities = v.leftCols(under_);
    angle_weighted_normals_into(frame_.positions, frame_.triangles, frame_.normals);
    if (draws_++ == 0)
      collider_.set_body(frame_);
    else
      collider_.update_body(frame_);
  }
  const auto above = static_cast<std::size_t>(x.cols() - under_), quads = static_cast<std::size_t>(above_.cols());
  contacts_.resize(above + quads);
  collider_.query(PointsView(x.data() + 3 * under_, above), {contacts_.data(), above});
  if (quads == 0) return;
  midpoints_.resize(3, above_.cols());
  for (Eigen::Index q = 0; q < above_.cols(); ++q)
    midpoints_.col(q) = 0.25f * (x.col(above_(0, q)) + x.col(above_(1, q)) + x.col(above_(2, q)) + x.col(above_(3, q)));
  collider_.query(PointsView(midpoints_), {contacts_.data() + above, quads});
}

}  // namespace clothbench
