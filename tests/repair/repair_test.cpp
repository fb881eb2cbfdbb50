// SPDX-License-Identifier: GPL-3.0-or-later
// What each kind of repair does on a small plan: the finding cleared, the edit and what it
// claims to move, the solid within that, openings kept where they stand, and a repaired plan
// repaired again left as it is.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "repair/repair.h"
#include "repair/solid_distance_support.h"
#include "solid/analytic_volume.h"
#include "support/model_support.h"
#include "validation/validate.h"

namespace roomcad {
namespace {

using test::add_opening;
using test::add_wall;
using test::empty_plan;

RepairResult repaired(const Plan& plan, RepairOptions options = {}) {
  Result<RepairResult> r = repair_plan(plan, options);
  EXPECT_TRUE(r.ok());
  return std::move(r).value();
}

std::size_t errors(const Plan& plan) { return validate(plan).error_count(); }

double largest_move(const RepairResult& r) {
  double most = 0;
  for (const RepairEdit& e : r.edits) most = std::max(most, e.moves);
  return most;
}

/// The guarantees every repair keeps: no error it was asked about left that it claims to have
/// cleared, the solid within the largest claimed move (and the tolerance), the volume kept
/// when every edit claims to keep the union, and nothing more to do on the result.
void expect_guarantees(const Plan& plan, const RepairResult& r, double tolerance = 0.01) {
  EXPECT_LE(largest_move(r), tolerance);
  const double distance =
      test::surface_distance(test::walls_and_slabs(plan), test::walls_and_slabs(r.plan), 0.05);
  EXPECT_LE(distance, largest_move(r) + 1e-9);
  if (largest_move(r) == 0) {
    EXPECT_EQ(analytic_wall_volume(r.plan), analytic_wall_volume(plan));
  }
  const RepairResult again = repaired(r.plan, {.tolerance = tolerance});
  EXPECT_TRUE(again.edits.empty());
  EXPECT_EQ(again.plan, r.plan);
}

TEST(Repair, AWallDrawnTwiceIsRemovedAndItsDoorMovesToTheOther) {
  Plan plan = empty_plan();
  add_wall(plan, "a", {1, 1}, {9, 1});
  add_wall(plan, "b", {3, 1}, {7, 1});
  add_opening(plan, "d", test::kDoor, "b", 1.0, 0.9, 0.0, 2.1);
  ASSERT_EQ(errors(plan), 2u);  // the walls overlap, and a blocks b's door
  const RepairResult r = repaired(plan);
  EXPECT_EQ(errors(r.plan), 0u);
  ASSERT_EQ(r.plan.walls.size(), 1u);
  EXPECT_EQ(r.plan.walls[0].id, "a");
  ASSERT_EQ(r.plan.openings.size(), 1u);
  EXPECT_EQ(r.plan.openings[0].id, "d");
  EXPECT_EQ(r.plan.openings[0].wall, "a");
  EXPECT_EQ(r.plan.openings[0].offset, 3.0);  // where it stood: x = 4
  EXPECT_EQ(largest_move(r), 0.0);
  expect_guarantees(plan, r);
}

TEST(Repair, WallsOverlappingAlongOneLineAreTrimmedToMeetEndToEnd) {
  Plan plan = empty_plan();
  add_wall(plan, "a", {1, 1}, {6, 1});
  add_wall(plan, "b", {4, 1}, {9, 1});
  add_opening(plan, "w", test::kWindow, "b", 3.0, 1.0, 1.0, 1.2);
  const RepairResult r = repaired(plan);
  EXPECT_EQ(errors(r.plan), 0u);
  ASSERT_EQ(r.plan.walls.size(), 2u);
  EXPECT_EQ(r.plan.walls[1].from, (Point2{6, 1}));  // b starts where a ends
  EXPECT_EQ(r.plan.openings[0].offset, 1.0);        // still at x = 7
  EXPECT_EQ(r.edits.back().change, RepairChange::trim);
  expect_guarantees(plan, r);
}

TEST(Repair, StoreysDrawnOverOneFootprintAreTrimmedInHeight) {
  Plan plan = empty_plan();
  add_wall(plan, "low", {1, 1}, {6, 1}).height = 3.0;
  Wall& high = add_wall(plan, "high", {1, 1}, {6, 1});
  high.base = 2.5;
  high.height = 2.5;
  const RepairResult r = repaired(plan);
  EXPECT_EQ(errors(r.plan), 0u);
  EXPECT_EQ(r.plan.walls[1].base + 0.0, 3.0);  // raised onto the lower one's top
  EXPECT_EQ(r.plan.walls[1].height, 2.0);      // keeping its own top at 5
  expect_guarantees(plan, r);
}

TEST(Repair, AnEndDrawnIntoAWallMovesOntoItsCentreLine) {
  Plan plan = empty_plan();
  add_wall(plan, "a", {1, 1}, {9, 1});
  add_wall(plan, "b", {5, 1.05}, {5, 5});  // its end 5 cm into a, short of the centre line
  ASSERT_EQ(errors(plan), 1u);
  const RepairResult r = repaired(plan);
  EXPECT_EQ(errors(r.plan), 0u);
  EXPECT_EQ(r.plan.walls[1].from, (Point2{5, 1}));  // a T join
  EXPECT_EQ(r.edits[0].change, RepairChange::extend);
  EXPECT_EQ(r.edits[0].moves, 0.0);
  expect_guarantees(plan, r);
}

TEST(Repair, AWallBesideAnotherWithinTheToleranceIsSnappedOntoItsLine) {
  Plan plan = empty_plan();
  add_wall(plan, "a", {1, 1}, {9, 1});
  add_wall(plan, "b", {3, 1.004}, {7, 1.004});  // drawn twice, 4 mm off
  const RepairResult r = repaired(plan);
  EXPECT_EQ(errors(r.plan), 0u);
  EXPECT_NEAR(largest_move(r), 0.004, 1e-12);
  expect_guarantees(plan, r);
}

TEST(Repair, WallsFurtherApartThanTheToleranceAreLeftWithWhy) {
  Plan plan = empty_plan();
  add_wall(plan, "a", {1, 1}, {9, 1});
  Wall& b = add_wall(plan, "b", {3, 1.05}, {7, 1.05});
  b.height = 3.0;  // taller: not inside a, and 5 cm off its line
  const RepairResult r = repaired(plan);
  ASSERT_EQ(r.remaining.size(), 1u);
  EXPECT_EQ(r.remaining[0].finding.code, Code::wall_overlap);
  EXPECT_NE(r.remaining[0].reason.find("tolerance"), std::string::npos) << r.remaining[0].reason;
  EXPECT_TRUE(r.edits.empty());
  EXPECT_EQ(r.plan, plan);
  // A larger tolerance allows the snap.
  const RepairResult wide = repaired(plan, {.tolerance = 0.06});
  EXPECT_TRUE(wide.remaining.empty());
}

TEST(Repair, AnOpeningAHairPastItsWallIsShortenedToFit) {
  Plan plan = empty_plan();
  add_wall(plan, "a", {1, 1}, {9, 1});
  add_opening(plan, "w", test::kWindow, "a", 7.0, 1.0000004, 1.0, 1.2);
  ASSERT_EQ(errors(plan), 1u);
  const RepairResult r = repaired(plan);
  EXPECT_EQ(errors(r.plan), 0u);
  EXPECT_EQ(r.edits[0].change, RepairChange::shorten);
  EXPECT_LE(r.edits[0].moves, 1e-6);
  EXPECT_GT(r.edits[0].moves, 0.0);
}

TEST(Repair, OverlappingWindowsOfOneHeightMergeIntoTheFirst) {
  Plan plan = empty_plan();
  add_wall(plan, "a", {1, 1}, {9, 1});
  add_opening(plan, "w1", test::kWindow, "a", 1.0, 1.0, 1.0, 1.2);
  add_opening(plan, "w2", test::kWindow, "a", 1.5, 1.0, 1.0, 1.2);
  const RepairResult r = repaired(plan);
  EXPECT_EQ(errors(r.plan), 0u);
  ASSERT_EQ(r.plan.openings.size(), 1u);
  EXPECT_EQ(r.plan.openings[0].id, "w1");
  EXPECT_EQ(r.plan.openings[0].width, 1.5);
  expect_guarantees(plan, r);
}

TEST(Repair, TheLaterOfTwoOverlappingSlabsIsCutBack) {
  Plan plan = empty_plan();
  plan.slabs.push_back({.id = "s1", .outline = {{1, 1}, {5, 1}, {5, 5}, {1, 5}}, .top = 0.2});
  plan.slabs.push_back({.id = "s2", .outline = {{3, 1}, {8, 1}, {8, 5}, {3, 5}}, .top = 0.2});
  ASSERT_EQ(errors(plan), 1u);
  const RepairResult r = repaired(plan);
  EXPECT_EQ(errors(r.plan), 0u);
  EXPECT_EQ(r.plan.slabs[0].outline, plan.slabs[0].outline);
  EXPECT_EQ(r.edits[0].object, "s2");
  EXPECT_EQ(r.edits[0].change, RepairChange::cut);
  expect_guarantees(plan, r);
}

TEST(Repair, APlanWithNothingToRepairComesBackEqual) {
  Plan plan = empty_plan();
  test::add_room(plan, "r", 1, 1, 4, 3);
  const RepairResult r = repaired(plan);
  EXPECT_TRUE(r.edits.empty());
  EXPECT_TRUE(r.remaining.empty());
  EXPECT_EQ(r.plan, plan);
}

TEST(Repair, OnlyTheCodesAskedForAreRepaired) {
  Plan plan = empty_plan();
  add_wall(plan, "a", {1, 1}, {9, 1});
  add_wall(plan, "b", {3, 1}, {7, 1});
  add_opening(plan, "w", test::kWindow, "a", 7.5, 0.5000001, 1.0, 1.2);
  const RepairResult r = repaired(plan, {.only = {Code::opening_outside_wall}});
  ASSERT_EQ(r.edits.size(), 1u);
  EXPECT_EQ(r.edits[0].object, "w");
  ASSERT_EQ(r.remaining.size(), 1u);
  EXPECT_EQ(r.remaining[0].finding.code, Code::wall_overlap);
}

TEST(Repair, ABadToleranceIsAnInvalidValue) {
  for (const double t : {-0.01, std::nan(""), static_cast<double>(INFINITY)}) {
    const Result<RepairResult> r = repair_plan(empty_plan(), {.tolerance = t});
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.code(), Code::invalid_value);
  }
}

}  // namespace
}  // namespace roomcad
