// SPDX-License-Identifier: GPL-3.0-or-later
// Which rooms a person stays in: the rooms room_without_window asks a window of. Halls,
// corridors, closets, stores, baths and WCs are not asked; the plan says which a room is by
// naming it (`rooms[]`), and otherwise its size and shape do.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "geometry/rooms.h"
#include "plan/plan.h"
#include "validation/rule_set.h"

namespace roomcad::detail {

/// @return `text` with ASCII letters in lower case (other bytes, UTF-8 included, kept). O(n).
[[nodiscard]] std::string lower_case(std::string_view text);

/// @return whether a person stays in `room`: named, unless a word of its name (letters and
///         digits, compared in lower case, a final "s" dropped too) is in
///         `rules.not_habitable`; unnamed, unless its clear area is under `rules.min_area` or
///         it is a corridor: at most `rules.corridor_width` wide across the direction of one
///         of its sides, and three times as long along it. O(v^2) for v corners.
[[nodiscard]] bool is_habitable(const Room& room, std::string_view name,
                                const HabitableRooms& rules);

}  // namespace roomcad::detail
