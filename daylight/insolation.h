// SPDX-License-Identifier: GPL-3.0-or-later
// Direct sun, room by room: for one day at the plan's site, when the sun reaches each window's
// calculation point (docs/plan-format.md, "Sun and sunlight"), its longest continuous period
// and its total, and each room's best window.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "core/error.h"
#include "daylight/site_time.h"
#include "mesh/solid_mesh.h"
#include "plan/plan.h"

namespace roomcad {

struct InsolationOptions {
  /// Where a window's calculation point is, from the format's (the middle of the window's
  /// width, on its wall's face on the room's side, at the sill): a rules file may move it.
  double above_sill = 0.0;     ///< metres up from the sill
  double into_reveal = 0.0;    ///< metres from the room-side face towards the outside
  double scan_seconds = 60.0;  ///< the scan's step; every change of sun is then bisected
  int threads = 0;             ///< 0: all cores; the result is the same at any count
  /// Only these windows' sun is computed (the others are listed without intervals); empty:
  /// every window. What checking a fix needs.
  std::vector<std::string> only_windows{};
};

/// A span of direct sun, UTC seconds.
using SunInterval = std::pair<UtcSeconds, UtcSeconds>;

/// One window of a room, and its sun that day.
struct WindowSun {
  std::string id;
  Vec3 point;                          ///< its calculation point, metres
  std::vector<SunInterval> intervals;  ///< in time order, disjoint
  double continuous_hours = 0.0;       ///< the longest interval
  double total_hours = 0.0;            ///< the sum of the intervals
};

/// A room (a closed region of one level's walls) with the windows in its walls.
struct RoomSun {
  std::string room;   ///< its name's id in `rooms[]`, or "room-N" (N from 1, level by level)
  std::string name;   ///< its name in `rooms[]`, or ""
  std::string level;  ///< its level's id, or ""
  double area = 0.0;  ///< clear floor, square metres
  std::vector<Point2> outline;     ///< its clear floor (for messages and drawings)
  std::vector<std::string> walls;  ///< ids of the walls bounding it (Room::walls)
  std::vector<WindowSun> windows;  ///< in the order of the room's walls
  std::string best_window;         ///< largest continuous, then total ("" without windows)
  double continuous_hours = 0.0;   ///< its best window's
  double total_hours = 0.0;        ///< its best window's
};

struct InsolationDay {
  CivilDay date = 0;
  GeoLocation place;
  std::vector<RoomSun> rooms;  ///< level by level, as find_rooms_by_level numbers them
};

/// Computes the direct sun of every room's windows on `date` (local, at the place's offset).
/// The sun reaches a point when its elevation is above 0 and the ray towards it passes
/// through no triangle of `solid` (the plan's built walls and slabs) or of the obstructions
/// (SunBlockers). The day is scanned every `scan_seconds` and each change between two
/// samples bisected to under half a second, so the ends are right to the second; a flash of
/// sun shorter than the step can be missed.
/// @pre `solid` is build_model(plan).walls.
/// @throws PreconditionError without plan.site.location.
/// Cost: about 1,440 sun positions plus windows x daylight samples ray casts, O(log t) each,
/// spread over `threads`.
[[nodiscard]] InsolationDay insolation(const Plan& plan, const SolidMesh& solid, CivilDay date,
                                       const InsolationOptions& options = {});

}  // namespace roomcad
