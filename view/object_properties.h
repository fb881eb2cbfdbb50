// What the window shows about the selected object: its kind, id and fields, one per line.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "modeling/plan.h"

namespace roomcad {

/// @return "wall w1" then lines such as "from 1, 1  to 5, 1 m" and "thickness 0.25 m"; empty
///         if no object has the id. Numbers are shortest round-trip decimals. O(n) in objects.
[[nodiscard]] std::vector<std::string> describe_object(const Plan& plan, std::string_view id);

}  // namespace roomcad
