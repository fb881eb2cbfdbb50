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
template <class Object>
Object build(std::vector<Object> Plan::*list, Object object, const std::string& id,
             const FieldValues& given) {
  Plan scratch;
  object.id = id.empty() ? "new" : id;
  (scratch.*list).push_back(std::move(object));
  for (const auto& [key, value] : given) set_field(scratch, (scratch.*list)[0].id, key, value, "add");
  Object built = std::move((scratch.*list)[0]);
  built.id = id;  // empty: add_* generates one
  return built;
}

/// @throws PreconditionError (usage_error) unless `given` holds only fields of the kind and
///         every required one.
void check_fields(std::string_view kind, const FieldValues& given) {
  const std::vector<std::string_view> allowed = settable_fields(kind);
  for (const auto& [key, value] : given) {
    if (std::find(allowed.begin(), allowed.end(), key) == allowed.end())
      throw PreconditionError(fmt::format("add: a {} has no field '{}' (it takes: {})", kind, key,
                                          fmt::join(allowed, ", ")),
                              Code::usage_error);
  }
  for (const std::string_view key : required_fields(kind)) {
    if (std::none_of(given.begin(), given.end(), [&](const auto& g) { return g.first == key; }))
      throw PreconditionError(fmt::format("add: a {} needs its field '{}'", kind, key),
                              Code::usage_error);
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

EditSummary add_object(Plan& plan, std::string_view kind, const std::string& id,
                       const FieldValues& fields) {
  if (std::find(std::begin(kAddableKinds), std::end(kAddableKinds), kind) == std::end(kAddableKinds))
    throw PreconditionError(fmt::format("add: no kind of object is called '{}' (kinds: {})", kind,
                                        fmt::join(kAddableKinds, ", ")),
                            Code::usage_error);
  check_fields(kind, fields);
  if (kind == "level") return add_level(plan, build(&Plan::levels, Level{}, id, fields));
  if (kind == "wall") return add_wall(plan, build(&Plan::walls, Wall{}, id, fields));
  if (kind == "slab") return add_slab(plan, build(&Plan::slabs, Slab{}, id, fields));
  if (kind == "light") return add_light(plan, build(&Plan::lights, Light{}, id, fields));
  if (kind == "camera") return add_camera(plan, build(&Plan::cameras, Camera{}, id, fields));
  const Opening base = default_opening(*parse_enum<OpeningType>(kind));
  return add_opening(plan, build(&Plan::openings, base, id, fields));
}

}  // namespace roomcad
