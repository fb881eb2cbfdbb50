// SPDX-License-Identifier: GPL-3.0-or-later
// The rules' shared context: storeys, rooms per storey, door sides, accessible rooms.
#include "validation/rules/context.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_set>

#include <fmt/format.h>

#include "plan/plan_edit.h"
#include "validation/rules/scene.h"
#include "validation/rules/written_number.h"

namespace roomcad::rules {
namespace {

/// How far beyond a wall face a door's side is probed for its room: well inside any room a
/// person can use, and far beyond the rounding of room outlines (1e-15 relative).
constexpr double kSideProbe = 0.01;

}  // namespace

std::vector<Storey> find_storeys(const Plan& plan, const std::vector<bool>& usable) {
  std::vector<std::size_t> all;
  std::vector<double> bases;
  for (std::size_t w = 0; w < plan.walls.size(); ++w)
    if (usable[w]) all.push_back(w), bases.push_back(plan.walls[w].base);
  std::sort(bases.begin(), bases.end());
  bases.erase(std::unique(bases.begin(), bases.end()), bases.end());
  std::vector<Storey> storeys;
  for (const double base : bases) {
    std::vector<std::size_t> walls = walls_at_floor(plan, all, base);
    if (walls.empty() || (!storeys.empty() && storeys.back().walls == walls)) continue;
    Storey s;
    s.floor = base;
    s.walls = std::move(walls);
    storeys.push_back(std::move(s));
  }
  if (!storeys.empty()) storeys.front().lowest = true;
  return storeys;
}

namespace {

/// The doors hosted by the storey's walls, and the room on each side of each.
void find_door_rooms(const Plan& plan, const std::vector<std::optional<std::size_t>>& host,
                     const RoomLocator& locator, Storey& s) {
  std::vector<bool> in_storey(plan.walls.size(), false);
  for (const std::size_t w : s.walls) in_storey[w] = true;
  std::vector<Point2> probes;
  for (std::size_t i = 0; i < plan.openings.size(); ++i) {
    const Opening& o = plan.openings[i];
    if (o.type != OpeningType::door || !host[i] || !in_storey[*host[i]]) continue;
    const Wall& w = plan.walls[*host[i]];
    const double length = std::hypot(w.to.x - w.from.x, w.to.y - w.from.y);
    const Point2 u{(w.to.x - w.from.x) / length, (w.to.y - w.from.y) / length};
    const double along = o.offset + o.width / 2;
    for (const double side : {-1.0, 1.0}) {
      const double across = side * (w.thickness / 2 + kSideProbe);
      probes.push_back(
          {w.from.x + along * u.x - across * u.y, w.from.y + along * u.y + across * u.x});
    }
    s.doors.push_back(i);
  }
  for (std::size_t d = 0; d < s.doors.size(); ++d)
    s.door_rooms.push_back({locator.locate(probes[2 * d]), locator.locate(probes[2 * d + 1])});
}

void mark_accessible(const RuleSet& rules, const RoomLocator& locator, Storey& s) {
  s.accessible.assign(s.rooms.size(), !rules.accessible_rooms.has_value());
  if (!rules.accessible_rooms) return;
  for (const Point2& p : *rules.accessible_rooms)
    if (const std::optional<std::size_t> r = locator.locate(p)) s.accessible[*r] = true;
}

}  // namespace

bool is_inside_outline(const std::vector<Point2>& outline, Point2 p) {
  bool inside = false;
  for (std::size_t i = 0, j = outline.size() - 1; i < outline.size(); j = i++) {
    const Point2& a = outline[i];
    const Point2& b = outline[j];
    if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x)
      inside = !inside;
  }
  return inside;
}

bool is_segment_inside_outline(const std::vector<Point2>& outline, Point2 a, Point2 b) {
  const auto cross = [](Point2 o, Point2 p, Point2 q) {
    return (p.x - o.x) * (q.y - o.y) - (p.y - o.y) * (q.x - o.x);
  };
  for (std::size_t i = 0, j = outline.size() - 1; i < outline.size(); j = i++) {
    const Point2 c = outline[j], d = outline[i];
    const double d1 = cross(a, b, c), d2 = cross(a, b, d), d3 = cross(c, d, a), d4 = cross(c, d, b);
    if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0)))
      return false;
  }
  return is_inside_outline(outline, a) && is_inside_outline(outline, b) &&
         is_inside_outline(outline, {(a.x + b.x) / 2, (a.y + b.y) / 2});
}

Box2 room_box(const Room& room) {
  Box2 box{INFINITY, INFINITY, -INFINITY, -INFINITY, 0};
  for (const Point2& p : room.outline) {
    box.min_x = std::min(box.min_x, p.x), box.max_x = std::max(box.max_x, p.x);
    box.min_y = std::min(box.min_y, p.y), box.max_y = std::max(box.max_y, p.y);
  }
  return box;
}

RoomLocator::RoomLocator(const std::vector<Room>& rooms) : rooms_(rooms) {
  std::vector<Box2> boxes;
  for (std::size_t r = 0; r < rooms.size(); ++r) {
    Box2 b = room_box(rooms[r]);
    // Rooms that hold a point are nested, and a room inside another has a smaller box.
    areas_.push_back((b.max_x - b.min_x) * (b.max_y - b.min_y));
    if (rooms[r].outline.size() < 3) continue;
    b.index = r;
    boxes.push_back(b);
  }
  grid_ = BoxGrid(std::move(boxes));
}

std::optional<std::size_t> RoomLocator::locate(Point2 p) const {
  std::optional<std::size_t> best;
  for (const std::size_t r : grid_.find({p.x, p.y, p.x, p.y, 0}))  // innermost: the smallest box
    if ((!best || areas_[r] < areas_[*best]) && is_inside_outline(rooms_[r].outline, p)) best = r;
  return best;
}

std::vector<std::optional<std::size_t>> locate_rooms(const std::vector<Room>& rooms,
                                                     const std::vector<Point2>& points) {
  const RoomLocator locator(rooms);
  std::vector<std::optional<std::size_t>> out;
  out.reserve(points.size());
  for (const Point2& p : points) out.push_back(locator.locate(p));
  return out;
}

std::vector<std::size_t> walls_at_floor(const Plan& plan,
                                        const std::vector<std::size_t>& candidates, double floor) {
  std::vector<std::size_t> out;
  for (const std::size_t w : candidates) {
    const Wall& wall = plan.walls[w];
    const bool meets = decide_written([&](auto tag) {
      using NT = decltype(tag);
      const NT lo(floor), hi = NT(floor) + NT(kHeadroom);
      return NT(wall.base) < hi && lo < NT(wall.base) + NT(wall.height);
    });
    if (meets) out.push_back(w);
  }
  return out;
}

Plan plan_with_walls(const Plan& plan, const std::vector<std::size_t>& walls) {
  Plan out;
  out.site = plan.site;
  std::unordered_set<std::string_view> ids;
  for (const std::size_t w : walls) {
    out.walls.push_back(plan.walls[w]);
    ids.insert(plan.walls[w].id);
  }
  for (const Opening& o : plan.openings)
    if (ids.count(o.wall)) out.openings.push_back(o);
  return out;
}

Context::Context(const Plan& plan, const Joins& joins, const detail::Usable& usable,
                 const RuleSet& rules, const std::vector<Room>* whole_rooms)
    : plan(plan), joins(joins), rules(rules), wall_usable(usable.walls), host(usable.host) {
  storeys = find_storeys(plan, wall_usable);
  locators_.reserve(storeys.size());  // no reallocation: each locator refers to its storey's rooms
  for (Storey& s : storeys) {
    const bool whole = s.walls.size() == plan.walls.size();
    s.rooms = whole && whole_rooms ? *whole_rooms : find_rooms(plan_with_walls(plan, s.walls));
    locators_.emplace_back(s.rooms);
    find_door_rooms(plan, host, locators_.back(), s);
    mark_accessible(rules, locators_.back(), s);
  }
  new_door_id = generate_id(plan, "door");
  accessible_door.assign(plan.openings.size(), !rules.accessible_rooms.has_value());
  for (const Storey& s : storeys)
    for (std::size_t d = 0; d < s.doors.size(); ++d)
      for (const std::optional<std::size_t>& r : s.door_rooms[d])
        if (r && s.accessible[*r]) accessible_door[s.doors[d]] = true;
}

const Storey* Context::entrance_storey() const {
  for (const Storey& s : storeys)
    for (const auto& sides : s.door_rooms)
      if (!sides[0] || !sides[1]) return &s;
  return storeys.empty() ? nullptr : &storeys.front();
}

const RoomLocator& Context::locator(const Storey& storey) const {
  return locators_[static_cast<std::size_t>(&storey - storeys.data())];
}

Severity Context::severity(Code code) const { return rules.severity[*rule_index(code)]; }

std::string Context::room_name(const Storey& storey, std::size_t room) const {
  if (storeys.size() == 1) return fmt::format("room {}", room + 1);
  return fmt::format("room {} on the floor at z = {:.2f} m", room + 1, storey.floor);
}

}  // namespace roomcad::rules

namespace roomcad {

Status check_accessible_rooms(const Plan& plan, const RuleSet& rules) {
  if (!rules.accessible_rooms) return Status::success();
  const rules::Scene scene(plan);
  std::vector<bool> usable(plan.walls.size());
  for (std::size_t w = 0; w < plan.walls.size(); ++w) usable[w] = scene.is_usable(w);
  std::vector<bool> found(rules.accessible_rooms->size(), false);
  for (const rules::Storey& s : rules::find_storeys(plan, usable)) {
    const std::vector<Room> rooms = find_rooms(rules::plan_with_walls(plan, s.walls));
    const std::vector<std::optional<std::size_t>> at =
        rules::locate_rooms(rooms, *rules.accessible_rooms);
    for (std::size_t i = 0; i < at.size(); ++i) found[i] = found[i] || at[i].has_value();
  }
  for (std::size_t i = 0; i < found.size(); ++i)
    if (!found[i]) {
      const Point2 p = (*rules.accessible_rooms)[i];
      return Status::failure(
          Code::usage_error,
          fmt::format("{}: /accessible_rooms/{}: the point [{}, {}] lies in no room of the plan",
                      rules.name, i, p.x, p.y),
          Location{rules.name, fmt::format("/accessible_rooms/{}", i), 0, 0});
    }
  return Status::success();
}

}  // namespace roomcad
