// SPDX-License-Identifier: GPL-3.0-or-later
// no_turning_circle: an accessible room with a door must hold a free circle of the turning
// diameter (free_disc.h decides it). The fix moves one of the room's walls outward, with the
// ends of the walls that meet it, by what the room lacks, or two walls across each other when
// one is not enough; it is tried on the neighbourhood (the room found again there must hold
// the circle, and no error may appear).
#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "validation/detail/diagnostics.h"
#include "validation/rules/fix_search.h"
#include "validation/rules/free_disc.h"
#include "validation/rules/room_sides.h"
#include "validation/rules/rules.h"

namespace roomcad::rules {
namespace {

/// @return a point inside the room's outline (the centroid, or a corner's inner triangle).
std::optional<Point2> interior_point(const Room& room) {
  const std::vector<Point2>& o = room.outline;
  const std::size_t n = o.size();
  double a2 = 0, cx = 0, cy = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const double w = o[k].x * o[(k + 1) % n].y - o[k].y * o[(k + 1) % n].x;
    a2 += w, cx += (o[k].x + o[(k + 1) % n].x) * w, cy += (o[k].y + o[(k + 1) % n].y) * w;
  }
  if (a2 != 0 && is_inside_outline(o, {cx / (3 * a2), cy / (3 * a2)}))
    return Point2{cx / (3 * a2), cy / (3 * a2)};
  for (std::size_t k = 0; k < n; ++k) {
    const Point2 p{(o[k].x + o[(k + 1) % n].x + o[(k + 2) % n].x) / 3,
                   (o[k].y + o[(k + 1) % n].y + o[(k + 2) % n].y) / 3};
    if (is_inside_outline(o, p)) return p;
  }
  return std::nullopt;
}

/// @return true if, in the edited neighbourhood, the room holding `inside` holds the circle.
bool holds_circle(const Plan& edited, double floor, Point2 inside, double diameter) {
  const Scene scene(edited);
  std::vector<std::size_t> all;
  for (std::size_t w = 0; w < edited.walls.size(); ++w)
    if (scene.is_usable(w)) all.push_back(w);
  const std::vector<std::size_t> walls = walls_at_floor(edited, all, floor);
  const std::vector<Room> rooms = find_rooms(plan_with_walls(edited, walls));
  const RoomLocator locator(rooms);
  const std::optional<std::size_t> room = locator.locate(inside);
  return room && find_free_disc(StoreyWalls(scene, walls), rooms, locator, *room, diameter).fits;
}

struct WallMove {
  std::string text;
  std::vector<FixEdit> edits;
};

/// A wall of the room moved `step` metres away from it, with the ends that meet it.
struct SideMove {
  std::size_t wall;
  Point2 by;
};

/// @return the walls of the room, each once, with the move that takes it away from the room.
std::vector<SideMove> side_moves(const Scene& scene, const Room& room, double step) {
  std::vector<SideMove> out;
  for (const RoomSide& side : room_sides(scene, room)) {
    if (std::any_of(out.begin(), out.end(), [&](const SideMove& m) { return m.wall == side.wall; }))
      continue;
    const Wall& w = scene.plan().walls[side.wall];
    const double length = std::hypot(w.to.x - w.from.x, w.to.y - w.from.y);
    out.push_back({side.wall,
                   {side.side * (w.to.y - w.from.y) / length * step,
                    -side.side * (w.to.x - w.from.x) / length * step}});
  }
  return out;
}

std::string move_words(const Scene& scene, const SideMove& m, const std::vector<FixEdit>& edits,
                       double step) {
  std::string text =
      fmt::format("move wall '{}' {} {} (away from the room)", scene.plan().walls[m.wall].id,
                  detail::metres(step), detail::direction_text({m.by.x / step, m.by.y / step}));
  if (edits.size() > 1) {
    std::vector<std::string> ends;
    for (std::size_t k = 1; k < edits.size(); ++k) ends.push_back("'" + edits[k].id + "'");
    text += fmt::format(", with the ends of {} that meet it", fmt::join(ends, ", "));
  }
  return text;
}

/// One wall moved out, or failing that two walls across each other (a room short both ways):
/// the second move is made on the plan with the first one applied.
std::optional<WallMove> widen_room(const Scene& scene, const Storey& s, const Room& room,
                                   double lacking, double diameter) {
  const std::optional<Point2> inside = interior_point(room);
  if (!inside) return std::nullopt;
  const double step = centimetres_up(lacking + 0.01);
  const Neighbourhood near(scene, grown(room_box(room), step + 2.0),
                           heights_of(scene.plan(), s.walls));
  const std::vector<SideMove> moves = side_moves(scene, room, step);
  for (const SideMove& m : moves) {
    std::vector<FixEdit> edits = move_wall_edits(scene, m.wall, m.by);
    const std::optional<Plan> edited = near.try_edits(edits);
    if (edited && holds_circle(*edited, s.floor, *inside, diameter))
      return WallMove{move_words(scene, m, edits, step), std::move(edits)};
  }
  for (std::size_t i = 0; i < moves.size(); ++i) {
    const std::vector<FixEdit> first = move_wall_edits(scene, moves[i].wall, moves[i].by);
    const std::optional<Plan> once = near.try_edits(first);
    if (!once) continue;
    const Scene moved(*once);
    for (std::size_t j = i + 1; j < moves.size(); ++j) {
      const SideMove& m = moves[j];
      if (std::fabs(moves[i].by.x * m.by.y - moves[i].by.y * m.by.x) < 1e-9 * step * step)
        continue;  // parallel
      const std::optional<std::size_t> wall = moved.wall_named(scene.plan().walls[m.wall].id);
      if (!wall) continue;
      std::vector<FixEdit> edits = first;
      const std::vector<FixEdit> second = move_wall_edits(moved, *wall, m.by);
      edits.insert(edits.end(), second.begin(), second.end());
      const std::optional<Plan> twice = near.try_edits(edits);
      if (twice && holds_circle(*twice, s.floor, *inside, diameter))
        return WallMove{move_words(scene, moves[i], first, step) + "; and " +
                            move_words(moved, {*wall, m.by}, second, step),
                        std::move(edits)};
    }
  }
  return std::nullopt;
}

}  // namespace

void check_turning_circles(const Context& cx, const Scene& scene, Report& report) {
  if (!cx.rules.is_enabled(Code::no_turning_circle)) return;
  const double diameter = cx.rules.thresholds.turning_diameter;
  for (const Storey& s : cx.storeys) {
    const StoreyWalls walls(scene, s.walls);
    const RoomLocator locator(s.rooms);
    for (std::size_t r = 0; r < s.rooms.size(); ++r) {
      const Room& room = s.rooms[r];
      if (!s.accessible[r] || room.doors.empty() || room.area < kMinRoomArea) continue;
      if (find_free_disc(walls, s.rooms, locator, r, diameter).fits) continue;
      const double largest = largest_free_diameter(walls, s.rooms, locator, r, diameter);
      const std::optional<WallMove> move = widen_room(scene, s, room, diameter - largest, diameter);
      report.add(make_finding(
          cx, Code::no_turning_circle, room.walls,
          fmt::format(
              "{} ({:.2f} m², walls {}) has no free circle {} across to turn a wheelchair in: the "
              "largest is about {}.",
              cx.room_name(s, r), room.area, fmt::join(room.walls, ", "), detail::metres(diameter),
              detail::metres(largest)),
          move ? move->text
               : "enlarge the room: no wall of it, or two, can move outward far enough",
          move ? move->edits : std::vector<FixEdit>{}, room_where(room)));
    }
  }
}

}  // namespace roomcad::rules
