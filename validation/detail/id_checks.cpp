// SPDX-License-Identifier: GPL-3.0-or-later
// duplicate_id (ids are unique across ALL objects of a plan) and unknown_reference.
#include <algorithm>
#include <string_view>
#include <unordered_map>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "modeling/plan_objects.h"
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

/// unknown_reference for each wall or slab whose `level` names no level.
template <class Object>
void check_level_references(const Plan& plan, const std::vector<Object>& objects,
                            std::string_view kind, Report& report) {
  for (const Object& o : objects) {
    if (o.level.empty() ||
        std::any_of(plan.levels.begin(), plan.levels.end(), [&](const Level& l) { return l.id == o.level; }))
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
  std::unordered_map<std::string_view, std::size_t> count;
  count.reserve(uses.size());
  for (const IdUse& u : uses) ++count[u.id];
  std::unordered_map<std::string_view, std::size_t> group_of;
  std::vector<std::vector<const IdUse*>> groups;
  for (const IdUse& u : uses) {
    if (count[u.id] < 2) continue;
    const auto [it, added] = group_of.emplace(u.id, groups.size());
    if (added) groups.emplace_back();
    groups[it->second].push_back(&u);
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
  std::unordered_map<std::string_view, std::size_t> walls;
  walls.reserve(plan.walls.size());
  for (std::size_t i = plan.walls.size(); i-- > 0;) walls[plan.walls[i].id] = i;  // first wins
  for (std::size_t i = 0; i < plan.openings.size(); ++i) {
    const Opening& o = plan.openings[i];
    const auto found = walls.find(o.wall);
    if (found == walls.end()) {
      usable.host[i].reset();
      report.add(make_diagnostic(
          Severity::error, Code::unknown_reference, {o.id},
          fmt::format("{} names wall '{}', which is not in the plan.", name_of(o), o.wall),
          plan.walls.empty()
              ? std::string("add the wall it belongs to, or delete the opening")
              : fmt::format("set its wall to the id of an existing wall, e.g. '{}'",
                            plan.walls.front().id)));
      continue;
    }
    if (usable.host[i] && usable.walls[found->second]) usable.host[i] = found->second;
    else usable.host[i].reset();
  }
}

}  // namespace roomcad::detail
