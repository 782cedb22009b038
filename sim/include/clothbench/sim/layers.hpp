#pragma once
/// Garments worn in layers: an outer garment placed round a body that already wears a dressed inner one starts
/// partly inside it (both are placed round the body, not round each other), and cloth against cloth (a thickness,
/// self_contact.hpp) stops points from crossing but cannot undo a crossing it starts from. `clear_of_layer` moves
/// the outer garment's points out before it is sewn. `LayersUnder` then answers the outer garment's points against
/// the cloth under it at every step, as against the body.
#include <vector>

#include "clothbench/sim/cloth.hpp"
#include "clothbench/sim/collider.hpp"

namespace clothbench {

/// Moves each point p of `outer` [m] (3 x n) that lies less than `clearance` [m] outside the `inner` cloth (its
/// points [m] and cells) out along the inner cloth's normal there, to `clearance` outside it. "There" is the inner
/// point q nearest p, if nearer than `reach` [m]; outside is along q's vertex normal (the mean of its cells'),
/// turned away from the cloth's middle at q's height where most of them face inwards. Returns how many moved.
long clear_of_layer(const Points3& inner, const Quads& inner_cells, Points3& outer, Real clearance, Real reach);

/// The dressed layers as a body for the layer worn over them: the dressing paper's future work (section 8: the
/// cloth rendered at each iteration and its collisions read from the frame buffer), with the cloth under as the body
/// whose maps are drawn. At each call the cells of the vertices before `under` (all of whose corners are) are given to
/// a collider as a moving body: their triangles turned to face away from the cloth's middle as clear_of_layer's
/// normals, the cloth's velocities as the body's. The vertices from `under` on are queried against it, and with
/// `faces` the midpoints of their quads (dressing section 6; the quads after the last with a corner under). The body is
/// given again only once a point of it has moved `redraw` since it last was (drawing is what costs: a settled layer
/// is drawn once), so an answer is off by less than that.
class LayersUnder {
 public:
  /// `collider`: not owned, used by nothing else (an image-space one: the maps of an open sheet of cloth say
  /// where a point is behind it, seen from its cameras).
  LayersUnder(Collider& collider, const ClothMesh& mesh, Eigen::Index under, Real redraw, bool faces);
  /// The layers under drawn at positions `x` with velocities `v` (3 x nv), and the points above queried.
  void detect(const Points3& x, const Points3& v);
  /// The first vertex above the layers under.
  Eigen::Index under() const { return under_; }
  /// How many times the layers under were given to the collider.
  long draws() const { return draws_; }
  /// The first quad of the quads above (the mesh's last ones).
  Eigen::Index first_quad() const { return first_quad_; }
  /// One contact per vertex above, from the last detect (vertex under() + k at k), then one per quad above.
  const std::vector<Contact>& contacts() const { return contacts_; }

 private:
  Collider& collider_;
  Eigen::Index under_;
  Real redraw_;
  Quads above_;              // the quads above, with faces (empty without)
  Eigen::Index first_quad_;  // of the mesh's quads, the first of above_
  Points3 midpoints_;        // of above_
  BodyFrame frame_;          // the layers under, as a body, where they were last drawn
  long draws_ = 0;
  std::vector<Contact> contacts_;
};

}  // namespace clothbench
