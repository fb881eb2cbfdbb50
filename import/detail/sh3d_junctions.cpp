// SPDX-License-Identifier: GPL-3.0-or-later
#include "import/detail/sh3d_junctions.h"

#include <cmath>
#include <numbers>
#include <optional>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "import/detail/sh3d_walls.h"

namespace roomcad::sh3d {
namespace {

// Ends within this of a centre line already join it (well inside the plan's join tolerance).
constexpr double kOnLine = 1e-9;
// Below this angle a wall runs along the other rather than into it: not a T.
const double kMinSin = std::sin(10.0 * std::numbers::pi / 180);

double cross(Point2 a, Point2 b) { return a.x * b.y - a.y * b.x; }
double distance(Point2 a, Point2 b) { return std::hypot(b.x - a.x, b.y - a.y); }

bool is_straight(const WallRecord& w) { return !w.arc_extent || *w.arc_extent == 0; }

/// Where the end `end` of a wall from `far` (thickness `own_thickness`) joins `host`, when it
/// lies inside `host`'s box (its footprint extended by half its thickness past each end, as
/// Sweet Home 3D fills corners): moved along its own wall onto `host`'s centre line, or, if that
/// point is within half of either wall's thickness of an end of `host` and the moving wall is
/// not the thicker, that end (an L corner, or a junction of three walls).
/// @return the new end point and its distance from `host`'s centre line before the move.
std::optional<std::pair<Point2, double>> join_point(Point2 far, Point2 end, double own_thickness,
                                                    const WallRecord& host) {
  const double length = distance(host.start, host.end);
  const double own = distance(far, end);
  const double half = host.thickness / 2;
  if (length == 0 || own == 0) return std::nullopt;
  const Point2 along{(host.end.x - host.start.x) / length, (host.end.y - host.start.y) / length};
  const Point2 dir{(end.x - far.x) / own, (end.y - far.y) / own};
  const Point2 rel{end.x - host.start.x, end.y - host.start.y};
  const double off = cross(along, rel);  // signed distance from the centre line
  const double u = along.x * rel.x + along.y * rel.y;
  const double turn = cross(along, dir);
  if (std::abs(off) >= half || u < -half || u > length + half || std::abs(turn) < kMinSin)
    return std::nullopt;
  const double s = -off / turn;  // end + s * dir lies on the centre line
  if (std::abs(s) >= own / 2) return std::nullopt;
  const Point2 moved{end.x + s * dir.x, end.y + s * dir.y};
  const double moved_u = along.x * (moved.x - host.start.x) + along.y * (moved.y - host.start.y);
  // Near an end of `host` the wall would poke past it (into the walls joined there): it joins
  // that end instead, unless it is the thicker wall (an outer wall does not bend to meet the
  // end of an inner one; the inner one moves onto it).
  const Point2 corner = moved_u < length / 2 ? host.start : host.end;
  if (own_thickness <= host.thickness &&
      distance(moved, corner) <= std::min(half, own_thickness / 2))
    return end == corner ? std::nullopt : std::optional{std::pair{corner, std::abs(off)}};
  if (moved_u < 0 || moved_u > length || std::abs(off) <= kOnLine) return std::nullopt;
  return std::pair{moved, std::abs(off)};
}

bool is_parallel(const WallRecord& a, const WallRecord& b) {
  const Point2 u{a.end.x - a.start.x, a.end.y - a.start.y};
  const Point2 v{b.end.x - b.start.x, b.end.y - b.start.y};
  return std::abs(cross(u, v)) <= kMinSin * std::hypot(u.x, u.y) * std::hypot(v.x, v.y);
}

/// The end point `end` of wall `i` moved onto the nearest centre line that takes it, if any.
/// An end shared with the end of a wall that turns away is a corner already and stays; one
/// shared only with walls in line (a straight wall drawn in pieces) moves with them.
std::optional<std::pair<Point2, std::size_t>> t_join_of(const std::vector<WallRecord>& walls,
                                                        std::size_t i, Point2 far, Point2 end) {
  for (std::size_t j = 0; j < walls.size(); ++j)
    if (j != i && (walls[j].start == end || walls[j].end == end) &&
        !is_parallel(walls[i], walls[j]))
      return std::nullopt;
  std::optional<std::pair<Point2, std::size_t>> best;
  double best_off = 0.0;
  for (std::size_t j = 0; j < walls.size(); ++j) {
    if (j == i || walls[j].level != walls[i].level || !is_straight(walls[j])) continue;
    const auto moved = join_point(far, end, walls[i].thickness, walls[j]);
    if (moved && (!best || moved->second < best_off)) {
      best = std::pair{moved->first, j};
      best_off = moved->second;
    }
  }
  return best;
}

/// @return false if moving the end point `from` of every wall ending there to `to` would take
/// away half or more of one of those walls (a short piece of a wall drawn in pieces).
bool keeps_lengths(const std::vector<WallRecord>& walls, Point2 from, Point2 to) {
  for (const WallRecord& w : walls) {
    if (w.start != from && w.end != from) continue;
    const Point2 other = w.start == from ? w.end : w.start;
    if (distance(to, other) <= distance(from, other) / 2) return false;
  }
  return true;
}

/// The first end point of walls [0, before) other than wall `self` on the level of `self` that
/// lies within `snap_distance` of `p` but is not `p`, if any.
std::optional<Point2> nearby_end(const std::vector<WallRecord>& walls, std::size_t before,
                                 std::size_t self, Point2 p, double snap_distance) {
  for (std::size_t j = 0; j < before; ++j) {
    if (j == self || walls[j].level != walls[self].level) continue;
    for (const Point2 q : {walls[j].start, walls[j].end})
      if (q != p && distance(p, q) <= snap_distance) return q;
  }
  return std::nullopt;
}

}  // namespace

void snap_close_ends(std::vector<WallRecord>& walls, double snap_distance) {
  for (std::size_t i = 1; i < walls.size(); ++i)
    for (Point2* p : {&walls[i].start, &walls[i].end})
      if (const std::optional<Point2> q = nearby_end(walls, i, i, *p, snap_distance)) *p = *q;
}

void join_t_ends(std::vector<WallRecord>& walls, double snap_distance, Report& warnings) {
  std::vector<std::string> moved;
  std::vector<std::string> ids;
  for (std::size_t i = 0; i < walls.size(); ++i) {
    if (!is_straight(walls[i])) continue;
    WallRecord& w = walls[i];
    for (const bool at_start : {true, false}) {
      Point2& end = at_start ? w.start : w.end;
      const auto join = t_join_of(walls, i, at_start ? w.end : w.start, end);
      if (!join) continue;
      // A point moved next to another wall's end (a T at a corner) becomes that end.
      const Point2 old_end = end;
      const Point2 new_end =
          nearby_end(walls, walls.size(), i, join->first, snap_distance).value_or(join->first);
      if (!keeps_lengths(walls, old_end, new_end)) continue;  // not moved: not reported
      const double by_mm = distance(old_end, join->first) * 1000.0;
      moved.push_back(fmt::format("'{}' {} by {} onto '{}'", w.id, at_start ? "start" : "end",
                                  by_mm < 0.1 ? "under 0.1 mm" : fmt::format("{:.1f} mm", by_mm),
                                  walls[join->second].id));
      for (WallRecord& other : walls)
        for (Point2* p : {&other.start, &other.end})
          if (*p == old_end) *p = new_end;  // this end and the pieces in line sharing it
      if (ids.empty() || ids.back() != w.id) ids.push_back(w.id);
    }
  }
  if (moved.empty()) return;
  Diagnostic d = import_warning(
      Code::import_t_junction, ids.front(),
      fmt::format("{} wall ends drawn inside another wall were moved onto that wall's centre line "
                  "(along their own wall) or onto its end (at a corner), so that the plan joins "
                  "them as Sweet Home 3D does, one per line:\n  {}",
                  moved.size(), fmt::join(moved, "\n  ")));
  d.objects = std::move(ids);
  warnings.add(std::move(d));
}

}  // namespace roomcad::sh3d
