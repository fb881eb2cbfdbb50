// SPDX-License-Identifier: GPL-3.0-or-later
// room_without_door and room_without_window: a room is a bounded face of the walls' centre
// line arrangement (find_rooms); only rooms a person stays in need a window (habitable_rooms.h).
#include <fmt/format.h>
#include <fmt/ranges.h>

#include "validation/detail/checks.h"
#include "validation/detail/diagnostics.h"
#include "validation/detail/habitable_rooms.h"
#include "validation/room_labels.h"

namespace roomcad::detail {
namespace {

void warn_room(const Room& room, std::size_t number, std::string_view name, Code code,
               std::string_view what, Report& report) {
  double lo_x = INFINITY, lo_y = INFINITY, hi_x = -INFINITY, hi_y = -INFINITY;
  for (const Point2& p : room.outline) {
    lo_x = std::min(lo_x, p.x), hi_x = std::max(hi_x, p.x);
    lo_y = std::min(lo_y, p.y), hi_y = std::max(hi_y, p.y);
  }
  report.add(make_diagnostic(
      Severity::warning, code, room.walls,
      fmt::format("room {} ({}{:.2f} m², walls {}) has no {}.", number,
                  name.empty() ? "" : fmt::format("{}, ", name), room.area,
                  fmt::join(room.walls, ", "), what),
      fmt::format("add a {} to one of its walls ({})", what, fmt::join(room.walls, ", ")),
      room.outline.empty() ? std::optional<Where>{} : box_where(lo_x, lo_y, hi_x, hi_y)));
}

}  // namespace

void warn_about_rooms(const std::vector<Room>& rooms, const Plan& plan,
                      const HabitableRooms& habitable, Report& report) {
  const std::vector<const RoomLabel*> labels = room_labels(rooms, plan);
  for (std::size_t i = 0; i < rooms.size(); ++i) {
    const std::string_view name = labels[i] ? std::string_view(labels[i]->name) : "";
    if (rooms[i].doors.empty())
      warn_room(rooms[i], i + 1, name, Code::room_without_door, "door", report);
    if (rooms[i].windows.empty() && is_habitable(rooms[i], name, habitable))
      warn_room(rooms[i], i + 1, name, Code::room_without_window, "window", report);
  }
}

}  // namespace roomcad::detail
