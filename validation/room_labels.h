// SPDX-License-Identifier: GPL-3.0-or-later
// Which of the plan's room names (`rooms[]`) names each room found among its walls, and
// whether a person stays in it.
#pragma once

#include <string_view>
#include <vector>

#include "geometry/rooms.h"
#include "plan/plan.h"
#include "validation/rule_set.h"

namespace roomcad {

/// @return for each room, the first of `plan.rooms` on the room's level whose point lies inside
///         the room's clear outline, or nullptr (the room is unnamed). O(r * l * v) for r
///         rooms, l names and v corners.
[[nodiscard]] std::vector<const RoomLabel*> room_labels(const std::vector<Room>& rooms,
                                                        const Plan& plan);

/// @return whether a person stays in `room`, named `name` ("" unnamed), as
///         room_without_window judges it (HabitableRooms in validation/rule_set.h).
[[nodiscard]] bool is_habitable_room(const Room& room, std::string_view name,
                                     const HabitableRooms& rules);

}  // namespace roomcad
