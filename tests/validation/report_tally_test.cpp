// SPDX-License-Identifier: GPL-3.0-or-later
// The summary that ends a long text report: findings counted by code and by level, and a
// report cut to its first items.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "validation/report_format.h"
#include "validation/report_tally.h"

namespace roomcad {
namespace {

Diagnostic finding(Code code, Severity severity, std::vector<std::string> objects) {
  Diagnostic d;
  d.code = code;
  d.severity = severity;
  d.objects = std::move(objects);
  d.message = "m";
  return d;
}

Plan two_storeys() {
  Plan plan;
  plan.levels = {{.id = "ground"}, {.id = "upper", .elevation = 3.0}};
  plan.walls = {{.id = "a", .level = "ground"}, {.id = "b", .level = "upper"}, {.id = "c"}};
  plan.openings = {{.id = "win", .wall = "b"}};
  return plan;
}

TEST(ReportTally, EachItemTakesTheLevelOfItsFirstObjectOnALevel) {
  Report r;
  r.add(finding(Code::wall_overlap, Severity::error, {"c", "a"}));
  r.add(finding(Code::opening_blocked, Severity::error, {"win"}));
  r.add(finding(Code::room_without_window, Severity::warning, {"c"}));
  r.add(finding(Code::unknown_field, Severity::warning, {}));
  EXPECT_EQ(item_levels(r, two_storeys()), (std::vector<std::string>{"ground", "upper", "", ""}));
}

TEST(ReportTally, CountsErrorsAndWarningsByCodeThenByLevel) {
  Report r;
  r.add(finding(Code::wall_overlap, Severity::error, {"a"}));
  r.add(finding(Code::opening_blocked, Severity::error, {"win"}));
  r.add(finding(Code::wall_overlap, Severity::error, {"b"}));
  r.add(finding(Code::room_without_window, Severity::warning, {"c"}));
  EXPECT_EQ(format_report_tally(r, item_levels(r, two_storeys())),
            "by code:\n"
            "  wall_overlap         2 errors\n"
            "  opening_blocked      1 error\n"
            "  room_without_window  1 warning\n"
            "by level:\n"
            "  ground      1 error\n"
            "  upper       2 errors\n"
            "  (no level)  1 warning\n");
  // A plan without levels: the codes only.
  EXPECT_EQ(format_report_tally(r, {}).find("by level:"), std::string::npos);
}

TEST(ReportTally, ALongTextReportEndsWithTheSummaryAndCountsWhatItCuts) {
  Report r;
  for (int i = 0; i < 12; ++i) r.add(finding(Code::wall_overlap, Severity::error, {"a"}));
  ReportFormatOptions options;
  options.max_items = 3;
  const std::string text = format_report_text(r, false, options);
  std::size_t blocks = 0;
  for (std::size_t at = text.find("error[wall_overlap]"); at != std::string::npos;
       at = text.find("error[wall_overlap]", at + 1))
    ++blocks;
  EXPECT_EQ(blocks, 3u);
  EXPECT_NE(text.find("... and 9 more"), std::string::npos) << text;
  EXPECT_NE(text.find("by code:\n  wall_overlap  12 errors\n"), std::string::npos) << text;
  // Under kTallyFrom items, printed whole: no summary.
  Report short_report;
  short_report.add(finding(Code::wall_overlap, Severity::error, {"a"}));
  EXPECT_EQ(format_report_text(short_report, false).find("by code:"), std::string::npos);
}

}  // namespace
}  // namespace roomcad
