// SPDX-License-Identifier: GPL-3.0-or-later
// The stable identifiers roomcad gives the things it writes for BIM tools: an IFC object's
// GlobalId (the same in every export of the plan) and a GUID for each finding (the same in
// every revision where the finding stays), so that a BCF topic names the objects of the IFC
// export and follows its issue across revisions.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "plan/plan.h"

namespace roomcad {

/// @return the 22-character IFC GlobalId (IFC's base 64) of `key`: 128 bits of hash, so the
///         same key always gives the same id. O(key).
[[nodiscard]] std::string ifc_global_id(std::string_view key);

/// @return the GlobalId of the IfcRoot that `roomcad build -o x.ifc` writes for the plan
///         object `id` (IfcWall, IfcDoor, IfcWindow, IfcSlab), or nullopt for an id that is
///         none of those (a level, a room's name, a light). O(objects).
[[nodiscard]] std::optional<std::string> ifc_global_id_of(const Plan& plan, std::string_view id);

/// @return a GUID in the 8-4-4-4-12 lower-case hexadecimal form of BCF, 128 bits of hash of
///         `key`. O(key).
[[nodiscard]] std::string hashed_guid(std::string_view key);

}  // namespace roomcad
