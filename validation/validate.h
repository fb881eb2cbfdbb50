// Validation of a plan: every error code and warning of docs/plan-format.md, all
// problems in one run, verdicts exact for the coordinates as read.
#pragma once

#include <vector>

#include "modeling/plan.h"
#include "modeling/rooms.h"  // find_rooms, once here
#include "validation/report.h"

namespace roomcad {

struct ValidateOptions {
  bool room_warnings = true;  ///< find rooms and warn about rooms with no door or no window
  /// warn about the fields kept in `extra`; the plan reader already reports them (with line
  /// and column), so commands that read a file turn this off.
  bool unknown_field_warnings = true;
};

/// Checks a plan. Never throws on any Plan value (NaN, negative sizes, dangling references
/// are reported, not assumed away). Cost O(n log n + k) for n objects and k nearby pairs.
[[nodiscard]] Report validate(const Plan& plan, const ValidateOptions& options = {});

}  // namespace roomcad
