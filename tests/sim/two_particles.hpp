#pragma once
/// The smallest cloth of the sim tests: two free particles joined by one structural spring.
#include "clothbench/sim/cloth.hpp"

namespace clothbench::test {

/// Two particles (vertex area 1 each, so their mass is the material's density) joined by one spring of
/// rest length `rest` [m], stretched by `stretch` [m] along x.
inline ClothMesh two_particles(Real rest, Real stretch) {
  ClothMesh c;
  c.positions.resize(3, 2);
  c.positions.col(0) = Vec3(0, 0, 0);
  c.positions.col(1) = Vec3(rest + stretch, 0, 0);
  c.vertex_area = Scalars::Constant(2, 1);
  c.springs.resize(2, 1);
  c.springs << 0, 1;
  c.rest_length = Scalars::Constant(1, rest);
  c.kind = {SpringKind::kStructural};
  c.quads.resize(4, 0);
  c.seam_pairs.resize(2, 0);
  c.panel = {0, 0};
  c.panel_names = {"pair"};
  return c;
}

}  // namespace clothbench::test
