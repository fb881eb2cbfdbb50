// SPDX-License-Identifier: GPL-3.0-or-later
// room_unreachable: the graph of rooms and doors (a door joins the rooms on its two sides,
// or a room and the outside) searched from the outside; regions under 0.5 m² are gaps, not
// rooms, and are not reported. Rooms are find_rooms' rooms of the
// entrance storey: the lowest storey with a door to the outside (the lowest storey if none
// has one). Other storeys are reached by stairs, which version 1 plans cannot hold, so they
// are not judged.
#include <algorithm>
#include <deque>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "validation/rules/fix_search.h"
#include "validation/rules/room_sides.h"
#include "validation/rules/rules.h"

namespace roomcad::rules {
namespace {

constexpr double kProbe = 0.01;  // as the door sides in context.cpp

/// The rooms and doors of a storey; node `rooms.size()` is the outside.
struct RoomGraph {
  std::size_t outside = 0;
  std::vector<std::vector<std::pair<std::size_t, std::size_t>>> links;  ///< node -> (door, node)

  explicit RoomGraph(const Storey& s) : outside(s.rooms.size()), links(s.rooms.size() + 1) {
    for (std::size_t d = 0; d < s.doors.size(); ++d) {
      const std::size_t a = s.door_rooms[d][0].value_or(outside),
                        b = s.door_rooms[d][1].value_or(outside);
      if (a == b) continue;
      links[a].emplace_back(s.doors[d], b);
      links[b].emplace_back(s.doors[d], a);
    }
  }

  /// @return the nodes reached from `start` through links to nodes `allowed` lets in.
  template <class Allowed>
  std::vector<std::size_t> reach(std::size_t start, Allowed allowed) const {
    std::vector<bool> seen(links.size(), false);
    std::vector<std::size_t> order{start};
    seen[start] = true;
    for (std::size_t k = 0; k < order.size(); ++k)
      for (const auto& [door, next] : links[order[k]])
        if (!seen[next] && allowed(next)) seen[next] = true, order.push_back(next);
    return order;
  }
};

/// A door from the component into a reached room or the outside, tried on the neighbourhood.
std::optional<FixEdit> connecting_door(const Context& cx, const Scene& scene, const Storey& s,
                                       const std::vector<std::size_t>& component,
                                       const std::vector<bool>& reached) {
  const Plan& plan = scene.plan();
  const RoomLocator& locator = cx.locator(s);
  const double width = std::max(0.9, centimetres_up(cx.rules.thresholds.door_min_width));
  const std::string& id = cx.new_door_id;
  for (const std::size_t r : component)
    for (const RoomSide& side : room_sides(scene, s.rooms[r])) {
      std::optional<Neighbourhood> near;  // built for the first place worth trying
      for (const double offset : door_offsets(scene, side, width)) {
        const std::optional<std::size_t> other =
            locator.locate(beyond_side(plan, side, offset + width / 2, kProbe));
        if (other && !reached[*other]) continue;
        std::vector<FixEdit> edits{add_door_edit(id, plan.walls[side.wall].id, offset, width)};
        if (!near)
          near.emplace(scene, scene.wall_box(side.wall), heights_of(plan.walls[side.wall]));
        if (near->try_edits(edits)) return edits.front();
      }
    }
  return std::nullopt;
}

std::string room_list(const Context& cx, const Storey& s, const std::vector<std::size_t>& rooms) {
  std::vector<std::string> names;
  for (const std::size_t r : rooms) names.push_back(std::to_string(r + 1));
  return (rooms.size() == 1 ? cx.room_name(s, rooms[0])
                            : "rooms " + fmt::format("{}", fmt::join(names, ", ")));
}

void report_component(const Context& cx, const Scene& scene, const Storey& s,
                      const RoomGraph& graph, std::vector<std::size_t> component,
                      const std::vector<bool>& reached, Report& report) {
  std::sort(component.begin(), component.end());
  std::vector<std::string> doors;
  for (const std::size_t r : component)
    for (const auto& [door, next] : graph.links[r]) doors.push_back(scene.plan().openings[door].id);
  std::sort(doors.begin(), doors.end());
  doors.erase(std::unique(doors.begin(), doors.end()), doors.end());
  const std::optional<FixEdit> door = connecting_door(cx, scene, s, component, reached);
  const std::string fix =
      door ? fmt::format("add a door {} m wide to wall '{}' at offset {}", door->fields[3].second,
                         door->fields[1].second, door->fields[2].second)
           : "no wall of these rooms has room, clear of its openings, for a door to the "
             "outside or to a room that can be reached: move an opening or a wall to make one";
  const std::string how =
      doors.empty() ? "it has no door"
      : component.size() == 1
          ? fmt::format("its doors ({}) lead to no room that can be", fmt::join(doors, ", "))
          : fmt::format("{} are joined by doors {}, but none of them leads to a room that can be",
                        room_list(cx, s, component), fmt::join(doors, ", "));
  for (const std::size_t r : component) {
    const Room& room = s.rooms[r];
    report.add(make_finding(
        cx, Code::room_unreachable, room.walls,
        fmt::format("{} ({:.2f} m², walls {}) cannot be reached from outside through doors: {}.",
                    cx.room_name(s, r), room.area, fmt::join(room.walls, ", "), how),
        fix, door ? std::vector<FixEdit>{*door} : std::vector<FixEdit>{}, room_where(room)));
  }
}

}  // namespace

void check_reachability(const Context& cx, const Scene& scene, Report& report) {
  if (!cx.rules.is_enabled(Code::room_unreachable)) return;
  const Storey* s = cx.entrance_storey();
  if (!s) return;
  const RoomGraph graph(*s);
  std::vector<bool> reached(graph.links.size(), false);
  for (const std::size_t n : graph.reach(graph.outside, [](std::size_t) { return true; }))
    reached[n] = true;
  std::vector<bool> reported(s->rooms.size(), false);
  for (std::size_t r = 0; r < s->rooms.size(); ++r) {
    if (reached[r] || reported[r] || s->rooms[r].area < kMinRoomArea) continue;
    const std::vector<std::size_t> component =
        graph.reach(r, [&](std::size_t n) { return n != graph.outside; });
    for (const std::size_t n : component) reported[n] = true;
    report_component(cx, scene, *s, graph, component, reached, report);
  }
}

}  // namespace roomcad::rules
