// SPDX-License-Identifier: GPL-3.0-or-later
// set_field: one field of one object from text, through the field tables
// (plan/plan_fields.h) and their text form (plan/field_text.h).
#include <fmt/format.h>

#include <algorithm>
#include <vector>

#include "plan/field_text.h"
#include "plan/nearest_name.h"
#include "plan/plan_edit.h"
#include "plan/plan_objects.h"

namespace roomcad {
namespace {

/// @return " (did you mean 'x'?)" for a near name, else " (fields: a, b, ...)".
std::string suggestion(const std::vector<std::string_view>& names, std::string_view key) {
  if (const auto nearest = nearest_name(key, names))
    return fmt::format(" (did you mean '{}'?)", *nearest);
  return fmt::format(" (fields: {})", fmt::join(names, ", "));
}

/// Sets `key` of `object` (not its id). @return whether the object changed, or a usage_error
/// for an unknown field or a value of the wrong type (the object unchanged).
template <class Object>
Result<bool> set_in(Object& object, std::string_view what, std::string_view key,
                    std::string_view value, std::string_view verb) {
  const Field<Object>* field = find_field<Object>(key);
  if (field == nullptr)
    return Result<bool>::failure(Code::usage_error,
                                 fmt::format("{}: {} has no field '{}'{}", verb, what, key,
                                             suggestion(field_names_of<Object>(), key)));
  const Object old = object;
  if (const Status set = set_field_text(object, *field, value, verb, what); !set)
    return set.error();
  return object != old;
}

/// Points every reference to `old_id` (a wall's openings, a level's walls and slabs) at
/// `new_id`. @return the ids of the objects changed.
std::vector<std::string> follow_rename(Plan& plan, ObjectKind kind, std::string_view old_id,
                                       std::string_view new_id) {
  std::vector<std::string> changed;
  auto retarget = [&](auto& objects, auto member) {
    for (auto& o : objects) {
      if (o.*member != old_id) continue;
      o.*member = new_id;
      changed.push_back(o.id);
    }
  };
  if (kind == ObjectKind::wall) retarget(plan.openings, &Opening::wall);
  if (kind == ObjectKind::level) {
    retarget(plan.walls, &Wall::level);
    retarget(plan.slabs, &Slab::level);
  }
  return changed;
}

/// Renames an object and what refers to it. @return the ids changed, or why the new id is
/// refused (empty, or another object's).
Result<std::vector<std::string>> rename(Plan& plan, ObjectRef ref, std::string_view new_id,
                                        std::string_view verb) {
  std::string& id = id_of(plan, ref);
  if (new_id.empty())
    return Result<std::vector<std::string>>::failure(
        Code::usage_error, fmt::format("{}: {} '{}' field 'id' wants a non-empty id, got ''", verb,
                                       kind_name(plan, ref), id));
  if (new_id == id) return std::vector<std::string>{};
  if (const Status unused = check_unused_id(plan, new_id, verb); !unused) return unused.error();
  std::vector<std::string> changed{std::string(new_id)};
  for (std::string& other : follow_rename(plan, ref.kind, id, new_id)) changed.push_back(other);
  id = new_id;
  return changed;
}

}  // namespace

Result<EditSummary> set_field(Plan& plan, std::string_view id, std::string_view key,
                              std::string_view value, std::string_view verb) {
  EditSummary summary;
  const auto ref = find_object(plan, id);
  if (!ref && id == "site") {
    const Result<bool> changed = set_in(plan.site, "the site", key, value, verb);
    if (!changed) return changed.error();
    if (*changed) summary.changed.push_back("site");
    return summary;
  }
  const Result<ObjectRef> object = lookup_object(plan, id, verb);
  if (!object) return object.error();
  if (key == "id") {
    Result<std::vector<std::string>> renamed = rename(plan, *object, value, verb);
    if (!renamed) return renamed.error();
    summary.changed = std::move(renamed).value();
    return summary;
  }
  const std::string what = fmt::format("{} '{}'", kind_name(plan, *object), id);
  const Result<bool> changed =
      visit_object(plan, *object, [&](auto& o) { return set_in(o, what, key, value, verb); });
  if (!changed) return changed.error();
  if (*changed) summary.changed.push_back(std::string(id));
  return summary;
}

std::vector<std::string_view> field_names(std::string_view kind) {
  if (kind == "site") return field_names_of<Site>();
  if (kind == "level") return field_names_of<Level>();
  if (kind == "wall") return field_names_of<Wall>();
  if (kind == "door" || kind == "window") return field_names_of<Opening>();
  if (kind == "slab") return field_names_of<Slab>();
  if (kind == "obstruction") return field_names_of<Obstruction>();
  if (kind == "room") return field_names_of<RoomLabel>();
  if (kind == "light") return field_names_of<Light>();
  if (kind == "camera") return field_names_of<Camera>();
  return {};
}

}  // namespace roomcad
