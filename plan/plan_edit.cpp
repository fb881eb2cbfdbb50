// SPDX-License-Identifier: GPL-3.0-or-later
// Adding and removing objects; ids. Transforms are in plan_transform_edit.cpp, fields in
// plan_set_field.cpp.
#include "plan/plan_edit.h"

#include <fmt/format.h>

#include <algorithm>
#include <utility>

#include "plan/plan_objects.h"

namespace roomcad {
namespace {

/// Gives `id` a generated value when empty, else checks it is free; @return the final id.
std::string claim_id(const Plan& plan, std::string id, std::string_view prefix) {
  if (id.empty()) return generate_id(plan, prefix);
  require_unused_id(plan, id, "add");
  return id;
}

/// Appends `object` (id claimed) to `objects`; @return the summary of an addition.
template <class Object>
EditSummary append_object(const Plan& plan, std::vector<Object>& objects, Object object,
                          std::string_view prefix) {
  object.id = claim_id(plan, std::move(object.id), prefix);
  EditSummary summary;
  summary.added.push_back(object.id);
  objects.push_back(std::move(object));
  return summary;
}

}  // namespace

std::optional<std::string_view> object_kind(const Plan& plan, std::string_view id) {
  const auto ref = find_object(plan, id);
  if (!ref) return std::nullopt;
  return kind_name(plan, *ref);
}

std::string generate_id(const Plan& plan, std::string_view prefix) {
  for (std::size_t n = 1;; ++n) {
    std::string id = fmt::format("{}-{}", prefix, n);
    if (!find_object(plan, id)) return id;
  }
}

std::vector<std::string> dependent_objects(const Plan& plan, std::string_view id) {
  std::vector<std::string> ids;
  auto add_openings_of = [&](std::string_view wall) {
    for (const Opening& o : plan.openings)
      if (o.wall == wall) ids.push_back(o.id);
  };
  add_openings_of(id);
  for (const Wall& w : plan.walls) {
    if (w.level != id || w.level.empty()) continue;
    ids.push_back(w.id);
    add_openings_of(w.id);
  }
  for (const Slab& s : plan.slabs)
    if (s.level == id && !s.level.empty()) ids.push_back(s.id);
  return ids;
}

Opening default_opening(OpeningType type) {
  const OpeningDefaults d = opening_defaults(type);
  Opening opening;
  opening.type = type;
  opening.width = d.width;
  opening.height = d.height;
  opening.sill = d.sill;
  return opening;
}

EditSummary add_wall(Plan& plan, Wall wall) {
  return append_object(plan, plan.walls, std::move(wall), "wall");
}

EditSummary add_opening(Plan& plan, Opening opening) {
  if (!find_wall(plan, opening.wall))
    throw PreconditionError(
        fmt::format("add: {} '{}' names wall '{}', and the plan has no such wall",
                    to_string(opening.type), opening.id, opening.wall));
  const std::string_view prefix = to_string(opening.type);
  return append_object(plan, plan.openings, std::move(opening), prefix);
}

EditSummary add_level(Plan& plan, Level level) {
  return append_object(plan, plan.levels, std::move(level), "level");
}

/// @throws PreconditionError if `object` names a level the plan does not have.
template <class Object>
void require_known_level(const Plan& plan, const Object& object, std::string_view kind) {
  if (!object.level.empty() && std::none_of(plan.levels.begin(), plan.levels.end(),
                                            [&](const Level& l) { return l.id == object.level; }))
    throw PreconditionError(
        fmt::format("add: {} '{}' names level '{}', and the plan has no "
                    "such level",
                    kind, object.id, object.level));
}

EditSummary add_slab(Plan& plan, Slab slab) {
  require_known_level(plan, slab, "slab");
  return append_object(plan, plan.slabs, std::move(slab), "slab");
}

EditSummary add_room(Plan& plan, RoomLabel room) {
  require_known_level(plan, room, "room");
  return append_object(plan, plan.rooms, std::move(room), "room");
}

EditSummary add_obstruction(Plan& plan, Obstruction obstruction) {
  return append_object(plan, plan.obstructions, std::move(obstruction), "obstruction");
}

EditSummary add_light(Plan& plan, Light light) {
  return append_object(plan, plan.lights, std::move(light), "light");
}

EditSummary add_camera(Plan& plan, Camera camera) {
  return append_object(plan, plan.cameras, std::move(camera), "camera");
}

EditSummary remove_object(Plan& plan, std::string_view id, const RemoveOptions& options) {
  const ObjectRef ref = require_object(plan, id, "rm");
  std::vector<std::string> dependents = dependent_objects(plan, id);
  if (!dependents.empty() && !options.cascade)
    throw PreconditionError(
        fmt::format("{} '{}' has {} ({}); --cascade removes them too", kind_name(plan, ref), id,
                    ref.kind == ObjectKind::wall ? "openings" : "objects on it",
                    fmt::join(dependents, ", ")),
        Code::edit_refused);
  EditSummary summary;
  summary.removed.push_back(std::string(id));
  summary.removed.insert(summary.removed.end(), dependents.begin(), dependents.end());
  // The object itself by its index (a plan being repaired may hold its id twice), then what
  // depends on it: never in the same list, so the index still holds.
  erase_object(plan, ref);
  auto depends = [&](const auto& o) {
    return std::find(dependents.begin(), dependents.end(), o.id) != dependents.end();
  };
  for_each_list(plan, [&](auto& objects, ObjectKind) { std::erase_if(objects, depends); });
  return summary;
}

}  // namespace roomcad
