// SPDX-License-Identifier: GPL-3.0-or-later
// door_swing_blocked, door_clearance and door_too_narrow: each caught, each fix applied and
// checked, and the cases that must stay quiet (touching is not hitting, exactly).
#include <gtest/gtest.h>

#include "rule_cases.h"

namespace roomcad::testing {
namespace {

/// A 4 x 4 m room (walls 0.2 thick on [0, 4]^2, moved by (dx, dy)) with door `d` in its
/// south wall `rs` (from west to east: its left side is the room).
Plan room_with_door(Opening door, double dx = 0, double dy = 0) {
  Plan plan = plan_with({});
  add_box(plan, "r", dx, dy, dx + 4, dy + 4);
  plan.openings.push_back(std::move(door));
  return plan;
}

TEST(DoorSwing, LeafThroughAWallIsCaughtAndTheFixSwingsItTheOtherWay) {
  Plan plan = room_with_door(make_door("d", "rs", 0.6));
  plan.walls.push_back(make_wall("fin", {1.0, 0.5}, {1.0, 2.5}, 0.1));  // 0.53 m from the hinge
  const RuleSet rules = only({Code::door_swing_blocked});
  const std::vector<Diagnostic> found = findings(check(plan, rules), Code::door_swing_blocked);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].objects, (Ids{"d", "fin"}));
  EXPECT_EQ(found[0].severity, Severity::warning);
  ASSERT_TRUE(found[0].where.has_value());
  const Plan fixed = expect_fix_clears(plan, rules, found[0]);
  EXPECT_EQ(fixed.openings[0].swing, Swing::out);  // either hinge side still hits the fin
  EXPECT_EQ(fixed.openings[0].hinge, Hinge::left);
}

TEST(DoorSwing, LeafThatReachesAWallFaceExactlyTouchesIt) {
  // The hinge is on the south wall's face (y = 0.1); the leaf is 0.9 wide; the bar's south
  // face is at y = 1.05 - 0.05 = 1.0: the quarter disc reaches it, and no further.
  for (const auto& [dx, dy] : {std::pair{0.0, 0.0}, std::pair{100.1, 200.3}}) {
    Plan plan = room_with_door(make_door("d", "rs", 0.6), dx, dy);
    plan.walls.push_back(make_wall("bar", {dx + 0.3, dy + 1.05}, {dx + 3.7, dy + 1.05}, 0.1));
    const RuleSet rules = only({Code::door_swing_blocked});
    EXPECT_TRUE(findings(check(plan, rules), Code::door_swing_blocked).empty()) << dx;
    plan.walls.back().from.y = plan.walls.back().to.y = dy + 1.049;  // 1 mm into the leaf's path
    EXPECT_EQ(findings(check(plan, rules), Code::door_swing_blocked).size(), 1u) << dx;
  }
}

TEST(DoorSwing, LeavesThatSweepIntoEachOtherAreCaughtOnceAndTheFixTurnsOne) {
  // Door a in the south wall opens north; door b, in a wall 1.3 m north of it, opens south
  // over the same stretch: the leaves' reaches (0.9 m each) overlap by 0.7 m.
  Plan plan = room_with_door(make_door("a", "rs", 1.5));
  plan.walls.push_back(make_wall("p", {4, 1.3}, {1, 1.3}, 0.2));  // its left side is south
  plan.openings.push_back(make_door("b", "p", 1.6));
  const RuleSet rules = only({Code::door_swing_blocked});
  const std::vector<Diagnostic> found = findings(check(plan, rules), Code::door_swing_blocked);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].objects, (Ids{"a", "b"}));
  expect_fix_clears(plan, rules, found[0]);
}

TEST(DoorSwing, LeavesOfFacingDoorsThatMeetTipToTipOnlyTouch) {
  // As above with the walls 0.2 + 0.9 + 0.9 apart: the quarter discs touch at one point.
  Plan plan = room_with_door(make_door("a", "rs", 1.5));
  plan.walls.push_back(make_wall("p", {4, 2.0}, {1, 2.0}, 0.2));
  plan.openings.push_back(make_door("b", "p", 1.6, 0.9, Hinge::right));  // hinge above a's
  const RuleSet rules = only({Code::door_swing_blocked});
  EXPECT_TRUE(findings(check(plan, rules), Code::door_swing_blocked).empty());
  plan.walls[4].from.y = plan.walls[4].to.y = 1.999;
  EXPECT_EQ(findings(check(plan, rules), Code::door_swing_blocked).size(), 1u);
}

TEST(DoorSwing, NeighbouringDoorsHingedOnOnePointOnlyTouch) {
  // a turns about its right end, b about its left end: the same point. Their quarter discs
  // share only the line through it.
  Plan plan = room_with_door(make_door("a", "rs", 0.6, 0.9, Hinge::right));
  plan.openings.push_back(make_door("b", "rs", 1.5, 0.9, Hinge::left));
  EXPECT_TRUE(
      findings(check(plan, only({Code::door_swing_blocked})), Code::door_swing_blocked).empty());
}

TEST(DoorSwing, LeafOfADoorInAnotherStoreyIsNotInTheWay) {
  Plan plan = room_with_door(make_door("d", "rs", 0.6));
  Wall fin = make_wall("fin", {1.0, 0.5}, {1.0, 2.5}, 0.1);
  fin.base = 2.5;  // upstairs: above the 2.1 m leaf
  plan.site.max_height = 6;
  plan.walls.push_back(fin);
  EXPECT_TRUE(
      findings(check(plan, only({Code::door_swing_blocked})), Code::door_swing_blocked).empty());
}

/// The room's door swings in, so its push side is outside, where `fence` runs in front of it.
Plan door_facing_fence(double fence_y) {
  Plan plan = room_with_door(make_door("d", "rs", 1.5));
  plan.walls.push_back(make_wall("fence", {0, fence_y}, {4, fence_y}, 0.2));
  return plan;
}

TEST(DoorClearance, WallInTheClearSpaceIsCaughtAndTheFixClearsIt) {
  const Plan plan = door_facing_fence(-1.0);  // 0.8 m of the 1.5 m in front of the door
  const RuleSet rules = only({Code::door_clearance});
  const std::vector<Diagnostic> found = findings(check(plan, rules), Code::door_clearance);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].objects, (Ids{"d", "fence"}));
  expect_fix_clears(plan, rules, found[0]);
}

TEST(DoorClearance, ClearSpaceEndingOnAWallFaceIsClear) {
  // The fence's face is at y = -1.7 + 0.1 = -1.6: 1.5 m from the wall face at y = -0.1.
  EXPECT_TRUE(
      findings(check(door_facing_fence(-1.7), only({Code::door_clearance})), Code::door_clearance)
          .empty());
  EXPECT_EQ(
      findings(check(door_facing_fence(-1.699), only({Code::door_clearance})), Code::door_clearance)
          .size(),
      1u);
}

TEST(DoorClearance, DepthAndWidthAreThresholds) {
  RuleSet rules = only({Code::door_clearance});
  rules.thresholds.clearance_depth = 0.8;  // the fence's face is 0.8 m out: touching
  EXPECT_TRUE(findings(check(door_facing_fence(-1.0), rules), Code::door_clearance).empty());
  rules.thresholds.clearance_depth = 0.81;
  EXPECT_EQ(findings(check(door_facing_fence(-1.0), rules), Code::door_clearance).size(), 1u);
}

TEST(DoorClearance, OnlyDoorsOfAccessibleRoomsAreChecked) {
  RuleSet rules = only({Code::door_clearance});
  Plan plan = door_facing_fence(-1.0);
  add_box(plan, "q", 4, 0, 8, 4);            // a second room east, with its own door to the outside
  plan.walls.erase(plan.walls.begin() + 8);  // its west wall: the first room's east wall
  plan.openings.push_back(make_door("e", "qs", 1.5));
  plan.walls.push_back(make_wall("fence2", {4, -1.0}, {8, -1.0}, 0.2));
  rules.accessible_rooms = std::vector<Point2>{{6, 2}};  // only the east room
  const std::vector<Diagnostic> found = findings(check(plan, rules), Code::door_clearance);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].objects[0], "e");
}

TEST(DoorWidth, NarrowDoorIsCaughtAndWidened) {
  const Plan plan = room_with_door(make_door("d", "rs", 1.5, 0.7));
  const RuleSet rules = only({Code::door_too_narrow});
  const std::vector<Diagnostic> found = findings(check(plan, rules), Code::door_too_narrow);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].objects, (Ids{"d"}));
  const Plan fixed = expect_fix_clears(plan, rules, found[0]);
  EXPECT_EQ(fixed.openings[0].width, 0.8);
}

TEST(DoorWidth, DoorOfExactlyTheThresholdIsWideEnough) {
  const RuleSet rules = only({Code::door_too_narrow});
  EXPECT_TRUE(
      findings(check(room_with_door(make_door("d", "rs", 1.5, 0.8)), rules), Code::door_too_narrow)
          .empty());
  EXPECT_EQ(findings(check(room_with_door(make_door("d", "rs", 1.5, 0.799)), rules),
                     Code::door_too_narrow)
                .size(),
            1u);
}

TEST(DoorWidth, DoorWithNoRoomToWidenGetsAFixInWordsOnly) {
  // A 0.7 m wall filled by its 0.7 m door: a 0.8 m door does not fit in it.
  Plan plan = plan_with({make_wall("w", {0, 0}, {0.7, 0}, 0.2)});
  plan.openings.push_back(make_door("d", "w", 0.0, 0.7));
  const std::vector<Diagnostic> found =
      findings(check(plan, only({Code::door_too_narrow})), Code::door_too_narrow);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_TRUE(found[0].edits.empty());
  EXPECT_FALSE(found[0].fix.empty());
}

}  // namespace
}  // namespace roomcad::testing
