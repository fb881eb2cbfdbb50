// SPDX-License-Identifier: GPL-3.0-or-later
// validate(): value checks, then ids and references, then exact geometry on what passed,
// then warnings. Every check runs; nothing stops at the first problem.
#include "validation/validate.h"

#include <algorithm>
#include <cmath>
#include <future>
#include <optional>
#include <vector>

#include "modeling/joins.h"
#include "modeling/plan_levels.h"
#include "validation/detail/checks.h"

namespace roomcad {
namespace {

/// The plan the geometry checks see: levels resolved (every base absolute, so walls standing
/// on one another are neither joined nor overlapping: docs/plan-format.md, "Version 2"), and
/// walls that failed a value check made to join nothing (NaN ends), so a bad thickness cannot
/// bend a good wall's mitre.
Plan geometry_plan(const Plan& plan, const detail::Usable& usable) {
  Plan copy = with_absolute_heights(plan);
  for (std::size_t w = 0; w < copy.walls.size(); ++w)
    if (!usable.walls[w]) copy.walls[w].from = copy.walls[w].to = {NAN, NAN};
  return copy;
}

/// A wall whose level puts it nowhere (a bad elevation, reported on the level) is unusable
/// for the geometry, as a wall with a bad value of its own is.
void leave_out_unplaced_walls(const Plan& plan, detail::Usable& usable) {
  if (plan.levels.empty()) return;  // every base was judged by the value checks
  for (std::size_t w = 0; w < plan.walls.size(); ++w) {
    const double base = base_z(plan, plan.walls[w]);
    if (!std::isfinite(base) || !std::isfinite(base + plan.walls[w].height)) usable.walls[w] = false;
  }
}

}  // namespace

Report validate(const Plan& plan, const ValidateOptions& options) {
  Report report;
  detail::Usable usable = detail::check_values(plan, report);
  detail::check_ids(plan, usable, report);
  leave_out_unplaced_walls(plan, usable);
  const bool all_walls_usable =
      std::all_of(usable.walls.begin(), usable.walls.end(), [](bool ok) { return ok; });
  const Joins joins = find_joins(plan);
  const bool rules = options.rules.any_enabled();
  // Rooms take about as long as all the other checks: find them on the second core while
  // those run (they only read the plan). Their warnings are added below, in a fixed place,
  // so the report does not depend on timing.
  std::future<std::vector<Room>> rooms;
  if (options.room_warnings || (rules && all_walls_usable))
    rooms = std::async(std::launch::async, [&plan, &joins] { return find_rooms(plan, joins); });
  // The geometry checks and the rules see the levels resolved and only usable walls
  // (geometry_plan); a plan without levels whose walls are all usable is that already.
  std::optional<Plan> geometry;
  std::optional<Joins> geometry_joins;
  if (!all_walls_usable || !plan.levels.empty()) {
    geometry = geometry_plan(plan, usable);
    geometry_joins = find_joins(*geometry);
  }
  const Plan& checked = geometry ? *geometry : plan;
  const Joins& checked_joins = geometry_joins ? *geometry_joins : joins;
  detail::check_geometry(checked, checked_joins, usable, report);
  const bool has_errors = !report.ok();
  detail::check_warnings(plan, options, report);
  std::vector<Room> found;
  const bool whole_rooms = rooms.valid() && all_walls_usable;
  if (rooms.valid()) found = rooms.get();
  // Rooms are only meaningful on a plan whose walls are sound: with errors, say nothing more.
  if (options.room_warnings && !has_errors) detail::warn_about_rooms(found, report);
  if (rules) detail::check_rules(checked, checked_joins, usable, options.rules, whole_rooms ? &found : nullptr, report);
  std::stable_partition(report.items.begin(), report.items.end(),
                        [](const Diagnostic& d) { return d.severity == Severity::error; });
  return report;
}

}  // namespace roomcad
