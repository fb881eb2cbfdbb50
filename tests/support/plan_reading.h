// SPDX-License-Identifier: GPL-3.0-or-later
// Reading a plan in a test, keeping both what read_plan_text returns and every problem it
// reported, so that a test can look at the whole report.
#pragma once

#include <filesystem>
#include <optional>
#include <string_view>

#include "io/plan_json.h"

namespace roomcad::test {

struct PlanReading {
  std::optional<Plan> plan;  ///< set when the text is a plan
  Report report;             ///< every problem found, in file order
};

/// read_plan_text, with its report.
inline PlanReading read_plan(std::string_view text, std::string_view file = "plan.json") {
  PlanReading reading;
  Result<Plan> plan = read_plan_text(text, file, &reading.report);
  if (plan) reading.plan = std::move(plan).value();
  return reading;
}

/// read_plan_file, with its report (empty when the file could not be read at all).
inline PlanReading read_plan_at(const std::filesystem::path& path) {
  PlanReading reading;
  Result<Plan> plan = read_plan_file(path, &reading.report);
  if (plan) reading.plan = std::move(plan).value();
  return reading;
}

}  // namespace roomcad::test
