// SPDX-License-Identifier: GPL-3.0-or-later
// The general path (detail/general_solid.h) on what the fast path cannot build and what
// plans with errors hold (built as `--force` builds them): each solid is checked (closed,
// 2-manifold, no self-intersection, outward, genus) and its volume is compared with the
// analytic volume and with the Nef reference's, face kind by face kind (expect_paths_agree).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include "solid/analytic_volume.h"
#include "support/model_support.h"

namespace roomcad {
namespace {

using test::add_opening;
using test::add_room;
using test::add_wall;
using test::empty_plan;
using test::expect_paths_agree;
using test::kDoor;
using test::kWindow;

BuildStats stats_of(const Plan& plan, BooleanPath path) {
  BuildStats stats;
  (void)build_model(plan, test::options_for(path), &stats);
  return stats;
}

TEST(GeneralSolid, BowTieWallKeepsThePartBetweenItsEnds) {
  // b is shorter than its mitres: its two mitre lines cross inside it (Nef used to crash).
  Plan plan = empty_plan();
  add_wall(plan, "a", {0, 0}, {4, 0}).thickness = 0.3;
  add_wall(plan, "b", {4, 0}, {4, 0.1}).thickness = 0.3;
  add_wall(plan, "c", {4, 0.1}, {0, 0.2}).thickness = 0.3;
  expect_paths_agree(plan, 0);
}

TEST(GeneralSolid, OverlappingWallsAreUnited) {
  Plan plan = empty_plan();
  add_wall(plan, "a", {0, 0}, {4, 0});
  add_wall(plan, "b", {1, 0.05}, {5, 0.05});  // not joined: their centre lines do not meet
  add_opening(plan, "win", kWindow, "a", 0.5, 1.0, 1.0, 1.0);
  expect_paths_agree(plan, 1);
}

TEST(GeneralSolid, CoincidentWallsAreOneSolid) {
  Plan plan = empty_plan();
  add_wall(plan, "a", {0, 0}, {4, 0});
  add_wall(plan, "b", {0, 0}, {4, 0});
  add_opening(plan, "door", kDoor, "b", 1.0, 0.9, 0.0, 2.1);
  // The door's hole goes through both (it spans the same thickness): a wall with a doorway.
  expect_paths_agree(plan, 0, 4 * 0.2 * 2.5 - 0.9 * 0.2 * 2.1);
}

TEST(GeneralSolid, ThinWallInsideAThickOneLeavesNoHoleInAnyFace) {
  // b lies inside a and rises through its top: a's top face would have a hole around b.
  Plan plan = empty_plan();
  add_wall(plan, "a", {0, 0}, {4, 0}).thickness = 0.6;
  Wall& b = add_wall(plan, "b", {1, 0}, {3, 0});
  b.thickness = 0.1;
  b.height = 3.5;
  add_opening(plan, "win", kWindow, "a", 1.5, 1.0, 1.0, 1.0);  // and a window through both
  expect_paths_agree(plan, 1);
}

TEST(GeneralSolid, OpeningAcrossAMitredCorner) {
  Plan plan = empty_plan();
  add_wall(plan, "a", {0, 0}, {4, 0});
  add_wall(plan, "b", {4, 0}, {4, 3});
  add_opening(plan, "corner", kWindow, "a", 3.5, 0.5, 1.0, 1.0);  // up to a's mitred end
  expect_paths_agree(plan, 1);
}

TEST(GeneralSolid, MitreOfWallsOfDifferentHeightsAndBases) {
  Plan plan = empty_plan();
  add_wall(plan, "a", {0, 0}, {4, 0}).height = 3.0;
  Wall& b = add_wall(plan, "b", {4, 0}, {4, 3});
  b.base = 0.5;
  b.height = 1.5;
  EXPECT_GT(stats_of(plan, BooleanPath::automatic).general_path_walls, 0u);
  expect_paths_agree(plan, 0);
}

TEST(GeneralSolid, BlockedOpeningCutsTheWallInFrontOfIt) {
  // c runs along a's face over its window: the window's hole (a's thickness) stops at a's face.
  Plan plan = empty_plan();
  add_wall(plan, "a", {0, 0}, {4, 0});
  add_wall(plan, "c", {1, 0.15}, {3, 0.15}).thickness = 0.1;
  add_opening(plan, "win", kWindow, "a", 1.5, 1.0, 1.0, 1.0);
  expect_paths_agree(plan, 0);
}

TEST(GeneralSolid, WallStandingOnAnotherIsFused) {
  Plan plan = empty_plan();
  add_wall(plan, "low", {0, 0}, {4, 0});
  Wall& high = add_wall(plan, "high", {1, 0}, {5, 0});
  high.base = 2.5;
  expect_paths_agree(plan, 0, 4 * 0.2 * 2.5 * 2);
}

TEST(GeneralSolid, WindowsLevelWithEachOtherStoreyOverStorey) {
  // Every side face of these walls has holes (the windows); two holes of one face level with
  // each other share a cut, and each cut reaches across its own wall only, not across the
  // neighbour on the same plane nor the storey above.
  Plan plan = empty_plan();
  for (const double base : {0.0, 2.5})
    for (const double x : {0.0, 4.0}) {
      const std::string id = fmt::format("w{}-{}", x, base);
      add_wall(plan, id, {x, 0}, {x + 4, 0}).base = base;
      add_opening(plan, id + "a", kWindow, id, 0.5, 1.0, 1.0, 1.0);
      add_opening(plan, id + "b", kWindow, id, 2.5, 1.0, 1.0, 1.0);
    }
  expect_paths_agree(plan, 8, 4 * (4 * 0.2 * 2.5 - 2 * 0.2 * 1.0 * 1.0));
}

TEST(GeneralSolid, RoomsWithWindowsTurnedAndFarAway) {
  Plan plan = empty_plan();
  add_room(plan, "r", 0, 0, 4, 3);
  add_room(plan, "s", 4, 0, 3, 3);  // shares r's east wall's line: walls overlapping along it
  add_opening(plan, "w1", kWindow, "r0", 1.0, 1.0, 1.0, 1.0);
  add_opening(plan, "w2", kWindow, "s2", 0.5, 1.0, 1.0, 1.0);
  add_opening(plan, "d1", kDoor, "r1", 1.0, 0.9, 0.0, 2.1);
  expect_paths_agree(test::transformed(plan, 17.0, 1e5, -3e4), 4);
}

TEST(GeneralSolid, EveryWallOfAPlanWithErrorsBuildsWithoutNef) {
  Plan plan = empty_plan();
  add_room(plan, "r", 0, 0, 4, 3);
  add_wall(plan, "over", {1, 0.05}, {3, 0.05});
  const BuildStats stats = stats_of(plan, BooleanPath::automatic);
  EXPECT_EQ(stats.nef_path_walls, 0u);
  EXPECT_EQ(stats.fast_path_walls + stats.general_path_walls, plan.walls.size());
  EXPECT_EQ(stats_of(plan, BooleanPath::nef).nef_path_walls, plan.walls.size());
}

// A slab whose corner lies on a wall's top edge touches the wall at that point only (a valid
// plan): the solid as written has a copy of the point for each, and checks valid.
TEST(GeneralSolid, SlabCornerOnAWallsTopEdgeTouchesItAtAPoint) {
  Plan plan = empty_plan();
  add_wall(plan, "a", {1, 1}, {5, 1}).thickness = 0.25;
  Slab& lid = plan.slabs.emplace_back();
  lid.id = "lid", lid.outline = {{1.75, 1.125}, {2, 2}, {1.5, 2}}, lid.top = 2.75,
  lid.thickness = 0.25;
  const Model model = build_model(plan, test::options_for(BooleanPath::general));
  const SolidCheck c = check_solid(model.walls);
  EXPECT_TRUE(c.is_valid());
  EXPECT_EQ(c.components, 2u);
  EXPECT_GT(c.touching_pairs, 0u);
  EXPECT_NEAR(c.volume, analytic_wall_volume(plan), 1e-12);
}

}  // namespace
}  // namespace roomcad
