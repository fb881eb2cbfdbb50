// Finding a plan's objects by id, for the edit functions (modeling/plan_edit.h).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include "modeling/plan.h"

namespace roomcad::detail {

enum class ObjectKind { wall, opening, light, camera };

/// An object of a plan: which vector, which index.
struct ObjectRef {
  ObjectKind kind = ObjectKind::wall;
  std::size_t index = 0;
};

/// @return the first object with this id, or nullopt. O(n).
[[nodiscard]] std::optional<ObjectRef> find_object(const Plan& plan, std::string_view id);

/// @return the object with this id.
/// @throws PreconditionError "<verb>: no object has id '<id>'" naming a few existing ids.
[[nodiscard]] ObjectRef require_object(const Plan& plan, std::string_view id,
                                       std::string_view verb);

/// @return "wall", "door", "window", "light" or "camera".
[[nodiscard]] std::string_view kind_name(const Plan& plan, ObjectRef ref);

/// @return a reference to the id string of the object.
[[nodiscard]] std::string& id_of(Plan& plan, ObjectRef ref);

/// @throws PreconditionError "<verb>: id '<id>' is already used by <kind> '<id>'" if it is.
void require_unused_id(const Plan& plan, std::string_view id, std::string_view verb);

}  // namespace roomcad::detail
