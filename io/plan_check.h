// SPDX-License-Identifier: GPL-3.0-or-later
// The report `roomcad validate` prints for a plan: what reading found (with lines and columns),
// then what validation finds, errors first. Shared by the command and the Python module, so
// that both give the same findings in the same order.
#pragma once

#include <string>

#include "plan/plan.h"
#include "validation/report.h"
#include "validation/rule_set.h"

namespace roomcad {

/// @param[in] reading  what reading the plan's text found (unknown fields, with their places),
///                     or nullptr for a plan made in memory (then validation reports its
///                     unknown fields, without places)
/// @param[in] rules    the rules beyond the format's checks (`validate --rules`); default: none
/// @pre check_accessible_rooms(plan, rules) succeeds (the rooms a rules file names exist)
/// @return the reading report (if any) then validate()'s findings, errors before warnings,
///         each group in the order found. Never throws. Cost as validate().
[[nodiscard]] Report check_plan(const Plan& plan, const Report* reading, const RuleSet& rules = {});

/// Reads `text` (named `file` in locations) and checks the plan it holds with check_plan; a
/// text that is not a plan gives its reading errors only.
[[nodiscard]] Report check_plan_text(const std::string& text, const std::string& file);

}  // namespace roomcad
