// SPDX-License-Identifier: GPL-3.0-or-later
// Which parts of a plan's model to build, draw or write (walls, slabs, floor, fixtures), and
// the --parts list that names them.
#pragma once

#include <string_view>

#include "core/error.h"

namespace roomcad {

/// Which parts of the model to build.
struct Parts {
  bool walls = true;
  bool floor = true;
  bool fixtures = true;
  bool slabs = true;  ///< built into one solid with the walls (Model::walls)
};

/// The names parse_parts knows, for messages and help.
inline constexpr const char* kPartNames = "walls, slabs, floor, fixtures";
/// Every part, as a --parts list (the default).
inline constexpr const char* kAllParts = "walls,slabs,floor,fixtures";

/// Parses a --parts list: names of kPartNames separated by commas, any subset in any order.
/// @return the parts, or a usage_error naming the list and the first unknown (or empty) name.
[[nodiscard]] Result<Parts> parse_parts(std::string_view list);

}  // namespace roomcad
