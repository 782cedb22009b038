#pragma once
/// Garments worn in layers: an outer garment placed round a body that already wears a dressed inner one starts
/// partly inside it (both are placed round the body, not round each other), and cloth against cloth (a thickness,
/// self_contact.hpp) stops points from crossing but cannot undo a crossing it starts from. `clear_of_layer` moves
/// the outer garment's points out before it is sewn.
#include "clothbench/sim/types.hpp"

namespace clothbench {

/// Moves each point p of `outer` [m] (3 x n) that lies less than `clearance` [m] outside the `inner` cloth (its
/// points [m] and cells) out along the inner cloth's normal there, to `clearance` outside it. "There" is the inner
/// point q nearest p, if nearer than `reach` [m]; outside is along q's vertex normal (the mean of its cells'),
/// turned away from the cloth's middle at q's height where most of them face inwards. Returns how many moved.
long clear_of_layer(const Points3& inner, const Quads& inner_cells, Points3& outer, Real clearance, Real reach);

}  // namespace clothbench
