// SPDX-License-Identifier: GPL-3.0-or-later
#include "plan/plan_objects.h"

#include <fmt/format.h>

#include <vector>

#include "core/error.h"
#include "core/flat_index.h"

namespace roomcad {
namespace {

/// @return up to `most` ids of the plan, comma separated, for "did you mean" style messages.
std::string some_ids(const Plan& plan, std::size_t most) {
  std::vector<std::string_view> ids;
  for_each_list(plan, [&](const auto& objects, ObjectKind) {
    for (const auto& o : objects) ids.push_back(o.id);
  });
  if (ids.empty()) return "the plan has no objects";
  const bool cut = ids.size() > most;
  if (cut) ids.resize(most);
  return fmt::format("ids: {}{}", fmt::join(ids, ", "), cut ? ", ..." : "");
}

}  // namespace

std::optional<ObjectRef> find_object(const Plan& plan, std::string_view id) {
  std::optional<ObjectRef> found;
  for_each_list(plan, [&](const auto& objects, ObjectKind kind) {
    for (std::size_t i = 0; i < objects.size() && !found; ++i)
      if (objects[i].id == id) found = ObjectRef{kind, i};
  });
  return found;
}

Result<ObjectRef> lookup_object(const Plan& plan, std::string_view id, std::string_view verb) {
  if (const auto ref = find_object(plan, id)) return *ref;
  return Result<ObjectRef>::failure(
      Code::precondition,
      fmt::format("{}: no object has id '{}' ({})", verb, id, some_ids(plan, 8)));
}

ObjectRef require_object(const Plan& plan, std::string_view id, std::string_view verb) {
  Result<ObjectRef> found = lookup_object(plan, id, verb);
  if (!found) throw PreconditionError(found.error());
  return found.value();
}

std::string_view to_string(ObjectKind kind) {
  switch (kind) {
    case ObjectKind::level: return "level";
    case ObjectKind::wall: return "wall";
    case ObjectKind::opening: return "opening";
    case ObjectKind::slab: return "slab";
    case ObjectKind::obstruction: return "obstruction";
    case ObjectKind::room: return "room";
    case ObjectKind::light: return "light";
    case ObjectKind::camera: break;
  }
  return "camera";
}

std::string_view list_name(ObjectKind kind) {
  switch (kind) {
    case ObjectKind::level: return "levels";
    case ObjectKind::wall: return "walls";
    case ObjectKind::opening: return "openings";
    case ObjectKind::slab: return "slabs";
    case ObjectKind::obstruction: return "obstructions";
    case ObjectKind::room: return "rooms";
    case ObjectKind::light: return "lights";
    case ObjectKind::camera: break;
  }
  return "cameras";
}

std::string_view kind_name(const Plan& plan, ObjectRef ref) {
  if (ref.kind == ObjectKind::opening) return to_string(plan.openings[ref.index].type);
  return to_string(ref.kind);
}

std::string& id_of(Plan& plan, ObjectRef ref) {
  return visit_object(plan, ref, [](auto& object) -> std::string& { return object.id; });
}

void erase_object(Plan& plan, ObjectRef ref) {
  const auto at = static_cast<std::ptrdiff_t>(ref.index);
  switch (ref.kind) {
    case ObjectKind::level: plan.levels.erase(plan.levels.begin() + at); return;
    case ObjectKind::wall: plan.walls.erase(plan.walls.begin() + at); return;
    case ObjectKind::opening: plan.openings.erase(plan.openings.begin() + at); return;
    case ObjectKind::slab: plan.slabs.erase(plan.slabs.begin() + at); return;
    case ObjectKind::obstruction: plan.obstructions.erase(plan.obstructions.begin() + at); return;
    case ObjectKind::room: plan.rooms.erase(plan.rooms.begin() + at); return;
    case ObjectKind::light: plan.lights.erase(plan.lights.begin() + at); return;
    case ObjectKind::camera: plan.cameras.erase(plan.cameras.begin() + at); return;
  }
}

Status check_unused_id(const Plan& plan, std::string_view id, std::string_view verb) {
  if (const auto ref = find_object(plan, id))
    return Status::failure(Code::precondition, fmt::format("{}: id '{}' is already used by {} '{}'",
                                                           verb, id, kind_name(plan, *ref), id));
  return Status::success();
}

void require_unused_id(const Plan& plan, std::string_view id, std::string_view verb) {
  if (const Status unused = check_unused_id(plan, id, verb); !unused)
    throw PreconditionError(unused.error());
}

OpeningsByWall openings_by_wall(const Plan& plan) {
  const IdIndex wall_index = index_by_id(plan.walls);
  OpeningsByWall out(plan.walls.size());
  for (std::size_t i = 0; i < plan.openings.size(); ++i)
    if (const std::uint32_t w = wall_index.find(plan.openings[i].wall); w != wall_index.kNone)
      out[w].push_back(i);
  return out;
}

}  // namespace roomcad
