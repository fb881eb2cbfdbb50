// The --parts option that `build` and `render` share.
#pragma once

#include <string>

#include "modeling/build_model.h"

namespace roomcad::cli {

/// Parses `walls,floor,fixtures` (any subset, any order).
/// @return false on an unknown name (set in `bad`) or an empty list (`bad` = the list).
bool parse_parts(const std::string& list, Parts& parts, std::string& bad);

}  // namespace roomcad::cli
