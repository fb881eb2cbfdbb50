// SPDX-License-Identifier: GPL-3.0-or-later
// duplicate_id (ids are unique across ALL objects of a plan) and unknown_reference.
#include <algorithm>
#include <cstdint>
#include <string_view>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "core/flat_index.h"
#include "plan/plan_objects.h"
#include "validation/detail/checks.h"
#include "validation/detail/diagnostics.h"

namespace roomcad::detail {
namespace {

struct IdUse {
  std::string_view id;
  std::string_view list;  ///< "walls", "openings", ...
  std::size_t index;
};

std::vector<IdUse> collect_ids(const Plan& plan) {
  std::vector<IdUse> uses;
  for_each_list(plan, [&uses](const auto& objects, ObjectKind kind) {
    for (std::size_t i = 0; i < objects.size(); ++i)
      if (!objects[i].id.empty()) uses.push_back({objects[i].id, list_name(kind), i});
  });
  return uses;
}

/// unknown_reference for each wall, slab or room whose `level` names no level.
template <class Object>
void check_level_references(const Plan& plan, const std::vector<Object>& objects,
                            std::string_view kind, Report& report) {
  for (const Object& o : objects) {
    if (o.level.empty() || std::any_of(plan.levels.begin(), plan.levels.end(),
                                       [&](const Level& l) { return l.id == o.level; }))
      continue;
    report.add(make_diagnostic(
        Severity::error, Code::unknown_reference, {o.id},
        fmt::format("{} '{}' names level '{}', which is not in the plan.", kind, o.id, o.level),
        plan.levels.empty() ? fmt::format("add level '{}' to the plan's levels", o.level)
                            : fmt::format("set its level to the id of an existing level, e.g. '{}'",
                                          plan.levels.front().id)));
  }
}

/// @return the uses of each id used more than once, in order of first use. O(n) expected.
std::vector<std::vector<const IdUse*>> find_duplicate_groups(const std::vector<IdUse>& uses) {
  IdIndex first_use(uses.size());
  std::vector<std::uint32_t> first(uses.size());
  std::vector<bool> repeated(uses.size(), false);  // by first use
  for (std::size_t i = 0; i < uses.size(); ++i) {
    first[i] = first_use.try_emplace(uses[i].id, std::uint32_t(i)).first;
    if (first[i] != i) repeated[first[i]] = true;
  }
  std::vector<std::size_t> group_of(uses.size());
  std::vector<std::vector<const IdUse*>> groups;
  for (std::size_t i = 0; i < uses.size(); ++i) {
    if (!repeated[first[i]]) continue;
    if (first[i] == i) {
      group_of[i] = groups.size();
      groups.emplace_back();
    }
    groups[group_of[first[i]]].push_back(&uses[i]);
  }
  return groups;
}

void report_duplicates(const Plan& plan, Report& report) {
  const std::vector<IdUse> uses = collect_ids(plan);
  for (const auto& group : find_duplicate_groups(uses)) {
    std::vector<std::string> labels;
    for (const IdUse* u : group) labels.push_back(fmt::format("{}[{}]", u->list, u->index));
    const std::string_view id = group.front()->id;
    report.add(make_diagnostic(
        Severity::error, Code::duplicate_id, {std::string(id)},
        fmt::format("id '{}' is used by {} objects ({}); ids must be unique in the plan.", id,
                    group.size(), fmt::join(labels, ", ")),
        fmt::format("rename all but one of them, e.g. {} to '{}-2'", labels[1], id)));
  }
}

}  // namespace

void check_ids(const Plan& plan, Usable& usable, Report& report) {
  report_duplicates(plan, report);
  check_level_references(plan, plan.walls, "wall", report);
  check_level_references(plan, plan.slabs, "slab", report);
  check_level_references(plan, plan.rooms, "room", report);
  const IdIndex walls = index_by_id(plan.walls);
  for (std::size_t i = 0; i < plan.openings.size(); ++i) {
    const Opening& o = plan.openings[i];
    const std::uint32_t found = walls.find(o.wall);
    if (found == walls.kNone) {
      usable.host[i].reset();
      report.add(make_diagnostic(
          Severity::error, Code::unknown_reference, {o.id},
          fmt::format("{} names wall '{}', which is not in the plan.", name_of(o), o.wall),
          plan.walls.empty() ? std::string("add the wall it belongs to, or delete the opening")
                             : fmt::format("set its wall to the id of an existing wall, e.g. '{}'",
                                           plan.walls.front().id)));
      continue;
    }
    if (usable.host[i] && usable.walls[found]) usable.host[i] = found;
    else usable.host[i].reset();
  }
}

}  // namespace roomcad::detail
