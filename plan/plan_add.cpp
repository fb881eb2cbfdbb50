// SPDX-License-Identifier: GPL-3.0-or-later
#include "plan/plan_add.h"

#include <algorithm>
#include <type_traits>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "plan/plan_fields.h"
#include "plan/value_text.h"

namespace roomcad {
namespace {

/// Builds the object in a scratch plan (so set_field type-checks every value), then takes it.
/// @return the object, or the first value set_field refuses.
template <class Object>
Result<Object> build(std::vector<Object> Plan::*list, Object object, const std::string& id,
                     const FieldValues& given) {
  Plan scratch;
  object.id = id.empty() ? "new" : id;
  (scratch.*list).push_back(std::move(object));
  for (const auto& [key, value] : given)
    if (const auto set = set_field(scratch, (scratch.*list)[0].id, key, value, "add"); !set)
      return set.error();
  Object built = std::move((scratch.*list)[0]);
  built.id = id;  // empty: add_* generates one
  return built;
}

/// @return success, or a usage_error unless `given` holds only fields of the kind and every
///         required one.
Status check_fields(std::string_view kind, const FieldValues& given) {
  const std::vector<std::string_view> allowed = settable_fields(kind);
  for (const auto& [key, value] : given) {
    if (std::find(allowed.begin(), allowed.end(), key) == allowed.end())
      return Status::failure(Code::usage_error,
                             fmt::format("add: a {} has no field '{}' (it takes: {})", kind, key,
                                         fmt::join(allowed, ", ")));
  }
  for (const std::string_view key : required_fields(kind)) {
    if (std::none_of(given.begin(), given.end(), [&](const auto& g) { return g.first == key; }))
      return Status::failure(Code::usage_error,
                             fmt::format("add: a {} needs its field '{}'", kind, key));
  }
  return Status::success();
}

/// Builds the object and adds it with `add` (add_wall ... add_camera, whose refusals of an id
/// or a reference come back as their Error).
template <class Object, class Add>
Result<EditSummary> build_and_add(Plan& plan, std::vector<Object> Plan::*list, Object base,
                                  const std::string& id, const FieldValues& given, Add&& add) {
  Result<Object> built = build(list, std::move(base), id, given);
  if (!built) return built.error();
  try {
    return add(plan, std::move(built).value());
  } catch (const PreconditionError& e) {
    return e.error();
  }
}

}  // namespace

std::vector<std::string_view> settable_fields(std::string_view kind) {
  std::vector<std::string_view> names = field_names(kind);
  std::erase_if(names, [](std::string_view n) { return n == "id" || n == "type"; });
  return names;
}

std::vector<std::string_view> required_fields(std::string_view kind) {
  return with_default_object(kind, [](const auto& object) {
    std::vector<std::string_view> names;
    for (const auto& f : fields_of<std::decay_t<decltype(object)>>())
      if (f.presence == Presence::required && f.name != "id") names.push_back(f.name);
    return names;
  });
}

Result<EditSummary> add_object(Plan& plan, std::string_view kind, const std::string& id,
                               const FieldValues& fields) {
  if (std::find(std::begin(kAddableKinds), std::end(kAddableKinds), kind) ==
      std::end(kAddableKinds))
    return Result<EditSummary>::failure(
        Code::usage_error, fmt::format("add: no kind of object is called '{}' (kinds: {})", kind,
                                       fmt::join(kAddableKinds, ", ")));
  if (const Status checked = check_fields(kind, fields); !checked) return checked.error();
  if (kind == "level") return build_and_add(plan, &Plan::levels, Level{}, id, fields, add_level);
  if (kind == "wall") return build_and_add(plan, &Plan::walls, Wall{}, id, fields, add_wall);
  if (kind == "slab") return build_and_add(plan, &Plan::slabs, Slab{}, id, fields, add_slab);
  if (kind == "obstruction")
    return build_and_add(plan, &Plan::obstructions, Obstruction{}, id, fields, add_obstruction);
  if (kind == "room") return build_and_add(plan, &Plan::rooms, RoomLabel{}, id, fields, add_room);
  if (kind == "light") return build_and_add(plan, &Plan::lights, Light{}, id, fields, add_light);
  if (kind == "camera")
    return build_and_add(plan, &Plan::cameras, Camera{}, id, fields, add_camera);
  const Opening base = default_opening(*parse_enum<OpeningType>(kind));
  return build_and_add(plan, &Plan::openings, base, id, fields, add_opening);
}

}  // namespace roomcad
