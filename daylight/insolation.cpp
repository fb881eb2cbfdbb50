// SPDX-License-Identifier: GPL-3.0-or-later
#include "daylight/insolation.h"

#include <algorithm>
#include <cmath>
#include <map>

#include <fmt/format.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include "core/error.h"
#include "daylight/detail/room_side.h"
#include "daylight/sun_blockers.h"
#include "daylight/sun_position.h"
#include "geometry/rooms.h"
#include "plan/arc_chords.h"
#include "plan/plan_levels.h"
#include "validation/room_labels.h"

namespace roomcad {
namespace {

/// The sun over the day: its direction in plan coordinates at each scan time, and the tracker
/// that gives it between them.
struct DaySun {
  UtcSeconds start = 0;
  double step = 60;
  double north = 0;
  SunTracker tracker;
  std::vector<Vec3> directions;  ///< at start + k * step; z <= 0: the sun is down
  [[nodiscard]] Vec3 direction(UtcSeconds t) const {
    const SunPosition p = tracker.at(t);
    const Vec3 d = sun_direction_in_plan(p, north);
    return p.elevation > 0 ? d : Vec3{d.x, d.y, std::min(d.z, 0.0)};
  }
};

DaySun scan_sun(const GeoLocation& place, double north, CivilDay date, double step) {
  const UtcSeconds start = local_midnight(date, place.utc_offset);
  DaySun sun{start, step, north, SunTracker(place, start, start + kSecondsPerDay), {}};
  const auto samples = static_cast<std::size_t>(std::ceil(kSecondsPerDay / step));
  sun.directions.resize(samples + 1);
  tbb::parallel_for(std::size_t{0}, samples + 1, [&](std::size_t k) {
    sun.directions[k] =
        sun.direction(std::min(start + static_cast<double>(k) * step, start + kSecondsPerDay));
  });
  return sun;
}

bool lit(const SunBlockers& blockers, const Vec3& point, const Vec3& direction) {
  return direction.z > 0 && !blockers.blocks(point, direction);
}

/// The intervals of sun at `point`: the scan, then each change bisected to under 0.5 s.
std::vector<SunInterval> sun_intervals(const SunBlockers& blockers, const DaySun& sun,
                                       const Vec3& point) {
  const std::size_t n = sun.directions.size();
  const auto time_of = [&](std::size_t k) {
    return std::min(sun.start + static_cast<double>(k) * sun.step, sun.start + kSecondsPerDay);
  };
  const auto change_between = [&](UtcSeconds a, UtcSeconds b, bool lit_at_a) {
    while (b - a > 0.5) {
      const UtcSeconds m = 0.5 * (a + b);
      (lit(blockers, point, sun.direction(m)) == lit_at_a ? a : b) = m;
    }
    return 0.5 * (a + b);
  };
  std::vector<SunInterval> out;
  bool was_lit = lit(blockers, point, sun.directions[0]);
  if (was_lit) out.push_back({sun.start, sun.start + kSecondsPerDay});
  for (std::size_t k = 1; k < n; ++k) {
    const bool now = lit(blockers, point, sun.directions[k]);
    if (now == was_lit) continue;
    const UtcSeconds at = change_between(time_of(k - 1), time_of(k), was_lit);
    if (now) out.push_back({at, sun.start + kSecondsPerDay});
    else out.back().second = at;
    was_lit = now;
  }
  return out;
}

/// The point at arc length `s` along a polyline, and the unit direction of its piece there.
std::pair<Point2, Point2> along(const std::vector<Point2>& line, double s) {
  for (std::size_t i = 0; i + 1 < line.size(); ++i) {
    const double dx = line[i + 1].x - line[i].x, dy = line[i + 1].y - line[i].y;
    const double length = std::hypot(dx, dy);
    if (length <= 0) continue;
    if (s <= length || i + 2 == line.size())
      return {{line[i].x + dx * s / length, line[i].y + dy * s / length},
              {dx / length, dy / length}};
    s -= length;
  }
  return {line.front(), {1, 0}};
}

/// The calculation point of window `o` (in wall `w`) on the side of `room`: the middle of its
/// width, on the wall's face towards the room, at its sill, moved as `at` says.
Vec3 calculation_point(const Plan& plan, const Wall& w, const Opening& o, const Room& room,
                       const InsolationOptions& at) {
  const std::vector<Point2> line = chord_polyline(w, chord_tolerance_of(plan.site));
  const auto [centre, u] = along(line, o.offset + o.width / 2);
  const Point2 n{-u.y, u.x};
  const double half = w.thickness / 2;
  const double out =
      daylight_detail::room_side(room.outline, centre, u, half) * (half - at.into_reveal);
  const double z =
      (w.level.empty() ? 0.0 : level_elevation(plan, w.level)) + w.base + o.sill + at.above_sill;
  return {centre.x + n.x * out, centre.y + n.y * out, z};
}

double hours(const std::vector<SunInterval>& intervals, bool longest) {
  double seconds = 0;
  for (const auto& [a, b] : intervals)
    seconds = longest ? std::max(seconds, b - a) : seconds + (b - a);
  return seconds / 3600.0;
}

}  // namespace

InsolationDay insolation(const Plan& plan, const SolidMesh& solid, CivilDay date,
                         const InsolationOptions& options) {
  if (!plan.site.location)
    throw PreconditionError(
        "insolation: the plan does not say where its site is (no "
        "site.location)");
  std::optional<tbb::global_control> threads;
  if (options.threads > 0)
    threads.emplace(tbb::global_control::max_allowed_parallelism,
                    static_cast<std::size_t>(options.threads));
  InsolationDay day{date, *plan.site.location, {}};
  const DaySun sun = scan_sun(day.place, plan.site.north.value_or(0.0), date, options.scan_seconds);
  const SunBlockers blockers(solid, plan.obstructions);
  std::map<std::string, std::size_t> opening_index;
  for (std::size_t i = 0; i < plan.openings.size(); ++i)
    opening_index.emplace(plan.openings[i].id, i);

  std::size_t number = 0;
  for (const LevelRooms& level : find_rooms_by_level(plan)) {
    const std::vector<const RoomLabel*> labels = room_labels(level.rooms, plan);
    for (std::size_t r = 0; r < level.rooms.size(); ++r) {
      const Room& room = level.rooms[r];
      RoomSun out{labels[r] ? labels[r]->id : fmt::format("room-{}", number + 1),
                  labels[r] ? labels[r]->name : "",
                  level.level,
                  room.area,
                  room.outline,
                  room.walls,
                  {},
                  "",
                  0,
                  0};
      ++number;
      for (const std::string& id : room.windows) {
        const auto found = opening_index.find(id);
        const Wall* wall = found == opening_index.end()
                               ? nullptr
                               : find_wall(plan, plan.openings[found->second].wall);
        if (!wall) continue;
        const Opening& o = plan.openings[found->second];
        out.windows.push_back({id, calculation_point(plan, *wall, o, room, options), {}, 0, 0});
      }
      day.rooms.push_back(std::move(out));
    }
  }
  std::vector<WindowSun*> windows;
  const auto asked = [&](const std::string& id) {
    return options.only_windows.empty() ||
           std::find(options.only_windows.begin(), options.only_windows.end(), id) !=
               options.only_windows.end();
  };
  for (RoomSun& room : day.rooms)
    for (WindowSun& w : room.windows)
      if (asked(w.id)) windows.push_back(&w);
  tbb::parallel_for(std::size_t{0}, windows.size(), [&](std::size_t i) {
    WindowSun& w = *windows[i];
    w.intervals = sun_intervals(blockers, sun, w.point);
    w.continuous_hours = hours(w.intervals, true);
    w.total_hours = hours(w.intervals, false);
  });
  for (RoomSun& room : day.rooms)
    for (const WindowSun& w : room.windows)
      if (room.best_window.empty() || w.continuous_hours > room.continuous_hours ||
          (w.continuous_hours == room.continuous_hours && w.total_hours > room.total_hours)) {
        room.best_window = w.id;
        room.continuous_hours = w.continuous_hours;
        room.total_hours = w.total_hours;
      }
  return day;
}

}  // namespace roomcad
