// SPDX-License-Identifier: GPL-3.0-or-later
// Which stretch of which wall bounds a room, and where a new door could go in it: what the
// room rules' fixes need beyond find_rooms' outline. Plain header.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "plan/plan.h"
#include "validation/report.h"
#include "validation/rules/context.h"
#include "validation/rules/scene.h"

namespace roomcad::rules {

/// A stretch of wall `wall` that a room's clear outline runs along, as the range [lo, hi] of
/// distances from the wall's `from`, on its left (side +1) or right (side -1) face.
struct RoomSide {
  std::size_t wall = 0;
  int side = 1;
  double lo = 0.0;
  double hi = 0.0;
};

/// @return the stretches of the room's walls along its outline, in outline order.
///         O(outline * walls of the room).
[[nodiscard]] std::vector<RoomSide> room_sides(const Scene& scene, const Room& room);

/// @return the point `across` metres beyond the face of a room side, at `along` on its wall
///         (positive: away from the room).
[[nodiscard]] Point2 beyond_side(const Plan& plan, const RoomSide& s, double along, double across);

/// A place for a new door of `width` in a room side: offsets along the wall on a 5 cm grid,
/// the middle of the stretch first, at least 5 cm from its ends, and clear of the wall's
/// openings (in doubles: a fix is then verified on the neighbourhood). O(places * openings
/// of the wall).
[[nodiscard]] std::vector<double> door_offsets(const Scene& scene, const RoomSide& s, double width);

/// @return an add edit for a door `id` in wall `wall` at `offset`, `width` wide.
[[nodiscard]] FixEdit add_door_edit(const std::string& id, const std::string& wall, double offset,
                                    double width);

}  // namespace roomcad::rules
