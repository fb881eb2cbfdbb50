// SPDX-License-Identifier: GPL-3.0-or-later
// escape_too_far: the longest walk from a point of a room to an exterior door, on the entrance
// storey (as room_unreachable). The walk is bounded from above and below (escape_walks.h); a
// room is reported when the upper bound is over the limit, conservatively: the message says
// whether the lower bound is over it too (certainly too far) or not (maybe too far). The fix
// adds a door to the outside in one of the room's walls, checked to bring the room's own
// upper bound within the limit.
#include <cmath>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "validation/detail/diagnostics.h"
#include "validation/rules/escape_walks.h"
#include "validation/rules/fix_search.h"
#include "validation/rules/room_sides.h"
#include "validation/rules/rules.h"

namespace roomcad::rules {
namespace {

constexpr double kCoarse = 1.0;  ///< sample spacing, metres, refined to kFine near the limit
constexpr double kFine = 0.25;
constexpr double kBeyond = 0.01;  ///< metres beyond a wall's far face where the outside is probed

/// @return true if every place of a door `width` wide in the side has one room beyond it, so
///         that no door there leads outside. O(outline of that room).
bool faces_one_room(const Plan& plan, const Storey& s, const RoomLocator& locator,
                    const RoomSide& side, double width) {
  const double lo = side.lo + 0.05 + width / 2, hi = side.hi - 0.05 - width / 2;  // as door_offsets
  if (hi < lo) return false;
  const Point2 a = beyond_side(plan, side, lo, kBeyond), b = beyond_side(plan, side, hi, kBeyond);
  const std::optional<std::size_t> room = locator.locate({(a.x + b.x) / 2, (a.y + b.y) / 2});
  return room && is_segment_inside_outline(s.rooms[*room].outline, a, b);
}

std::optional<FixEdit> exterior_door(const Context& cx, const Scene& scene, const Storey& s,
                                     const EscapeWalks& walks, std::size_t r, double limit) {
  const Plan& plan = scene.plan();
  const RoomLocator& locator = cx.locator(s);
  const double width = std::max(0.9, centimetres_up(cx.rules.thresholds.door_min_width));
  const std::string& id = cx.new_door_id;
  for (const RoomSide& side : room_sides(scene, s.rooms[r])) {
    if (faces_one_room(plan, s, locator, side, width)) continue;
    const Wall& w = plan.walls[side.wall];
    std::optional<Neighbourhood> near;  // built for the first place worth trying
    std::optional<std::size_t> beyond;  // the room beyond the last place tried
    for (const double offset : door_offsets(scene, side, width)) {
      // Not the outside: inside the room beyond the last place (checked first: the places
      // are a few centimetres apart), or inside any room.
      const Point2 p = beyond_side(plan, side, offset + width / 2, kBeyond);
      if (beyond && is_inside_outline(s.rooms[*beyond].outline, p)) continue;
      if ((beyond = locator.locate(p))) continue;
      const std::vector<Point2> exits =
          EscapeWalks::door_points(w, offset, offset + width, side.side);
      if (walks.walk_to(r, exits, w.thickness + 0.02, kFine) > limit) continue;
      std::vector<FixEdit> edits{add_door_edit(id, w.id, offset, width)};
      if (!near) near.emplace(scene, scene.wall_box(side.wall), heights_of(w));
      if (near->try_edits(edits)) return edits.front();
    }
  }
  return std::nullopt;
}

}  // namespace

void check_escape(const Context& cx, const Scene& scene, Report& report) {
  if (!cx.rules.is_enabled(Code::escape_too_far)) return;
  const Storey* s = cx.entrance_storey();
  if (!s) return;
  const double limit = cx.rules.thresholds.escape_max_distance;
  const EscapeWalks walks(scene, *s);
  for (std::size_t r = 0; r < s->rooms.size(); ++r) {
    std::optional<WalkBounds> b = walks.longest_walk(r, kCoarse);
    if (!b || b->upper <= limit) continue;
    if (b->lower <= limit) b = walks.longest_walk(r, kFine);
    if (b->upper <= limit) continue;
    const Room& room = s->rooms[r];
    const std::optional<FixEdit> door = exterior_door(cx, scene, *s, walks, r, limit);
    const std::string walk =
        b->lower > limit
            ? fmt::format("is between {} and {}, more than {}", detail::metres(b->lower),
                          detail::metres(b->upper), detail::metres(limit))
            : fmt::format("may be more than {}: roomcad bounds it between {} and {}",
                          detail::metres(limit), detail::metres(b->lower),
                          detail::metres(b->upper));
    report.add(make_finding(
        cx, Code::escape_too_far, room.walls,
        fmt::format("the longest walk from a point of {} ({:.2f} m², walls {}) to an exterior "
                    "door, from {}, {}.",
                    cx.room_name(*s, r), room.area, fmt::join(room.walls, ", "),
                    detail::point_text(b->farthest), walk),
        door ? fmt::format("add a door {} m wide to the outside in wall '{}' at offset {}",
                           door->fields[3].second, door->fields[1].second, door->fields[2].second)
             : "add an exterior door nearer to it: no wall of the room has room for one to the "
               "outside, clear "
               "of its openings, that brings the walk within the limit",
        door ? std::vector<FixEdit>{*door} : std::vector<FixEdit>{},
        Where{b->farthest, std::nullopt}));
  }
}

}  // namespace roomcad::rules
