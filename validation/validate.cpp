// validate(): value checks, then ids and references, then exact geometry on what passed,
// then warnings. Every check runs; nothing stops at the first problem.
#include "validation/validate.h"

#include <algorithm>
#include <cmath>
#include <future>
#include <vector>

#include "modeling/joins.h"
#include "validation/detail/checks.h"

namespace roomcad {
namespace {

/// The plan the geometry checks see: walls that failed a value check are made to join
/// nothing (NaN ends), so a bad thickness cannot bend a good wall's mitre.
Plan geometry_plan(const Plan& plan, const detail::Usable& usable) {
  Plan copy = plan;
  for (std::size_t w = 0; w < copy.walls.size(); ++w)
    if (!usable.walls[w]) copy.walls[w].from = copy.walls[w].to = {NAN, NAN};
  return copy;
}

}  // namespace

Report validate(const Plan& plan, const ValidateOptions& options) {
  Report report;
  detail::Usable usable = detail::check_values(plan, report);
  detail::check_ids(plan, usable, report);
  const bool all_walls_usable =
      std::all_of(usable.walls.begin(), usable.walls.end(), [](bool ok) { return ok; });
  const Joins joins = find_joins(plan);
  // Rooms take about as long as all the other checks: find them on the second core while
  // those run (they only read the plan). Their warnings are added below, in a fixed place,
  // so the report does not depend on timing.
  std::future<std::vector<Room>> rooms;
  if (options.room_warnings)
    rooms = std::async(std::launch::async, [&plan, &joins] { return find_rooms(plan, joins); });
  if (all_walls_usable) {
    detail::check_geometry(plan, joins, usable, report);
  } else {
    const Plan geometry = geometry_plan(plan, usable);
    detail::check_geometry(geometry, find_joins(geometry), usable, report);
  }
  const bool has_errors = !report.ok();
  detail::check_warnings(plan, options, report);
  // Rooms are only meaningful on a plan whose walls are sound: with errors, say nothing more.
  if (rooms.valid()) {
    const std::vector<Room> found = rooms.get();
    if (!has_errors) detail::warn_about_rooms(found, report);
  }
  std::stable_partition(report.items.begin(), report.items.end(),
                        [](const Diagnostic& d) { return d.severity == Severity::error; });
  return report;
}

}  // namespace roomcad
