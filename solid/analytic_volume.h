// SPDX-License-Identifier: GPL-3.0-or-later
// The wall solid's volume computed from the plan alone, independently of the builders, against
// which `roomcad build --check` (solid/wall_check.h) and the tests measure the solid built.
#pragma once

#include "plan/plan.h"

namespace roomcad {

/// The volume of the plan's solid from the plan alone, independent of the builders' planes:
/// (union of walls and slabs) minus (union of holes), walls with sloped tops, holes rectangular
/// or shaped (the opening's outline through the wall), slabs their outline minus their holes.
/// Over z the cross-section's area is a polynomial of degree <= 2 between events: every
/// primitive's corner heights, and the heights where a tilted plane (a sloped top, an edge of
/// a shaped hole) meets two other face planes within their boxes. Each interval takes one
/// exact area (CGAL 2D boolean operations on Epeck) where nothing moves, else Simpson's rule
/// on three. The work is split into small groups: the flat walls and slabs together (as
/// before: one area per interval), each sloped wall against what is near it, each cluster of
/// overlapping holes against the walls and slabs near it.
/// @pre the plan builds (build_model does not throw).
/// @return cubic metres, the exact sum rounded once. O(s n log n) for s intervals of the flat
///         walls and slabs and n of them, plus small groups per sloped wall and hole cluster
///         (candidate triples of planes filtered by boxes).
/// @throws PreconditionError as build_model does for walls and openings that cannot be built.
[[nodiscard]] double analytic_wall_volume(const Plan& plan);

}  // namespace roomcad
