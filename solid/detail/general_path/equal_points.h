// SPDX-License-Identifier: GPL-3.0-or-later
// Equal points of one plane given one index, so that the plane's boolean (plane_faces.h) links
// its pieces at shared corners however each corner was made.
#pragma once

#include <cstddef>
#include <vector>

#include "solid/detail/general_path/exact_planes.h"

namespace roomcad::detail {

/// Gives equal points one index: @return per point index its representative's, the first of
/// its equals in order of their low bounds on the first view axis (then index). Points are
/// tested exactly where their bounds share a cell of a fine grid (2^-24 of the largest
/// coordinate: far wider than a point's bounds, far narrower than a plan's features), and
/// points whose bounds are wider than two cells (corners of nearly parallel planes) against
/// all. O(n) expected hashing plus the exact tests of near points (most are repeats of one
/// representation, decided without arithmetic).
/// @param[in] i, j  the plane's two view axes (dominant_axis dropped)
[[nodiscard]] std::vector<std::size_t> find_equal_points(PointCache& points, int i, int j);

}  // namespace roomcad::detail
