// SPDX-License-Identifier: GPL-3.0-or-later
// window_sill_low, window_sill_high and duplicate_object: caught, fixed and checked, and
// quiet at the thresholds and for near copies.
#include <gtest/gtest.h>

#include "rule_cases.h"

namespace roomcad::testing {
namespace {

Plan room_with_window(double sill, double height = 1.2) {
  Plan plan = plan_with({});
  add_box(plan, "r", 0, 0, 4, 4);
  plan.openings.push_back(make_opening("win", OpeningType::window, "rn", 1.0, 1.2, height, sill));
  return plan;
}

TEST(WindowSill, LowSillIsCaughtAndRaised) {
  const Plan plan = room_with_window(0.3, 2.0);  // the top (2.3 m) is near the wall's (2.5 m)
  const RuleSet rules = only({Code::window_sill_low});
  const std::vector<Diagnostic> found = findings(check(plan, rules), Code::window_sill_low);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].objects, (Ids{"win"}));
  const Plan fixed = expect_fix_clears(plan, rules, found[0]);
  EXPECT_EQ(fixed.openings[0].sill, 0.8);
  EXPECT_LE(fixed.openings[0].sill + fixed.openings[0].height,
            2.5);  // shortened to stay in the wall
}

TEST(WindowSill, HighSillIsCaughtAndLowered) {
  const Plan plan = room_with_window(1.5, 0.6);
  const RuleSet rules = only({Code::window_sill_high});
  const std::vector<Diagnostic> found = findings(check(plan, rules), Code::window_sill_high);
  ASSERT_EQ(found.size(), 1u);
  const Plan fixed = expect_fix_clears(plan, rules, found[0]);
  EXPECT_EQ(fixed.openings[0].sill, 1.2);
}

TEST(WindowSill, SillsAtTheThresholdsAreQuietAndDoorsAreNotWindows) {
  const RuleSet rules = only({Code::window_sill_low, Code::window_sill_high});
  EXPECT_TRUE(findings(check(room_with_window(0.8), rules), Code::window_sill_low).empty());
  EXPECT_TRUE(findings(check(room_with_window(1.2), rules), Code::window_sill_high).empty());
  EXPECT_EQ(findings(check(room_with_window(0.79), rules), Code::window_sill_low).size(), 1u);
  EXPECT_EQ(findings(check(room_with_window(1.21), rules), Code::window_sill_high).size(), 1u);
  Plan plan = room_with_window(0.8);
  plan.openings.push_back(make_door("d", "rs", 1.0));  // sill 0: a door
  EXPECT_TRUE(findings(check(plan, rules), Code::window_sill_low).empty());
}

TEST(Duplicates, WallDrawnTwiceIsCaughtAndTheFixKeepsItsOpenings) {
  Plan plan = plan_with({});
  add_box(plan, "r", 0, 0, 4, 4);
  Wall copy = plan.walls[0];
  copy.id = "copy";
  std::swap(copy.from, copy.to);  // drawn the other way round
  plan.walls.push_back(copy);
  plan.openings.push_back(make_door("d", "copy", 0.5));  // 0.5 from the east end
  const RuleSet rules = only({Code::duplicate_object});
  const Report report = check(plan, rules);
  EXPECT_FALSE(report.ok());  // the copy overlaps its original: wall_overlap
  const std::vector<Diagnostic> found = findings(report, Code::duplicate_object);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].objects, (Ids{"rs", "copy"}));
  const Plan fixed = expect_fix_clears(plan, rules, found[0]);
  EXPECT_TRUE(check(fixed, rules).ok());  // the overlap went with the copy
  ASSERT_EQ(fixed.openings.size(), 1u);
  EXPECT_EQ(fixed.openings[0].wall, "rs");
  EXPECT_DOUBLE_EQ(fixed.openings[0].offset, 4 - 0.5 - 0.9);
}

TEST(Duplicates, OpeningsLightsAndCamerasDrawnTwiceAreCaught) {
  Plan plan = room_with_window(0.9);
  plan.openings.push_back(plan.openings[0]);
  plan.openings.back().id = "win2";
  Light sun;
  sun.id = "sun";
  plan.lights = {sun, sun};
  plan.lights[1].id = "sun2";
  const RuleSet rules = only({Code::duplicate_object});
  const std::vector<Diagnostic> found = findings(check(plan, rules), Code::duplicate_object);
  ASSERT_EQ(found.size(), 2u);
  EXPECT_EQ(found[0].objects, (Ids{"win", "win2"}));
  EXPECT_EQ(found[1].objects, (Ids{"sun", "sun2"}));
  const Plan once = expect_fix_clears(plan, rules, found[0]);
  expect_fix_clears(once, rules, findings(check(once, rules), Code::duplicate_object).at(0));
}

TEST(Duplicates, NearCopiesAreNotCopies) {
  Plan plan = plan_with({});
  add_box(plan, "r", 0, 0, 4, 4);
  Wall copy = plan.walls[0];
  copy.id = "copy";
  copy.from.y = copy.to.y = 1e-3;  // a millimetre off: an overlap, not a copy
  plan.walls.push_back(copy);
  EXPECT_TRUE(
      findings(check(plan, only({Code::duplicate_object})), Code::duplicate_object).empty());
}

}  // namespace
}  // namespace roomcad::testing
