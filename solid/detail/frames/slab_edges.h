// SPDX-License-Identifier: GPL-3.0-or-later
// Slabs laid into the walls that bound them (docs/plan-format.md, "Slabs and walls").
//
// People draw a floor up to a wall's face: its edge lies on the wall's face only within
// rounding (a side is centre line +- thickness / 2, which doubles rarely hold), so slab and
// wall would meet along a sliver, an edge or a point, and the solid would not be 2-manifold.
// A slab edge that runs along a face of a wall's footprint (a side or an end), within the
// site's join tolerance, is moved a quarter of the wall's thickness into the wall. Where the
// wall stands over the slab's whole height, what the slab gains there lies inside the wall,
// so the solid (their union) is the same, only without the sliver. Where the wall stands on
// the slab or hangs under it (or covers part of its height), the two would share a bare edge;
// a slab beside the wall is then laid under it, and the solid gains that strip. An edge
// longer than the face moves whole: the strip beyond the face is gained too.
#pragma once

#include <vector>

#include "plan/plan.h"
#include "solid/detail/frames/wall_frame.h"

namespace roomcad::detail {

/// Lays every edge of the slab (outline and holes) that runs along a face of a wall into that
/// wall. A face is the footprint's (mitres included), so a floor drawn round a corner of walls
/// is laid into both.
/// @param[in,out] slab  top absolute (with_absolute_heights)
/// @param[in] walls     the plan's wall frames
/// @param[in] boxes     wall_boxes_for_laying(walls, tolerance), made once for every slab
/// @param[in] tolerance the site's join tolerance
/// Cost O((n + e) log (n + e) + k) for n walls, e slab edges and k near pairs.
void lay_slab_edges_into_walls(Slab& slab, const std::vector<WallFrame>& walls,
                               const std::vector<Box2>& boxes, double tolerance);

/// @return the walls' footprint boxes grown by `tolerance`, tagged with their index in
///         `walls`; a wall whose footprint is a bow tie (no inside to lay into) has none. O(n).
[[nodiscard]] std::vector<Box2> wall_boxes_for_laying(const std::vector<WallFrame>& walls,
                                                      double tolerance);

}  // namespace roomcad::detail
