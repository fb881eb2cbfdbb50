// SPDX-License-Identifier: GPL-3.0-or-later
// introduced_errors: errors counted per (code, sorted ids); warnings and rewordings ignored.
#include <gtest/gtest.h>

#include "validation/report_diff.h"

namespace roomcad {
namespace {

Diagnostic error(Code code, std::vector<std::string> ids, std::string message = "m") {
  Diagnostic d;
  d.code = code, d.objects = std::move(ids), d.message = std::move(message);
  return d;
}

TEST(ReportDiff, SameProblemRewordedOrReorderedIsNotNew) {
  Report before, after;
  before.add(error(Code::wall_overlap, {"a", "b"}, "walls a and b overlap at 1,1"));
  after.add(error(Code::wall_overlap, {"b", "a"}, "walls b and a overlap at 2,1"));
  EXPECT_TRUE(introduced_errors(before, after).ok());
}

TEST(ReportDiff, CountsEachIdentity) {
  Report before, after;
  before.add(error(Code::wall_overlap, {"a", "b"}));
  after.add(error(Code::wall_overlap, {"a", "b"}));
  after.add(error(Code::wall_overlap, {"a", "b"}));
  after.add(error(Code::opening_outside_wall, {"d"}));
  Diagnostic warning = error(Code::room_without_door, {"r"});
  warning.severity = Severity::warning;
  after.add(warning);
  const Report fresh = introduced_errors(before, after);
  ASSERT_EQ(fresh.items.size(), 2u);
  EXPECT_EQ(fresh.items[0].code, Code::wall_overlap);
  EXPECT_EQ(fresh.items[1].code, Code::opening_outside_wall);
  EXPECT_TRUE(introduced_errors(after, before).ok());
}

TEST(ReportDiff, ItemIdsNameTheCodeAndSortedObjectsAndNumberRepeats) {
  Report r;
  r.add(error(Code::door_clearance, {"w3", "d1"}));
  r.add(error(Code::door_clearance, {"d1", "w3"}, "again"));
  r.add(error(Code::parse_error, {}, "not JSON"));
  EXPECT_EQ(item_ids(r), (std::vector<std::string>{"door_clearance:d1+w3", "door_clearance:d1+w3#2",
                                                   "parse_error:not JSON"}));
}

TEST(ReportDiff, RevisionsCompareAsNewUnchangedAndFixed) {
  Report old_report, new_report;
  old_report.add(error(Code::door_too_narrow, {"d1"}, "door 'd1' is 0.70 m wide"));
  old_report.add(error(Code::room_unreachable, {"a", "b"}));
  new_report.add(error(Code::door_too_narrow, {"d1"}, "door 'd1' is 0.75 m wide"));  // reworded
  new_report.add(error(Code::window_sill_low, {"w"}));
  const ReportComparison c = compare_reports(old_report, new_report);
  EXPECT_EQ(c.status, (std::vector<ItemStatus>{ItemStatus::unchanged, ItemStatus::added}));
  EXPECT_EQ(c.ids, item_ids(new_report));
  ASSERT_EQ(c.fixed.items.size(), 1u);
  EXPECT_EQ(c.fixed.items[0].code, Code::room_unreachable);
  EXPECT_EQ(c.fixed_ids, (std::vector<std::string>{"room_unreachable:a+b"}));
  EXPECT_EQ(to_string(ItemStatus::added), "new");
  const ReportComparison same = compare_reports(new_report, new_report);
  EXPECT_TRUE(same.fixed.items.empty());
  EXPECT_EQ(same.status, (std::vector<ItemStatus>{ItemStatus::unchanged, ItemStatus::unchanged}));
}

}  // namespace
}  // namespace roomcad
