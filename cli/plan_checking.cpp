// SPDX-License-Identifier: GPL-3.0-or-later
#include "cli/plan_checking.h"

#include <fmt/format.h>

#include "daylight/insolation_rule.h"
#include "io/plan_check.h"
#include "io/plan_json.h"
#include "io/text_file.h"
#include "validation/report_tally.h"

namespace roomcad::cli {

Result<CheckedPlan> check_plan_file(const std::string& path, const RuleSet& rules) {
  const Result<std::string> text = read_text_file(path);
  if (!text) return text.error();
  Report reading;
  Result<Plan> read = read_plan_text(text.value(), path, &reading);
  if (!read) return CheckedPlan{reading, {}, std::nullopt};
  if (const Status rooms = check_accessible_rooms(read.value(), rules); !rooms)
    return rooms.error();
  CheckedPlan checked{check_plan(read.value(), &reading, rules), {}, std::move(read).value()};
  add_insolation_findings(*checked.plan, rules, checked.report);
  checked.levels = item_levels(checked.report, *checked.plan);
  return checked;
}

Error not_a_plan(const CheckedPlan& checked, const std::string& path, std::string_view context) {
  return {Code::parse_error,
          fmt::format("{}{} is not a plan ({} problems: `roomcad validate {}` lists them)", context,
                      path, checked.report.items.size(), path)};
}

}  // namespace roomcad::cli
