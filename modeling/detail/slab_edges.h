// SPDX-License-Identifier: GPL-3.0-or-later
// Slabs laid into the walls that bound them (docs/plan-format.md, "Slabs and walls").
//
// People draw a floor up to a wall's face: its edge lies on the wall's side line only within
// rounding (a side is centre line +- thickness / 2, which doubles rarely hold), so slab and
// wall would meet along a sliver or an edge, and the solid would not be 2-manifold. A slab
// edge that runs along a wall's side, within the site's join tolerance, is moved a quarter of
// the wall's thickness into the wall, when the wall stands over the slab's whole height there:
// what the slab gains lies inside the wall, so the solid (their union) is the same, only
// without the sliver.
#pragma once

#include <vector>

#include "modeling/detail/wall_frame.h"
#include "modeling/plan.h"

namespace roomcad::detail {

/// Lays every edge of the slab (outline and holes) that runs along a wall's side into that
/// wall. A side is the footprint's (mitres included), so a floor drawn round a corner of walls
/// is laid into both.
/// @param[in,out] slab  top absolute (with_absolute_heights)
/// @param[in] walls     the plan's wall frames
/// @param[in] tolerance the site's join tolerance
/// Cost O((n + e) log (n + e) + k) for n walls, e slab edges and k near pairs.
void lay_slab_edges_into_walls(Slab& slab, const std::vector<WallFrame>& walls, double tolerance);

}  // namespace roomcad::detail
