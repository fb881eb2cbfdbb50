// SPDX-License-Identifier: GPL-3.0-or-later
// Validation of a plan: every error code and warning of docs/plan-format.md, all
// problems in one run, verdicts exact for the coordinates as read.
#pragma once

#include <vector>

#include "geometry/rooms.h"  // find_rooms, once here
#include "plan/plan.h"
#include "validation/report.h"
#include "validation/rule_set.h"

namespace roomcad {

struct ValidateOptions {
  bool room_warnings = true;  ///< find rooms and warn about rooms with no door or no window
  /// warn about the fields kept in `extra`; the plan reader already reports them (with line
  /// and column), so commands that read a file turn this off.
  bool unknown_field_warnings = true;
  /// The rules beyond the plan format's checks (validation/rule_set.h); the default set has
  /// none. Rule findings are warnings unless the set says "error" for a rule. ({}: may be left
  /// out of designated initializers without a warning.)
  RuleSet rules{};
};

/// Checks a plan. Never throws on any Plan value (NaN, negative sizes, dangling references
/// are reported, not assumed away). Cost O(n log n + k) for n objects and k nearby pairs,
/// plus the rules' searches (each finding's fix is tried near it).
[[nodiscard]] Report validate(const Plan& plan, const ValidateOptions& options = {});

}  // namespace roomcad
