// SPDX-License-Identifier: GPL-3.0-or-later
#include "validation/room_labels.h"

#include "validation/detail/habitable_rooms.h"
#include "validation/rules/context.h"

namespace roomcad {

std::vector<const RoomLabel*> room_labels(const std::vector<Room>& rooms, const Plan& plan) {
  std::vector<const RoomLabel*> labels(rooms.size(), nullptr);
  for (std::size_t r = 0; r < rooms.size(); ++r)
    for (const RoomLabel& label : plan.rooms)
      if (label.level == rooms[r].level && rules::is_inside_outline(rooms[r].outline, label.at)) {
        labels[r] = &label;
        break;
      }
  return labels;
}

bool is_habitable_room(const Room& room, std::string_view name, const HabitableRooms& rules) {
  return detail::is_habitable(room, name, rules);
}

}  // namespace roomcad
