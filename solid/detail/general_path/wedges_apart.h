// SPDX-License-Identifier: GPL-3.0-or-later
// Where two wedges of solid meet along a line of a plane only (the plane's 2D boolean and its
// grid both ask): then a face across that line must end there.
#pragma once

#include "solid/detail/general_path/exact_planes.h"

namespace roomcad::detail {

/// Whether two solids just below `plane` (`below`; else just above), either side of a line L
/// of it, touch only along L: each is a wedge between the plane and its own plane through L,
/// and the two wedges leave a gap between them. The plane's face then
/// ends at L on both sides, as the faces of the wedges' other sides do; a face running on
/// across L would be crossed by them by an ulp once its corners are rounded (walls leaving one
/// point a few degrees apart, a window at their ends). Why the signs: in the cross-section
/// of L (u from m0's side to m1's, v away from the solids, l = u x v), the wedges leave a gap
/// exactly when m0 x m1 points against l. Both m0 x m1 and m0 x plane run along L, and
/// m0 x plane points along l below, against it above; so det(m0, m1, across) and
/// det(m0, plane, across), each the dot product of one with `across`, agree in sign below
/// (disagree above) exactly when m0 x m1 points along l. Equal planes (m1 = -m0: the solids
/// share a face) leave none. Exact, O(1).
/// @param[in] m0      through L, the first solid on its negative side
/// @param[in] m1      through L, the second solid on its negative side (m0's positive side)
/// @param[in] across  a plane crossing L
[[nodiscard]] bool wedges_apart(const PlaneSet& set, PlaneRef plane, PlaneRef m0, PlaneRef m1,
                                PlaneRef across, bool below);

}  // namespace roomcad::detail
