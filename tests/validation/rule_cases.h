// SPDX-License-Identifier: GPL-3.0-or-later
// Helpers for the rule sets' tests: run one rule, pick its findings, apply a finding's fix and
// check that the finding is gone and no error came with it.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "plan_cases.h"
#include "validation/fix_edits.h"
#include "validation/report_diff.h"
#include "validation/rule_set.h"
#include "validation/validate.h"

namespace roomcad::testing {

/// @return the rule set with only `codes` enabled (default thresholds).
inline RuleSet only(std::initializer_list<Code> codes) {
  RuleSet rules;
  for (const Code c : codes) rules.enabled[*rule_index(c)] = true;
  return rules;
}

/// @return validate(plan) with the rules.
inline Report check(const Plan& plan, const RuleSet& rules) {
  ValidateOptions options;
  options.rules = rules;
  return validate(plan, options);
}

/// @return the findings of `code` in the report.
inline std::vector<Diagnostic> findings(const Report& report, Code code) {
  std::vector<Diagnostic> out;
  std::copy_if(report.items.begin(), report.items.end(), std::back_inserter(out),
               [&](const Diagnostic& d) { return d.code == code; });
  return out;
}

/// @return the identity of a finding across revisions (item_ids of a one-item report).
inline std::string identity(const Diagnostic& d) {
  Report one;
  one.add(d);
  return item_ids(one).front();
}

/// @return true if the report has an item with the same identity as `d`.
inline bool still_there(const Report& report, const Diagnostic& d) {
  const std::vector<std::string> ids = item_ids(report);
  const std::string id = identity(d);
  return std::any_of(ids.begin(), ids.end(),
                     [&](const std::string& x) { return x.substr(0, x.find('#')) == id; });
}

/// Applies the finding's edits to a copy of the plan and checks the fix: the finding is gone
/// under the same rules, and validation reports no error the plan did not have (`before`:
/// the plan's report under those rules, when the caller has it already).
/// @return the plan with the fix applied.
inline Plan expect_fix_clears(const Plan& plan, const RuleSet& rules, const Diagnostic& finding,
                              const Report* before = nullptr) {
  Plan fixed = plan;
  EXPECT_FALSE(finding.edits.empty())
      << "no edits for: " << finding.message << " (fix: " << finding.fix << ")";
  EXPECT_NO_THROW(apply_fix_edits(fixed, finding.edits)) << finding.fix;
  const Report after = check(fixed, rules);
  EXPECT_FALSE(still_there(after, finding))
      << "still there after '" << finding.fix << "': " << finding.message;
  const Report fresh = introduced_errors(before ? *before : check(plan, rules), after);
  EXPECT_TRUE(fresh.items.empty())
      << "the fix '" << finding.fix << "' brought " << to_string(fresh.items.front().code) << ": "
      << fresh.items.front().message;
  return fixed;
}

/// Four walls on the rectangle [x0, x1] x [y0, y1] (centre lines), counter-clockwise from the
/// south wall: ids prefix + "s", "e", "n", "w".
inline void add_box(Plan& plan, const std::string& prefix, double x0, double y0, double x1,
                    double y1, double thickness = 0.2) {
  plan.walls.push_back(make_wall(prefix + "s", {x0, y0}, {x1, y0}, thickness));
  plan.walls.push_back(make_wall(prefix + "e", {x1, y0}, {x1, y1}, thickness));
  plan.walls.push_back(make_wall(prefix + "n", {x1, y1}, {x0, y1}, thickness));
  plan.walls.push_back(make_wall(prefix + "w", {x0, y1}, {x0, y0}, thickness));
}

/// A door of `wall` at `offset`, `width` wide, with its leaf as given.
inline Opening make_door(std::string id, std::string wall, double offset, double width = 0.9,
                         Hinge hinge = Hinge::left, Swing swing = Swing::in) {
  Opening o =
      make_opening(std::move(id), OpeningType::door, std::move(wall), offset, width, 2.1, 0.0);
  o.hinge = hinge;
  o.swing = swing;
  return o;
}

}  // namespace roomcad::testing
