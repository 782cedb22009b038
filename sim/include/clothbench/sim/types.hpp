#pragma once
/// Scalar and array types shared by every clothbench module (SI units throughout).
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstddef>
#include <cstdint>

namespace clothbench {

using Real = float;                               ///< one scalar for the whole code base
using Vec3 = Eigen::Matrix<Real, 3, 1>;           ///< a point or vector [m], [m/s] or unitless
using Points3 = Eigen::Matrix<Real, 3, Eigen::Dynamic>;  ///< packed xyz columns (3 x n)
using Tris = Eigen::Matrix<std::int32_t, 3, Eigen::Dynamic>;  ///< triangle vertex indices (3 x nt)
using Quads = Eigen::Matrix<std::int32_t, 4, Eigen::Dynamic>; ///< quad vertex indices, cyclic (4 x nq)
using Pairs = Eigen::Matrix<std::int32_t, 2, Eigen::Dynamic>; ///< index pairs (2 x n)
using Triples = Eigen::Matrix<std::int32_t, 3, Eigen::Dynamic>; ///< index triples (3 x n)
using Scalars = Eigen::Matrix<Real, Eigen::Dynamic, 1>;       ///< one value per element (n)

/// Standard gravity [m/s^2], along -Y (DESIGN.md: +Y up).
inline constexpr Real kGravity = 9.81f;

}  // namespace clothbench
