// What `build` and `render` share between reading a plan and building its model: the --parts
// list and the validation gate.
#pragma once

#include <string>
#include <string_view>

#include "modeling/build_model.h"
#include "modeling/plan.h"

namespace roomcad::cli {

/// Parses `walls,floor,fixtures` (any subset, any order).
/// @return false on an unknown name (set in `bad`) or an empty list (`bad` = the list).
bool parse_parts(const std::string& list, Parts& parts, std::string& bad);

/// The validation gate: validates the plan and prints its problems (warnings too) to stderr;
/// errors stop `command` unless `force`. @return whether the command may go on. O(validate).
bool passes_validation(std::string_view command, const std::string& plan_path, const Plan& plan,
                       bool force);

}  // namespace roomcad::cli
