// SPDX-License-Identifier: GPL-3.0-or-later
// add_object: an object of any kind from its fields as text (roomcad add, Plan.add).
#include "plan/plan_add.h"

#include <gtest/gtest.h>

#include "testing/plan_builders.h"

namespace roomcad {
namespace {

Plan one_wall() {
  Plan plan;
  plan.walls = {samples::make_wall("south", {1, 1}, {9, 1}, 0.25, 2.8)};
  return plan;
}

TEST(PlanAdd, WallTakesItsFieldsAndAGeneratedId) {
  Plan plan = one_wall();
  const EditSummary done =
      add_object(plan, "wall", "", {{"from", "1,5"}, {"to", "9,5"}, {"height", "3"}}).value();
  ASSERT_EQ(done.added, std::vector<std::string>{"wall-1"});
  ASSERT_EQ(plan.walls.size(), 2u);
  EXPECT_EQ(plan.walls[1].from, (Point2{1, 5}));
  EXPECT_EQ(plan.walls[1].to, (Point2{9, 5}));
  EXPECT_EQ(plan.walls[1].height, 3.0);
  EXPECT_EQ(plan.walls[1].thickness, Wall{}.thickness);  // the format's default
}

TEST(PlanAdd, WindowStartsFromTheFormatsDefaults) {
  Plan plan = one_wall();
  ASSERT_TRUE(add_object(plan, "window", "w1", {{"wall", "south"}, {"offset", "2"}}).ok());
  ASSERT_EQ(plan.openings.size(), 1u);
  EXPECT_EQ(plan.openings[0].id, "w1");
  EXPECT_EQ(plan.openings[0].type, OpeningType::window);
  EXPECT_EQ(plan.openings[0].sill, default_opening(OpeningType::window).sill);
}

TEST(PlanAdd, UnknownKindFieldOrMissingFieldIsAUsageErrorAndChangesNothing) {
  Plan plan = one_wall();
  const Plan before = plan;
  const auto code_of = [&](std::string_view kind, const FieldValues& fields) {
    return add_object(plan, kind, "", fields).code();  // never thrown
  };
  EXPECT_EQ(code_of("roof", {}), Code::usage_error);
  EXPECT_EQ(code_of("wall", {{"from", "0,0"}, {"to", "1,0"}, {"colour", "#ffffff"}}),
            Code::usage_error);
  EXPECT_EQ(code_of("wall", {{"from", "0,0"}}), Code::usage_error);  // no `to`
  EXPECT_EQ(code_of("wall", {{"from", "0,0"}, {"to", "far"}}), Code::usage_error);
  EXPECT_EQ(plan, before);
}

TEST(PlanAdd, RequiredFieldsAreThoseWithoutADefault) {
  const std::vector<std::string_view> wall = required_fields("wall");
  EXPECT_NE(std::find(wall.begin(), wall.end(), "from"), wall.end());
  EXPECT_NE(std::find(wall.begin(), wall.end(), "to"), wall.end());
  const std::vector<std::string_view> settable = settable_fields("door");
  EXPECT_EQ(std::find(settable.begin(), settable.end(), "id"), settable.end());
  EXPECT_EQ(std::find(settable.begin(), settable.end(), "type"), settable.end());
}

}  // namespace
}  // namespace roomcad
