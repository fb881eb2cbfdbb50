// SPDX-License-Identifier: GPL-3.0-or-later
// Levels resolved to absolute heights, and one level's part of a plan.
#include <gtest/gtest.h>

#include "core/error.h"
#include "plan/plan_levels.h"

namespace roomcad {
namespace {

Plan storeys_with_own_bases() {
  Plan plan;
  plan.levels = {{.id = "ground", .elevation = 0.0}, {.id = "first", .elevation = 3.0}};
  plan.walls = {{.id = "a", .level = "ground", .from = {0, 0}, .to = {4, 0}, .base = 0.5},
                {.id = "b", .level = "first", .from = {0, 0}, .to = {4, 0}, .base = 0.1},
                {.id = "c", .from = {0, 4}, .to = {4, 4}, .base = 0.2}};
  plan.openings = {{.id = "d", .wall = "a", .offset = 1}, {.id = "e", .wall = "b", .offset = 1}};
  plan.slabs = {{.id = "f", .level = "first", .outline = {{0, 0}, {4, 0}, {4, 4}}, .top = 0.0}};
  return plan;
}

TEST(PlanLevels, BasesAndTopsAreTheLevelsElevationPlusTheirOwn) {
  const Plan plan = storeys_with_own_bases();
  EXPECT_EQ(base_z(plan, plan.walls[0]), 0.5);
  EXPECT_EQ(base_z(plan, plan.walls[1]), 3.1);
  EXPECT_EQ(base_z(plan, plan.walls[2]), 0.2);  // no level: as in version 1
  EXPECT_EQ(top_z(plan, plan.slabs[0]), 3.0);
  EXPECT_EQ(level_elevation(plan, "nowhere"), 0.0);
  EXPECT_EQ(find_level(plan, ""), nullptr);
}

TEST(PlanLevels, AbsoluteHeightsClearTheLevels) {
  const Plan plan = with_absolute_heights(storeys_with_own_bases());
  EXPECT_EQ(plan.walls[1].base, 3.1);
  EXPECT_TRUE(plan.walls[1].level.empty());
  EXPECT_EQ(plan.slabs[0].top, 3.0);
  EXPECT_TRUE(plan.slabs[0].level.empty());
  EXPECT_EQ(plan.levels.size(), 2u);
}

TEST(PlanLevels, APlanOfOneLevelKeepsItsWallsTheirOpeningsAndItsSlabs) {
  const Plan first = plan_of_level(storeys_with_own_bases(), "first");
  ASSERT_EQ(first.walls.size(), 1u);
  EXPECT_EQ(first.walls[0].id, "b");
  ASSERT_EQ(first.openings.size(), 1u);
  EXPECT_EQ(first.openings[0].id, "e");
  EXPECT_EQ(first.slabs.size(), 1u);
  const Plan ground = plan_of_level(storeys_with_own_bases(), "ground");
  EXPECT_EQ(ground.slabs.size(), 0u);
  EXPECT_EQ(ground.openings.size(), 1u);
  try {
    (void)plan_of_level(storeys_with_own_bases(), "attic");
    FAIL() << "no such level";
  } catch (const PreconditionError& e) {
    EXPECT_EQ(e.code(), Code::precondition);
  }
}

}  // namespace
}  // namespace roomcad
