// SPDX-License-Identifier: GPL-3.0-or-later
// The checks validate() runs, one file each, sharing what earlier checks found.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "geometry/joins.h"
#include "plan/plan.h"
#include "validation/report.h"
#include "validation/validate.h"

namespace roomcad::detail {

/// Which objects passed the value and reference checks. Geometry checks look only at these,
/// so one mistake gives one error.
struct Usable {
  bool site = false;        ///< origin, cells, cell_size, max_height finite/positive
  std::vector<bool> walls;  ///< by index into Plan::walls
  std::vector<std::optional<std::size_t>> host;  ///< by opening: its host wall, if both are usable
  std::vector<bool> slabs;                       ///< by index into Plan::slabs
  std::vector<bool> obstructions;                ///< by index into Plan::obstructions
};

/// invalid_value for every number, size and direction of the plan (no geometry).
/// @return which walls and whether the site are usable. O(n).
[[nodiscard]] Usable check_values(const Plan& plan, Report& report);

/// duplicate_id across all objects, unknown_reference for openings; fills `usable.host`.
/// O(n log n).
void check_ids(const Plan& plan, Usable& usable, Report& report);

struct ResolvedPlan;

/// wall_overlap and out_of_bounds on usable walls (of `resolved`, with its `joins`);
/// opening_outside_wall and opening_overlap on the usable openings of `plan` (judged on their
/// walls' polylines and sloped tops), opening_blocked on `resolved`'s; slab_overlap,
/// opening_blocked by slabs and out_of_bounds of slabs and levels. O(n log n + k).
void check_geometry(const Plan& plan, const Usable& usable, const ResolvedPlan& resolved,
                    const Joins& joins, Report& report);

/// unknown_field (if asked) and door_above_floor warnings. O(n).
void check_warnings(const Plan& plan, const ValidateOptions& options, Report& report);

/// room_without_door and room_without_window warnings for rooms found by find_rooms. O(n).
/// A room is named by the plan's `rooms` (room_labels); only rooms a person stays in
/// (is_habitable) are asked for a window.
void warn_about_rooms(const std::vector<Room>& rooms, const Plan& plan,
                      const HabitableRooms& habitable, Report& report);

/// The rule set's rules (validation/rules/): findings with the rule codes, on the usable
/// walls and openings. `whole_rooms`: find_rooms of the plan if already found (or nullptr).
/// Cost: O(n log n) plus the rules' searches near each finding.
void check_rules(const Plan& plan, const Joins& joins, const Usable& usable, const RuleSet& rules,
                 const std::vector<Room>* whole_rooms, Report& report);

}  // namespace roomcad::detail
