// SPDX-License-Identifier: GPL-3.0-or-later
// validate(): value checks, then ids and references, then exact geometry on what passed,
// then warnings. Every check runs; nothing stops at the first problem.
#include "validation/validate.h"

#include <algorithm>
#include <cmath>
#include <future>
#include <iterator>
#include <map>
#include <string>
#include <string_view>
#include <unordered_set>
#include <vector>

#include "geometry/joins.h"
#include "geometry/rooms.h"
#include "validation/detail/checks.h"
#include "validation/detail/resolved_plan.h"

namespace roomcad {
namespace {

/// Walls that failed a value check are made to join nothing (NaN ends), so a bad thickness
/// cannot bend a good wall's mitre.
void isolate_unusable(Plan& plan, const std::vector<bool>& usable) {
  for (std::size_t w = 0; w < plan.walls.size(); ++w)
    if (!usable[w]) plan.walls[w].from = plan.walls[w].to = {NAN, NAN};
}

/// The rooms of each storey: the resolved plan's walls grouped by their level (walls without
/// one form a group of their own), so that walls of different storeys never bound one room.
std::vector<Room> find_rooms_by_level(const Plan& plan, const detail::ResolvedPlan& resolved,
                                      const Joins& joins) {
  if (plan.levels.empty()) return find_rooms(resolved.plan, joins);
  std::map<std::string, Plan> storeys;
  for (std::size_t j = 0; j < resolved.plan.walls.size(); ++j) {
    Plan& storey = storeys[plan.walls[resolved.source_wall[j]].level];
    storey.walls.push_back(resolved.plan.walls[j]);
  }
  std::vector<Room> rooms;
  for (auto& [level, storey] : storeys) {
    std::unordered_set<std::string_view> ids;
    for (const Wall& w : storey.walls) ids.insert(w.id);
    for (const Opening& o : resolved.plan.openings)
      if (ids.contains(o.wall)) storey.openings.push_back(o);
    storey.site = plan.site;
    std::ranges::move(find_rooms(storey, find_joins(storey)), std::back_inserter(rooms));
  }
  return rooms;
}

}  // namespace

Report validate(const Plan& plan, const ValidateOptions& options) {
  Report report;
  detail::Usable usable = detail::check_values(plan, report);
  detail::check_ids(plan, usable, report);
  // Geometry is judged on the plan as built: levels resolved, arcs as their chords; walls that
  // failed a value check join nothing there.
  detail::ResolvedPlan resolved = detail::resolve_plan(plan, usable);
  isolate_unusable(resolved.plan, resolved.usable.walls);
  const Joins joins = find_joins(resolved.plan);
  const bool rules = options.rules.any_enabled();
  // The rules reuse the rooms when one storey holds every wall: a sound plan without levels.
  const bool rooms_for_rules =
      rules && plan.levels.empty() &&
      std::all_of(usable.walls.begin(), usable.walls.end(), [](bool ok) { return ok; });
  // Rooms take about as long as all the other checks: find them on the second core while
  // those run (they only read the plan). Their warnings are added below, in a fixed place,
  // so the report does not depend on timing.
  std::future<std::vector<Room>> rooms;
  if (options.room_warnings || rooms_for_rules)
    rooms = std::async(std::launch::async, [&plan, &resolved, &joins] {
      return find_rooms_by_level(plan, resolved, joins);
    });
  detail::check_geometry(plan, usable, resolved, joins, report);
  const bool has_errors = !report.ok();
  detail::check_warnings(plan, options, report);
  std::vector<Room> found;
  if (rooms.valid()) found = rooms.get();
  // Rooms are only meaningful on a plan whose walls are sound: with errors, say nothing more.
  if (options.room_warnings && !has_errors)
    detail::warn_about_rooms(found, plan, options.rules.habitable_rooms, report);
  if (rules)
    detail::check_rules(resolved.plan, joins, resolved.usable, options.rules,
                        rooms_for_rules ? &found : nullptr, report);
  std::stable_partition(report.items.begin(), report.items.end(),
                        [](const Diagnostic& d) { return d.severity == Severity::error; });
  return report;
}

}  // namespace roomcad
