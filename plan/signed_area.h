// SPDX-License-Identifier: GPL-3.0-or-later
// The signed area of a plan polygon, for orientation and floor areas (rooms, imported profiles).
#pragma once

#include "plan/plan.h"

namespace roomcad {

/// @param[in] polygon  vertices in metres, the last joined to the first
/// @return the area in square metres: positive counter-clockwise, negative clockwise, 0 for
///         fewer than 3 points. Shoelace formula in doubles (not exact). O(n).
[[nodiscard]] double signed_area(const Polygon& polygon);

}  // namespace roomcad
