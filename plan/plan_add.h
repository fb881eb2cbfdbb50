// SPDX-License-Identifier: GPL-3.0-or-later
// Adding an object of any kind from its fields as text: what `roomcad add` and the Python
// module's Plan.add share. Each value is type-checked by set_field (plan/plan_edit.h),
// through the field tables (plan/plan_fields.h).
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "plan/plan.h"
#include "plan/plan_edit.h"

namespace roomcad {

/// The kinds of object add_object adds, in the order help lists them.
inline constexpr std::string_view kAddableKinds[] = {
    "level", "wall", "door", "window", "slab", "obstruction", "room", "light", "camera"};

/// A field of a new object, as text: (name, value), e.g. ("from", "1,2").
using FieldValues = std::vector<std::pair<std::string, std::string>>;

/// Calls visit(Object{}) with a default object of `kind` (one of kAddableKinds; "door" and
/// "window": an Opening, an unknown kind: a Camera). @return what visit returns.
template <class Visit>
decltype(auto) with_default_object(std::string_view kind, Visit&& visit) {
  if (kind == "level") return visit(Level{});
  if (kind == "wall") return visit(Wall{});
  if (kind == "door" || kind == "window") return visit(Opening{});
  if (kind == "slab") return visit(Slab{});
  if (kind == "obstruction") return visit(Obstruction{});
  if (kind == "room") return visit(RoomLabel{});
  if (kind == "light") return visit(Light{});
  return visit(Camera{});
}

/// @return the fields a new object of `kind` may be given (all but id and type), file order.
[[nodiscard]] std::vector<std::string_view> settable_fields(std::string_view kind);

/// @return the fields a new object of `kind` cannot do without (the others have the format's
///         defaults), its id aside.
[[nodiscard]] std::vector<std::string_view> required_fields(std::string_view kind);

/// Adds an object of `kind` (one of kAddableKinds) with these fields, the others at the
/// format's defaults (a door's or window's width, height and sill: default_opening). An empty
/// `id` is generated (`wall-3`). Whether the plan stays valid is the caller's to judge.
/// @return what was added; or a usage_error naming the kind and field for an unknown kind, a
///         field the kind does not have, a missing required field or a value of the wrong type;
///         or add_wall's ... add_camera's error for a used id or an unknown wall or level. The
///         plan is unchanged then. Never throws for its input. Cost O(n) in the plan's objects.
[[nodiscard]] Result<EditSummary> add_object(Plan& plan, std::string_view kind,
                                             const std::string& id, const FieldValues& fields);

}  // namespace roomcad
