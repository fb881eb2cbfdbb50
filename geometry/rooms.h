// SPDX-License-Identifier: GPL-3.0-or-later
// Rooms: the closed regions of the walls' centre-line arrangement, with their clear floor,
// bounding walls, doors and windows. Validation warns about them; floor plans label them.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "geometry/joins.h"
#include "plan/plan.h"

namespace roomcad {

/// A closed region of the wall arrangement (a room), as a simple polygon on the wall faces
/// that bound it, counter-clockwise, in metres.
struct Room {
  std::vector<Point2> outline;       ///< the clear floor: centre-line face moved inward
                                     ///< by each bounding wall's half-thickness
  double area = 0.0;                 ///< clear floor area, square metres (rooms nested
                                     ///< inside are subtracted by their centre-line area)
  std::string level;                 ///< the level of the walls bounding it ("": none)
  std::vector<std::string> walls;    ///< ids of the walls bounding it
  std::vector<std::string> doors;    ///< ids of doors in those walls
  std::vector<std::string> windows;  ///< ids of windows in those walls
};

/// Finds the rooms of a plan: bounded faces of the walls' centre-line arrangement, numbered
/// from the south-west. Meant for a plan that validates without errors; on any other it
/// skips walls that are not drawable and does not throw. A room's doors and windows are the
/// openings on the pieces of wall that bound it. O(n log n) in walls.
[[nodiscard]] std::vector<Room> find_rooms(const Plan& plan);

/// find_rooms with the plan's joins already found (validation finds them once for all checks).
/// @pre joins == find_joins(plan).
[[nodiscard]] std::vector<Room> find_rooms(const Plan& plan, const Joins& joins);

/// find_rooms on the walls of one level alone (`level` empty: the walls that name no level), so
/// that walls of different storeys never bound one room (a ground-floor wall and a roof wall
/// drawn over it make no room). @pre `level` is empty or names a level of the plan.
[[nodiscard]] std::vector<Room> find_rooms_on_level(const Plan& plan, std::string_view level);

/// The rooms of one level of a plan.
struct LevelRooms {
  std::string level;        ///< the level's id; empty: the walls that name no level
  std::vector<Room> rooms;  ///< find_rooms_on_level
};

/// Rooms level by level: the walls that name no level first (if any, or if the plan has no
/// levels), then each level in the plan's order. O(levels * n log n) for n walls.
[[nodiscard]] std::vector<LevelRooms> find_rooms_by_level(const Plan& plan);

}  // namespace roomcad
