// SPDX-License-Identifier: GPL-3.0-or-later
// find_rooms: rooms are the bounded faces of the walls' centre-line arrangement.
//
// The reported outline and area are the CLEAR floor inside the walls (what an architect
// quotes): each side of the face is moved inward by its wall's half-thickness and
// consecutive sides are intersected. A nested region (a room within a room) is subtracted
// by its centre-line area. Mitred ends closer than the tolerance are snapped together first
// so that such a corner still closes its room; an end that stops short of a centre line
// within the tolerance (a T with a micrometre gap) leaves the room open, and it is not
// reported (no false warnings).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string_view>
#include <tuple>

#include "geometry/detail/arrangement.h"
#include "geometry/detail/centre_lines.h"
#include "geometry/joins.h"
#include "geometry/rooms.h"
#include "plan/plan_levels.h"
#include "plan/plan_objects.h"
#include "plan/signed_area.h"

namespace roomcad {
namespace {

struct Line {
  Point2 p;  ///< a point on the offset side line
  Point2 d;  ///< its direction
};

Line inner_line(const detail::FaceEdge& e, double half) {
  const Point2 d{e.target.x - e.source.x, e.target.y - e.source.y};
  const double len = std::hypot(d.x, d.y);
  return {{e.source.x - d.y / len * half, e.source.y + d.x / len * half}, d};
}

/// How far a clear-floor corner may lie from its centre-line corner, in the larger of the two
/// walls' half-thicknesses: a corner of 11.5 degrees reaches 10. Sides nearly in line (walls
/// drawn with a kink of a hundredth of a degree, of different thicknesses) would meet a
/// kilometre away; they are joined by a step across, as sides exactly in line are.
constexpr double kCornerReach = 10.0;

/// @return the foot of the perpendicular from `at` on line a.
Point2 foot_on(const Line& a, Point2 at) {
  const double t =
      ((at.x - a.p.x) * a.d.x + (at.y - a.p.y) * a.d.y) / (a.d.x * a.d.x + a.d.y * a.d.y);
  return {a.p.x + t * a.d.x, a.p.y + t * a.d.y};
}

/// Adds the clear-floor corner(s) between consecutive inner side lines a then b, which turn
/// at centre-line corner `at`.
void add_corner(const Line& a, const Line& b, Point2 at, std::vector<Point2>& out) {
  const Point2 on_a = foot_on(a, at), on_b = foot_on(b, at);
  const double reach = kCornerReach * std::max(std::hypot(on_a.x - at.x, on_a.y - at.y),
                                               std::hypot(on_b.x - at.x, on_b.y - at.y));
  const double denom = a.d.x * b.d.y - a.d.y * b.d.x;
  if (denom != 0.0) {
    const double s = ((b.p.x - a.p.x) * b.d.y - (b.p.y - a.p.y) * b.d.x) / denom;
    const Point2 corner{a.p.x + s * a.d.x, a.p.y + s * a.d.y};
    if (std::hypot(corner.x - at.x, corner.y - at.y) <= reach) {
      out.push_back(corner);
      return;
    }
  }
  // In line (or nearly), or the tip of a wall end poking into the room: a step across.
  out.push_back(on_a);
  if (on_b != out.back()) out.push_back(on_b);
}

/// Openings whose span along their wall overlaps the face edge's piece of that wall.
void collect_openings(const Plan& plan, const OpeningsByWall& by_wall, const detail::FaceEdge& e,
                      Room& room) {
  const Wall& w = plan.walls[e.wall];
  const Point2 d{w.to.x - w.from.x, w.to.y - w.from.y};
  const double len = std::hypot(d.x, d.y);
  const auto along = [&](Point2 p) {
    return ((p.x - w.from.x) * d.x + (p.y - w.from.y) * d.y) / len;
  };
  const double lo = std::min(along(e.source), along(e.target));
  const double hi = std::max(along(e.source), along(e.target));
  for (const std::size_t i : by_wall[e.wall]) {
    const Opening& o = plan.openings[i];
    if (std::max(lo, o.offset) >= std::min(hi, o.offset + o.width)) continue;
    (o.type == OpeningType::door ? room.doors : room.windows).push_back(o.id);
  }
}

void sort_unique(std::vector<std::string>& ids) {
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
}

Room room_of(const Plan& plan, const OpeningsByWall& by_wall, const detail::Face& face) {
  Room room;
  std::vector<Line> lines;
  std::vector<Point2> starts;
  for (const detail::FaceEdge& e : face.boundary) {
    room.level = plan.walls[e.wall].level;  // rooms are found level by level: one for all
    room.walls.push_back(plan.walls[e.wall].id);
    collect_openings(plan, by_wall, e, room);
    // Two exact vertices a hair apart can round to one double: such an edge has no direction.
    if (e.source == e.target) continue;
    lines.push_back(inner_line(e, plan.walls[e.wall].thickness / 2));
    starts.push_back(e.source);
  }
  const std::size_t n = lines.size();
  for (std::size_t i = 0; i < n; ++i)
    add_corner(lines[(i + n - 1) % n], lines[i], starts[i], room.outline);
  room.area = std::max(0.0, signed_area(room.outline) - face.hole_area);
  sort_unique(room.walls);
  sort_unique(room.doors);
  sort_unique(room.windows);
  return room;
}

}  // namespace

std::vector<Room> find_rooms(const Plan& plan) { return find_rooms(plan, find_joins(plan)); }

std::vector<Room> find_rooms(const Plan& plan, const Joins& joins) {
  const OpeningsByWall by_wall = openings_by_wall(plan);
  const detail::CentreLines lines = detail::build_centre_lines(plan, joins);
  std::vector<Room> rooms;
  for (detail::Face& face : detail::find_bounded_faces(lines.segments)) {
    for (detail::FaceEdge& e : face.boundary) e.wall = lines.walls[e.wall];
    rooms.push_back(room_of(plan, by_wall, face));
  }
  // Number rooms from the south-west: by the lowest, then leftmost, corner of the outline.
  const auto key = [](const Room& r) {
    const auto it = std::min_element(r.outline.begin(), r.outline.end(), [](Point2 a, Point2 b) {
      return std::tie(a.y, a.x) < std::tie(b.y, b.x);
    });
    return it == r.outline.end() ? std::pair{0.0, 0.0} : std::pair{it->y, it->x};
  };
  std::stable_sort(rooms.begin(), rooms.end(),
                   [&](const Room& a, const Room& b) { return key(a) < key(b); });
  return rooms;
}

std::vector<Room> find_rooms_on_level(const Plan& plan, std::string_view level) {
  if (!level.empty()) return find_rooms(plan_of_level(plan, level));
  Plan unlevelled = plan;
  std::erase_if(unlevelled.walls, [](const Wall& w) { return !w.level.empty(); });
  return find_rooms(unlevelled);
}

std::vector<LevelRooms> find_rooms_by_level(const Plan& plan) {
  std::vector<LevelRooms> out;
  const bool unlevelled =
      plan.levels.empty() || std::any_of(plan.walls.begin(), plan.walls.end(),
                                         [](const Wall& w) { return w.level.empty(); });
  if (unlevelled) out.push_back({"", find_rooms_on_level(plan, "")});
  for (const Level& l : plan.levels) out.push_back({l.id, find_rooms_on_level(plan, l.id)});
  return out;
}

}  // namespace roomcad
