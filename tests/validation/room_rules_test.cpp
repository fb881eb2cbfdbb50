// SPDX-License-Identifier: GPL-3.0-or-later
// passage_too_narrow, no_turning_circle, room_unreachable and escape_too_far: each caught,
// each fix applied and checked, and the cases that must stay quiet.
#include <gtest/gtest.h>

#include "rule_cases.h"

namespace roomcad::testing {
namespace {

/// A 6 x 4 m room with a door in its west and its east wall, and a partition hanging from
/// the north wall down to y = `end`: the way between the doors runs between its end and the
/// south wall's face (y = 0.1).
Plan room_with_partition(double end) {
  Plan plan = plan_with({});
  add_box(plan, "r", 0, 0, 6, 4);
  plan.walls.push_back(make_wall("p", {3, 4}, {3, end}, 0.2));
  plan.openings.push_back(make_door("a", "rw", 1.5));
  plan.openings.push_back(make_door("b", "re", 1.5));
  return plan;
}

TEST(Passage, GapBelowTheWidthOnTheOnlyWayIsCaughtAndTheFixWidensIt) {
  const Plan plan = room_with_partition(0.9);  // 0.8 m between the partition and the wall
  const RuleSet rules = only({Code::passage_too_narrow});
  const std::vector<Diagnostic> found = findings(check(plan, rules), Code::passage_too_narrow);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].objects, (Ids{"p", "rs"}));
  EXPECT_NE(found[0].message.find("0.80 m"), std::string::npos) << found[0].message;
  expect_fix_clears(plan, rules, found[0]);
}

TEST(Passage, GapOfExactlyTheWidthIsWideEnough) {
  const RuleSet rules = only({Code::passage_too_narrow});
  EXPECT_TRUE(findings(check(room_with_partition(1.0), rules), Code::passage_too_narrow).empty());
  EXPECT_EQ(findings(check(room_with_partition(0.999), rules), Code::passage_too_narrow).size(),
            1u);
}

TEST(Passage, NarrowPlaceOffTheWayIsNotAPassage) {
  // A niche 0.5 m wide in a corner: narrow, but no way between the doors runs through it.
  Plan plan = room_with_partition(3.0);  // the gap under the partition is 2.8 m
  plan.walls.push_back(make_wall("niche", {5.5, 4}, {5.5, 3}, 0.2));
  EXPECT_TRUE(
      findings(check(plan, only({Code::passage_too_narrow})), Code::passage_too_narrow).empty());
}

TEST(Passage, ThresholdIsTheRuleSets) {
  RuleSet rules = only({Code::passage_too_narrow});
  rules.thresholds.passage_min_width = 0.8;
  EXPECT_TRUE(findings(check(room_with_partition(0.9), rules), Code::passage_too_narrow).empty());
}

/// A square room `side` metres between wall centres (walls 0.2 thick) with a door.
Plan square_room(double side) {
  Plan plan = plan_with({});
  add_box(plan, "r", 0, 0, side, side);
  plan.openings.push_back(make_door("d", "rs", 0.3));
  return plan;
}

TEST(TurningCircle, SmallRoomIsCaughtAndTheFixMovesAWallOut) {
  const Plan plan = square_room(1.6);  // 1.4 m clear
  const RuleSet rules = only({Code::no_turning_circle});
  const std::vector<Diagnostic> found = findings(check(plan, rules), Code::no_turning_circle);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].objects, (Ids{"re", "rn", "rs", "rw"}));
  EXPECT_NE(found[0].message.find("1.40 m"), std::string::npos) << found[0].message;  // the largest
  expect_fix_clears(plan, rules, found[0]);
}

TEST(TurningCircle, RoomExactlyTheDiameterAcrossHoldsTheCircle) {
  const RuleSet rules = only({Code::no_turning_circle});
  EXPECT_TRUE(
      findings(check(square_room(1.7), rules), Code::no_turning_circle).empty());  // 1.5 m clear
  EXPECT_EQ(findings(check(square_room(1.699), rules), Code::no_turning_circle).size(), 1u);
}

TEST(TurningCircle, RoomsWithoutDoorsAndRoomsNotNamedAccessibleAreLeftAlone) {
  Plan plan = square_room(1.6);
  plan.openings.clear();
  EXPECT_TRUE(
      findings(check(plan, only({Code::no_turning_circle})), Code::no_turning_circle).empty());
  RuleSet rules = only({Code::no_turning_circle});
  rules.accessible_rooms = std::vector<Point2>{{50, 50}};  // in no room
  EXPECT_TRUE(findings(check(square_room(1.6), rules), Code::no_turning_circle).empty());
}

/// Two 4 x 4 m rooms side by side; the west one has a door to the outside.
Plan two_rooms() {
  Plan plan = plan_with({});
  add_box(plan, "r", 0, 0, 4, 4);
  add_box(plan, "q", 4, 0, 8, 4);
  plan.walls.pop_back();  // the east room's west wall is the west room's east wall
  plan.openings.push_back(make_door("d", "rs", 1.5));
  return plan;
}

TEST(Reachability, RoomWithoutAWayInIsCaughtAndTheFixAddsADoor) {
  const Plan plan = two_rooms();
  const RuleSet rules = only({Code::room_unreachable});
  const std::vector<Diagnostic> found = findings(check(plan, rules), Code::room_unreachable);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].objects, (Ids{"qe", "qn", "qs", "re"}));
  ASSERT_EQ(found[0].edits.size(), 1u);
  EXPECT_EQ(found[0].edits[0].op, FixEdit::Op::add);
  const Plan fixed = expect_fix_clears(plan, rules, found[0]);
  EXPECT_EQ(fixed.openings.size(), 2u);
}

TEST(Reachability, RoomsReachedThroughOtherRoomsAreReachable) {
  Plan plan = two_rooms();
  plan.openings.push_back(make_door("between", "re", 1.5));
  EXPECT_TRUE(
      findings(check(plan, only({Code::room_unreachable})), Code::room_unreachable).empty());
}

TEST(Reachability, GapsBetweenWallsAreNotRooms) {
  // A closed sliver 2 m x 0.15 m under the east room's south wall, as imports leave them.
  Plan plan = two_rooms();
  plan.openings.push_back(make_door("between", "re", 1.5));
  plan.walls.push_back(make_wall("g", {5, -0.35}, {7, -0.35}, 0.2));
  plan.walls.push_back(make_wall("gw", {5, 0}, {5, -0.35}, 0.2));
  plan.walls.push_back(make_wall("ge", {7, 0}, {7, -0.35}, 0.2));
  ASSERT_EQ(find_rooms(plan).size(), 3u);
  EXPECT_TRUE(
      findings(check(plan, only({Code::room_unreachable})), Code::room_unreachable).empty());
}

TEST(Reachability, RoomsJoinedOnlyToEachOtherAreEachCaughtWithTheirDoors) {
  Plan plan = two_rooms();
  plan.openings.front().wall = "re";  // the west room's door now leads east, not out
  const std::vector<Diagnostic> found =
      findings(check(plan, only({Code::room_unreachable})), Code::room_unreachable);
  ASSERT_EQ(found.size(), 2u);
  for (const Diagnostic& d : found)
    EXPECT_NE(d.message.find("joined by doors d"), std::string::npos) << d.message;
}

/// A corridor room `length` x 3 m with one door to the outside, in its west wall.
Plan corridor(double length) {
  Plan plan = plan_with({});
  add_box(plan, "r", -30, 0, -30 + length, 3);
  plan.openings.push_back(make_door("d", "rw", 1.0));
  return plan;
}

TEST(Escape, FarEndOfALongRoomIsCaughtAndTheFixAddsAnExteriorDoor) {
  const Plan plan = corridor(40);
  const RuleSet rules = only({Code::escape_too_far});
  const std::vector<Diagnostic> found = findings(check(plan, rules), Code::escape_too_far);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].objects, (Ids{"re", "rn", "rs", "rw"}));
  ASSERT_TRUE(found[0].where.has_value());
  EXPECT_GT(found[0].where->min.x, 0.0);  // the farthest point is at the east end
  expect_fix_clears(plan, rules, found[0]);
}

TEST(Escape, RoomWithinTheDistanceIsQuietAndTheDistanceIsAThreshold) {
  const RuleSet rules = only({Code::escape_too_far});
  EXPECT_TRUE(findings(check(corridor(20), rules), Code::escape_too_far).empty());
  RuleSet longer = rules;
  longer.thresholds.escape_max_distance = 45;
  EXPECT_TRUE(findings(check(corridor(40), longer), Code::escape_too_far).empty());
}

}  // namespace
}  // namespace roomcad::testing
