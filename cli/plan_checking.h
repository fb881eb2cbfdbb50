// SPDX-License-Identifier: GPL-3.0-or-later
// A plan file checked as `roomcad validate` checks it: what `validate` prints and `report`
// shows.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/error.h"
#include "plan/plan.h"
#include "validation/report.h"
#include "validation/rule_set.h"

namespace roomcad::cli {

/// A plan's findings, the level of each (item_levels), and the plan where it could be read.
struct CheckedPlan {
  Report report;
  std::vector<std::string> levels;  ///< empty where the plan was not read
  std::optional<Plan> plan;
};

/// Reading problems (with their lines and columns) then, if the plan could be read, what
/// validation and the rules find (io/plan_check.h), the insolation rule's included
/// (daylight/insolation_rule.h).
/// @return the findings, or an error: the file cannot be read, or the rules name rooms the
///         plan does not have.
[[nodiscard]] Result<CheckedPlan> check_plan_file(const std::string& path, const RuleSet& rules);

/// @return the error of a command that needs the plan itself when the file at `path` could not
///         be read as one: "PATH is not a plan (N problems: `roomcad validate PATH` lists
///         them)", prefixed by `context` ("--format bcf: ").
[[nodiscard]] Error not_a_plan(const CheckedPlan& checked, const std::string& path,
                               std::string_view context = {});

}  // namespace roomcad::cli
