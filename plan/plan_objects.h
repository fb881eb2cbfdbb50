// SPDX-License-Identifier: GPL-3.0-or-later
// A plan's objects by id, of every kind: finding, naming, visiting with their own type, erasing.
// What the edit functions (plan/plan_edit.h), the window and the bindings build on.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/error.h"
#include "plan/plan.h"

namespace roomcad {

enum class ObjectKind { level, wall, opening, slab, obstruction, room, light, camera };

/// "level", "wall", "opening", ...: the kind in messages (an opening's own type is kind_name's).
[[nodiscard]] std::string_view to_string(ObjectKind kind);

/// "levels", "walls", "openings", ...: the kind's list in the plan file.
[[nodiscard]] std::string_view list_name(ObjectKind kind);

/// Opening indices by host wall: per wall index, the openings naming the wall, in plan order.
/// Where walls share an id, the first of them hosts (as validation reads a plan); an opening
/// naming no wall is in no list. O(walls + openings) expected.
using OpeningsByWall = std::vector<std::vector<std::size_t>>;
[[nodiscard]] OpeningsByWall openings_by_wall(const Plan& plan);

/// An object of a plan: which vector, which index.
struct ObjectRef {
  ObjectKind kind = ObjectKind::wall;
  std::size_t index = 0;
};

/// Calls `visit(objects, kind)` for each list of objects of the plan, in file order (levels,
/// walls, openings, slabs, obstructions, rooms, lights, cameras); `PlanType` may be const.
template <class PlanType, class Visit>
void for_each_list(PlanType& plan, Visit&& visit) {
  visit(plan.levels, ObjectKind::level);
  visit(plan.walls, ObjectKind::wall);
  visit(plan.openings, ObjectKind::opening);
  visit(plan.slabs, ObjectKind::slab);
  visit(plan.obstructions, ObjectKind::obstruction);
  visit(plan.rooms, ObjectKind::room);
  visit(plan.lights, ObjectKind::light);
  visit(plan.cameras, ObjectKind::camera);
}

/// Calls `visit(object)` on the object `ref` names, with its own type.
template <class PlanType, class Visit>
decltype(auto) visit_object(PlanType& plan, ObjectRef ref, Visit&& visit) {
  switch (ref.kind) {
    case ObjectKind::level: return visit(plan.levels[ref.index]);
    case ObjectKind::wall: return visit(plan.walls[ref.index]);
    case ObjectKind::opening: return visit(plan.openings[ref.index]);
    case ObjectKind::slab: return visit(plan.slabs[ref.index]);
    case ObjectKind::obstruction: return visit(plan.obstructions[ref.index]);
    case ObjectKind::room: return visit(plan.rooms[ref.index]);
    case ObjectKind::light: return visit(plan.lights[ref.index]);
    case ObjectKind::camera: break;
  }
  return visit(plan.cameras[ref.index]);
}

/// @return the first object with this id, or nullopt. O(n).
[[nodiscard]] std::optional<ObjectRef> find_object(const Plan& plan, std::string_view id);

/// @return the object with this id, or a precondition error "<verb>: no object has id '<id>'"
///         naming a few existing ids. O(n).
[[nodiscard]] Result<ObjectRef> lookup_object(const Plan& plan, std::string_view id,
                                              std::string_view verb);

/// lookup_object for callers whose precondition is that the id exists.
/// @throws PreconditionError with lookup_object's error.
[[nodiscard]] ObjectRef require_object(const Plan& plan, std::string_view id,
                                       std::string_view verb);

/// @return "level", "wall", "door", "window", "slab", "obstruction", "room", "light" or
///         "camera".
[[nodiscard]] std::string_view kind_name(const Plan& plan, ObjectRef ref);

/// @return a reference to the id string of the object.
[[nodiscard]] std::string& id_of(Plan& plan, ObjectRef ref);

/// Erases the object `ref` names (later indices of its list shift down by one).
void erase_object(Plan& plan, ObjectRef ref);

/// @return success, or a precondition error "<verb>: id '<id>' is already used by <kind>
///         '<id>'" if it is. O(n).
[[nodiscard]] Status check_unused_id(const Plan& plan, std::string_view id, std::string_view verb);

/// check_unused_id for callers whose precondition is a new id.
/// @throws PreconditionError with check_unused_id's error.
void require_unused_id(const Plan& plan, std::string_view id, std::string_view verb);

}  // namespace roomcad
