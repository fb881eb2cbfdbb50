// SPDX-License-Identifier: GPL-3.0-or-later
#include "plan/plan_objects.h"

#include <gtest/gtest.h>

namespace roomcad {
namespace {

Plan plan_with(std::vector<std::string> wall_ids, std::vector<std::string> opening_walls) {
  Plan plan;
  for (std::string& id : wall_ids) {
    Wall w;
    w.id = std::move(id);
    plan.walls.push_back(w);
  }
  for (std::size_t i = 0; i < opening_walls.size(); ++i) {
    Opening o;
    o.id = "o";
    o.id += std::to_string(i);
    o.wall = std::move(opening_walls[i]);
    plan.openings.push_back(o);
  }
  return plan;
}

TEST(PlanObjects, ListsEachWallsOpeningsInPlanOrder) {
  const Plan plan = plan_with({"a", "b", "c"}, {"b", "a", "b", "b"});
  const OpeningsByWall by_wall = openings_by_wall(plan);
  ASSERT_EQ(by_wall.size(), 3u);
  EXPECT_EQ(by_wall[0], (std::vector<std::size_t>{1}));
  EXPECT_EQ(by_wall[1], (std::vector<std::size_t>{0, 2, 3}));
  EXPECT_TRUE(by_wall[2].empty());
}

// A plan with errors: the first wall with a shared id hosts, as validation reads it; an
// opening naming no wall is in no list.
TEST(PlanObjects, TheFirstWallOfAnIdHostsAndUnknownWallsHostNothing) {
  const Plan plan = plan_with({"a", "a", "b"}, {"a", "missing", "b", ""});
  const OpeningsByWall by_wall = openings_by_wall(plan);
  ASSERT_EQ(by_wall.size(), 3u);
  EXPECT_EQ(by_wall[0], (std::vector<std::size_t>{0}));
  EXPECT_TRUE(by_wall[1].empty());
  EXPECT_EQ(by_wall[2], (std::vector<std::size_t>{2}));
}

}  // namespace
}  // namespace roomcad
