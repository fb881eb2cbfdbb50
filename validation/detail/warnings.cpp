// SPDX-License-Identifier: GPL-3.0-or-later
// Warnings that do not depend on geometry: unknown_field and door_above_floor.
#include <cmath>
#include <cstdint>
#include <string_view>

#include <fmt/format.h>

#include "core/flat_index.h"
#include "validation/detail/checks.h"
#include "validation/detail/diagnostics.h"

namespace roomcad::detail {
namespace {

void warn_extra(const ExtraFields& extra, std::string_view owner, const std::string& id,
                Report& report) {
  for (const ExtraField& f : extra)
    report.add(make_diagnostic(
        Severity::warning, Code::unknown_field,
        id.empty() ? std::vector<std::string>{} : std::vector{id},
        fmt::format("{} has a field '{}' that the plan format does not define; it is kept but "
                    "has no effect.",
                    owner, f.key),
        fmt::format("check the spelling of '{}', or remove it", f.key)));
}

void warn_unknown_fields(const Plan& plan, Report& report) {
  warn_extra(plan.extra, "the plan", "", report);
  warn_extra(plan.site.extra, "the site", "", report);
  for (const Level& l : plan.levels)
    warn_extra(l.extra, fmt::format("level '{}'", l.id), l.id, report);
  for (const Wall& w : plan.walls) warn_extra(w.extra, name_of(w), w.id, report);
  for (const Opening& o : plan.openings) warn_extra(o.extra, name_of(o), o.id, report);
  for (const Slab& s : plan.slabs)
    warn_extra(s.extra, fmt::format("slab '{}'", s.id), s.id, report);
  for (const Light& l : plan.lights)
    warn_extra(l.extra, fmt::format("light '{}'", l.id), l.id, report);
  for (const Camera& c : plan.cameras)
    warn_extra(c.extra, fmt::format("camera '{}'", c.id), c.id, report);
}

}  // namespace

void check_warnings(const Plan& plan, const ValidateOptions& options, Report& report) {
  if (options.unknown_field_warnings) warn_unknown_fields(plan, report);
  const IdIndex walls = index_by_id(plan.walls);
  for (const Opening& o : plan.openings) {
    if (o.type != OpeningType::door || !std::isfinite(o.sill) || o.sill <= 0) continue;
    // A wall of a level that reaches down through its floor (base < 0) has the floor at
    // v = -base: a door standing there is at the floor.
    const std::uint32_t found = walls.find(o.wall);
    const Wall* w = found == walls.kNone ? nullptr : &plan.walls[found];
    const bool below_floor = w && !w->level.empty() && w->base < 0;
    if (below_floor && o.sill == -w->base) continue;
    report.add(make_diagnostic(
        Severity::warning, Code::door_above_floor, {o.id},
        below_floor
            ? fmt::format("{} starts {} above the floor of its level (wall '{}' reaches {} below "
                          "it); a door normally starts at the floor.",
                          name_of(o), metres(o.sill + w->base), o.wall, metres(-w->base))
            : fmt::format("{} starts {} above the base of wall '{}'; a door normally starts at "
                          "the floor.",
                          name_of(o), metres(o.sill), o.wall),
        below_floor ? fmt::format("set its sill to {}, the depth its wall reaches below the floor, "
                                  "or make it a window if it is one",
                                  exact_metres(-w->base))
                    : "set its sill to 0, or make it a window if it is one"));
  }
}

}  // namespace roomcad::detail
