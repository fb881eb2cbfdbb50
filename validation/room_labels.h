// SPDX-License-Identifier: GPL-3.0-or-later
// Which of the plan's room names (`rooms[]`) names each room found among its walls.
#pragma once

#include <vector>

#include "geometry/rooms.h"
#include "plan/plan.h"

namespace roomcad {

/// @return for each room, the first of `plan.rooms` on the room's level whose point lies inside
///         the room's clear outline, or nullptr (the room is unnamed). O(r * l * v) for r
///         rooms, l names and v corners.
[[nodiscard]] std::vector<const RoomLabel*> room_labels(const std::vector<Room>& rooms,
                                                        const Plan& plan);

}  // namespace roomcad
