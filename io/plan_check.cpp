// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/plan_check.h"

#include <algorithm>

#include "io/plan_json.h"
#include "validation/validate.h"

namespace roomcad {

Report check_plan(const Plan& plan, const Report* reading, const RuleSet& rules) {
  Report report;
  if (reading != nullptr) report = *reading;
  ValidateOptions options;
  options.unknown_field_warnings = reading == nullptr;  // else the reader has reported them
  options.rules = rules;
  report.append(validate(plan, options));
  // Errors first (the JSON lists them apart anyway), each group in the order found.
  std::stable_partition(report.items.begin(), report.items.end(),
                        [](const Diagnostic& d) { return d.severity == Severity::error; });
  return report;
}

Report check_plan_text(const std::string& text, const std::string& file) {
  Report reading;
  const Result<Plan> read = read_plan_text(text, file, &reading);
  if (!read) return reading;
  return check_plan(read.value(), &reading);
}

}  // namespace roomcad
