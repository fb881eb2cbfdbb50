// SPDX-License-Identifier: GPL-3.0-or-later
// What the rules share: the usable walls and openings, the storeys with their rooms (found by
// find_rooms), which room lies on each side of each door, and which rooms are accessible.
// Plain header (no CGAL).
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "geometry/box_grid.h"
#include "geometry/joins.h"
#include "plan/plan.h"
#include "validation/detail/checks.h"
#include "validation/rule_set.h"
#include "validation/validate.h"

namespace roomcad::rules {

/// Height above a storey's floor that walking needs: walls meeting this band are obstacles
/// to people, and bound the storey's rooms.
inline constexpr double kHeadroom = 2.0;
/// m² of clear floor: a smaller closed region is a gap between walls (as drawing tools leave
/// them: walls drawn a hair apart), not a room anyone goes into; the room rules report none,
/// though it may join rooms they report.
inline constexpr double kMinRoomArea = 0.5;

/// The rooms on one floor. A storey's floor is the base of some wall; its walls are the
/// usable walls whose height range meets (floor, floor + kHeadroom). Version 1 plans have no
/// levels: walls standing on a higher base (upper storeys, as importers write them) make
/// storeys of their own, so rooms of different floors are not mixed.
struct Storey {
  double floor = 0.0;
  bool lowest = false;             ///< the lowest storey: the one exterior doors lead out of
  std::vector<std::size_t> walls;  ///< indices into Plan::walls
  std::vector<Room> rooms;         ///< find_rooms on those walls, numbered from 1 in order
  std::vector<bool> accessible;    ///< per room: the accessibility rules apply to it
  std::vector<std::size_t> doors;  ///< indices into Plan::openings, doors in those walls
  /// Per door (same order): the room on its wall's right side [0] and left side [1] (seen
  /// from the wall's `from` to its `to`), or nullopt for outside (no room).
  std::vector<std::array<std::optional<std::size_t>, 2>> door_rooms;
};

/// Finds the room a point lies in: the innermost room whose clear outline contains it.
class RoomLocator {
 public:
  explicit RoomLocator(const std::vector<Room>& rooms);  ///< O(m) for m rooms
  /// @return the room's index, or nullopt (outside every room). O(rooms near p).
  [[nodiscard]] std::optional<std::size_t> locate(Point2 p) const;

 private:
  const std::vector<Room>& rooms_;
  std::vector<double> areas_;  ///< by room: the area of its box (the innermost is the smallest)
  BoxGrid grid_;
};

class Context {
 public:
  /// @param[in] whole_rooms  find_rooms of the whole plan if already found, reused for a
  ///                         storey that holds every wall (nullptr: found here)
  /// Cost: O(n log n) per storey (find_rooms) plus O(n log n) for the door sides.
  Context(const Plan& plan, const Joins& joins, const detail::Usable& usable, const RuleSet& rules,
          const std::vector<Room>* whole_rooms);
  Context(const Context&) = delete;  // the locators refer to the storeys' rooms
  Context& operator=(const Context&) = delete;

  const Plan& plan;
  const Joins& joins;
  const RuleSet& rules;
  std::vector<bool> wall_usable;                 ///< by wall
  std::vector<std::optional<std::size_t>> host;  ///< by opening: its usable host wall
  std::vector<Storey> storeys;                   ///< by rising floor
  /// By opening: a door the accessibility rules apply to: every door when the rule set names
  /// no accessible rooms, else the doors with a named room on a side (in some storey).
  std::vector<bool> accessible_door;
  /// An id no object of the plan has, for the door a fix adds ("door-1").
  std::string new_door_id;

  /// @return the storey people enter: the lowest with a door to the outside (the lowest if
  ///         none has one), or nullptr for a plan without walls.
  [[nodiscard]] const Storey* entrance_storey() const;
  /// @return the severity the rule set gives `code`.
  [[nodiscard]] Severity severity(Code code) const;
  /// @return "room 3" (with " on the floor at z = 2.50 m" when the plan has several storeys).
  [[nodiscard]] std::string room_name(const Storey& storey, std::size_t room) const;
  /// @return the locator of the rooms of `storey` (one of `storeys`), built once. O(1).
  [[nodiscard]] const RoomLocator& locator(const Storey& storey) const;

 private:
  std::vector<RoomLocator> locators_;  ///< by storey
};

/// @return RoomLocator(rooms).locate(p) for each point. O(n + m) for n points and m rooms.
[[nodiscard]] std::vector<std::optional<std::size_t>> locate_rooms(
    const std::vector<Room>& rooms, const std::vector<Point2>& points);

/// @return true if p lies inside the polygon (crossing number, doubles: for points well
///         inside or outside, such as door sides 1 cm off a wall face). O(n).
[[nodiscard]] bool is_inside_outline(const std::vector<Point2>& outline, Point2 p);

/// @return true if the segment a-b lies inside the polygon: its ends and middle inside, and no
///         edge crossed properly (doubles, as is_inside_outline). O(n).
[[nodiscard]] bool is_segment_inside_outline(const std::vector<Point2>& outline, Point2 a,
                                             Point2 b);

/// @return the bounding box of a room's clear outline (index 0).
[[nodiscard]] Box2 room_box(const Room& room);

/// @return the walls of `plan` whose height range meets (floor, floor + kHeadroom) in the
///         written numbers, among `candidates`.
[[nodiscard]] std::vector<std::size_t> walls_at_floor(const Plan& plan,
                                                      const std::vector<std::size_t>& candidates,
                                                      double floor);

/// @return the storeys of the usable walls (by wall), without rooms yet: one per distinct
///         base, but a base whose walls are those of the base below (a wall on a plinth) adds
///         none. O(n * storeys).
[[nodiscard]] std::vector<Storey> find_storeys(const Plan& plan, const std::vector<bool>& usable);

/// @return a copy of `plan` with only `walls` (indices) and the openings they host, for
///         find_rooms on one storey or near one place.
[[nodiscard]] Plan plan_with_walls(const Plan& plan, const std::vector<std::size_t>& walls);

}  // namespace roomcad::rules
