// SPDX-License-Identifier: GPL-3.0-or-later
// Making Sweet Home 3D's wall junctions meet roomcad's join rule (end points on a centre line).
//
// Sweet Home 3D joins walls by reference (wallAtStart/wallAtEnd) and draws a T-junction as a
// wall whose end sits anywhere inside the other wall; roomcad joins walls only where an end
// point lies on another wall's end point or centre line (within the site tolerance). These
// functions move end points so that the walls Sweet Home 3D shows joined are joined in the plan,
// without changing the union of the walls' footprints.
#pragma once

#include <vector>

#include "import/detail/sh3d_home.h"
#include "validation/report.h"

namespace roomcad::sh3d {

/// End points of walls on one level closer than `snap_distance` (metres) but not equal are made
/// equal: Sweet Home 3D keeps float32 centimetres and its users rely on magnetism, so ends that
/// are meant to meet differ by rounding or a fraction of a millimetre. Walls are visited in file
/// order, and an end takes the first earlier end near it. O(walls^2).
void snap_close_ends(std::vector<WallRecord>& walls, double snap_distance);

/// Each straight wall end, not shared with another wall's end, that lies strictly inside another
/// straight wall of its level (off its centre line, within half its thickness, or in the corner
/// block past one of its ends) is moved along its own wall onto that wall's centre line; if
/// that point is near the other wall's end (within half of either thickness), the end joins
/// that end instead (an L corner or a junction of three walls). The moved stretch lies inside the
/// other wall, so the union of the walls barely changes, and the junction becomes a T or a corner
/// that the plan format joins. The nearest centre line wins. A moved end that lands within
/// `snap_distance` of another wall's end takes that end.
/// @param[out] warnings appended: one `import_t_junction` warning listing the walls moved.
/// O(walls^2).
void join_t_ends(std::vector<WallRecord>& walls, double snap_distance, Report& warnings);

}  // namespace roomcad::sh3d
