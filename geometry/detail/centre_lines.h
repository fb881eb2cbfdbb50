// SPDX-License-Identifier: GPL-3.0-or-later
// The centre-line pieces rooms are found on (see rooms.cpp).
#pragma once

#include <cstddef>
#include <utility>
#include <vector>

#include "geometry/joins.h"
#include "plan/plan.h"

namespace roomcad::detail {

struct CentreLines {
  std::vector<std::pair<Point2, Point2>> segments;
  std::vector<std::size_t> walls;  ///< segment index -> wall index
};

/// @return the centre lines of the walls with finite ends, positive length and thickness.
/// When every join is exact end-to-end or end-on-wall, walls are split at the ends that
/// stand on them; otherwise the whole centre lines are given,
/// with mitred ends (closer than the tolerance) snapped to the lower-indexed wall's end.
/// O(n log n + k).
[[nodiscard]] CentreLines build_centre_lines(const Plan& plan, const Joins& joins);

}  // namespace roomcad::detail
