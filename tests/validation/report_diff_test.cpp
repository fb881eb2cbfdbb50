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

}  // namespace
}  // namespace roomcad
