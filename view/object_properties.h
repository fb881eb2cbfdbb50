// SPDX-License-Identifier: GPL-3.0-or-later
// What the window shows about the selected object: its kind, id and fields, one per line.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "plan/plan.h"

namespace roomcad {

/// @return "wall w1" then one line per field, from its field table (plan/plan_fields.h),
///         as `roomcad set` takes it: "from 1,1 m", "thickness 0.25 m", "color #e8e2d0"; empty
///         if no object has the id. Numbers are shortest round-trip decimals. O(n) in objects.
[[nodiscard]] std::vector<std::string> describe_object(const Plan& plan, std::string_view id);

}  // namespace roomcad
