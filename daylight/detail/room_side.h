// SPDX-License-Identifier: GPL-3.0-or-later
// Which side of a wall a room is on: where a window's calculation point lies, and which way a
// wall faces out of its room.
#pragma once

#include <vector>

#include "plan/plan.h"

namespace roomcad::daylight_detail {

/// @return +1 when the room (its clear outline) lies to the left of a wall running along the
///         unit direction `u` through `at` (left: `u` turned counter-clockwise), else -1: the
///         side whose point just past the wall's face (half_thickness + 1 cm, or twice the
///         half thickness for a thinner wall) is inside the outline. O(corners).
[[nodiscard]] double room_side(const std::vector<Point2>& outline, Point2 at, Point2 u,
                               double half_thickness);

}  // namespace roomcad::daylight_detail
