// SPDX-License-Identifier: GPL-3.0-or-later
// fine_feature (solid/detail/frames/fine_features.h): which plans build_model checks as written
// before it returns their solid, and how it names why.
#include <gtest/gtest.h>

#include <cmath>

#include "solid/detail/frames/fine_features.h"
#include "support/model_support.h"
#include "testing/tower_plan.h"

namespace roomcad {
namespace {

using detail::fine_feature;
using test::add_opening;
using test::add_wall;
using test::empty_plan;
using test::kWindow;

TEST(FineFeatures, AnOrdinaryPlanHasNone) {
  Plan plan = empty_plan();
  test::add_room(plan, "r", 0.0, 0.0, 4.0, 3.0);
  add_opening(plan, "win", kWindow, plan.walls.front().id, 1.0, 1.0, 0.9, 1.2);
  EXPECT_EQ(fine_feature(plan), std::nullopt);
}

TEST(FineFeatures, EachDimensionUnderATenthOfAMicrometreIsNamedWithItsSize) {
  struct Case {
    const char* expected;
    void (*change)(Plan&);
  };
  for (const Case& c : {
           Case{"wall 'w' is 5e-08 m long",
                [](Plan& p) {
                  p.walls[0].to = {5e-8, 0.0};
                }},
           Case{"wall 'w' is 1e-09 m thick", [](Plan& p) { p.walls[0].thickness = 1e-9; }},
           Case{"wall 'w' is 2e-08 m high", [](Plan& p) { p.walls[0].height = 2e-8; }},
           Case{"wall 'w' is 5e-08 m high at its end",
                [](Plan& p) { p.walls[0].height_at_end = 5e-8; }},
           Case{"opening 'o' is 3e-09 m wide", [](Plan& p) { p.openings[0].width = 3e-9; }},
           Case{"opening 'o' is 2e-08 m high", [](Plan& p) { p.openings[0].height = 2e-8; }},
       }) {
    SCOPED_TRACE(c.expected);
    Plan plan = empty_plan();
    add_wall(plan, "w", {0.0, 0.0}, {4.0, 0.0});
    add_opening(plan, "o", kWindow, "w", 1.0, 1.0, 0.9, 1.2);
    c.change(plan);
    EXPECT_EQ(fine_feature(plan), std::optional<std::string>(c.expected));
  }
  // The bound itself is not finer than the bound.
  Plan plan = empty_plan();
  add_wall(plan, "w", {0.0, 0.0}, {4.0, 0.0}).thickness = detail::kFinestFeature;
  EXPECT_EQ(fine_feature(plan), std::nullopt);
}

// A step a nanometre high between two walls' bases (a fuzzed plan whose solid crossed itself).
TEST(FineFeatures, AStepUnderATenthOfAMicrometreBetweenTwoHeightsIsNamed) {
  Plan plan = empty_plan();
  add_wall(plan, "a", {-2.1, 2.9}, {0.0, -1.0});
  add_wall(plan, "b", {0.0, -1.0}, {2.0, 0.0}).base = 1e-9;
  EXPECT_EQ(
      fine_feature(plan),
      std::optional<std::string>(
          "the base of wall 'b' (z 1e-09 m) lies 1e-09 m above the base of wall 'a' (z 0 m)"));
  plan.walls[1].base = 0.0;  // level: no step
  EXPECT_EQ(fine_feature(plan), std::nullopt);
  plan.walls[0].base = 0.0;
  plan.walls[1].base = 0.1 + 0.2;  // 0.30000000000000004
  plan.walls[0].height = 0.3;      // its top, an ulp below b's base
  EXPECT_EQ(fine_feature(plan), std::nullopt);
}

// Levels' elevations plus heights meet an ulp or two apart in a multi-storey plan: no step.
TEST(FineFeatures, TheTowerHasNone) {
  EXPECT_EQ(fine_feature(samples::make_tower_plan({})), std::nullopt);
}

// A wall an ulp off the y axis at 1 km (a fuzzed plan whose solid crossed itself), and two
// walls an ulp of angle apart; walls exactly parallel are not, however their directions round.
TEST(FineFeatures, WallsUnderAHundredthOfANanoradianApartAreNamed) {
  Plan plan = empty_plan();
  add_wall(plan, "w", {999.6, 1002.9}, {999.6000000000001, 1000.0});
  const auto found = fine_feature(plan);
  ASSERT_TRUE(found.has_value());
  EXPECT_TRUE(found->starts_with("wall 'w' runs 3.9")) << *found;
  EXPECT_TRUE(found->ends_with("rad off the y axis")) << *found;

  Plan two = empty_plan();
  add_wall(two, "a", {0.0, 0.0}, {std::sqrt(3.0), 1.0});
  add_wall(two, "b", {0.0, 1.0}, {std::sqrt(3.0), std::nextafter(2.0, 3.0)});
  ASSERT_TRUE(fine_feature(two).has_value());
  EXPECT_TRUE(fine_feature(two)->starts_with("wall 'b' runs ")) << *fine_feature(two);

  Plan parallel = empty_plan();
  add_wall(parallel, "a", {0.0, 0.0}, {3.0, 1.0});
  add_wall(parallel, "b", {0.0, 1.0}, {3.0, 2.0});
  add_wall(parallel, "c", {6.0, 2.0}, {1.5, 0.5});  // along a, drawn the other way
  add_wall(parallel, "d", {0.0, 0.0}, {0.0, 3.0});
  EXPECT_EQ(fine_feature(parallel), std::nullopt);
}

// Walls drawn along one line an ulp of angle apart, either way round (a fuzzed plan whose
// solid crossed itself: their angles round to the same double, their directions differ).
TEST(FineFeatures, WallsAlongOneLineDrawnAnUlpApartAreNamed) {
  Plan plan = empty_plan();
  add_wall(plan, "a", {1.075, 0.8499999999999999}, {0.42500000000000004, -0.15});
  add_wall(plan, "b", {0.425, -0.15}, {1.075, 0.8499999999999999});
  const auto found = fine_feature(plan);
  ASSERT_TRUE(found.has_value());
  EXPECT_TRUE(found->starts_with("wall 'b' runs ")) << *found;
  EXPECT_TRUE(found->ends_with(" rad off wall 'a'")) << *found;
  EXPECT_EQ(found->find("runs 0 rad"), std::string::npos) << *found;
}

// Parallel walls on lines 1e-17 m apart are named; 3e-7 m apart (two real homes have such)
// they are not.
TEST(FineFeatures, ParallelWallsOnLinesUnderATenthOfAMicrometreApartAreNamed) {
  Plan plan = empty_plan();
  add_wall(plan, "a", {0.0, 0.0}, {4.0, 0.0});
  add_wall(plan, "b", {8.0, 1e-17}, {4.0, 1e-17});
  EXPECT_EQ(fine_feature(plan), std::optional<std::string>(
                                    "wall 'a' runs parallel to wall 'b', 1e-17 m from its line"));

  Plan apart = empty_plan();
  add_wall(apart, "a", {0.0, 0.0}, {4.0, 0.0});
  add_wall(apart, "b", {4.0, 3e-7}, {8.0, 3e-7});
  EXPECT_EQ(fine_feature(apart), std::nullopt);
}

// A wall drawn over another along one line, ending an ulp past it, is named (a fuzzed plan
// whose written solid was open); walls that meet end to end, or end a millimetre apart, are not.
TEST(FineFeatures, WallEndsAlongOneLineUnderATenthOfAMicrometreApartAreNamed) {
  Plan plan = empty_plan();
  add_wall(plan, "a", {-0.5, -1.0}, {-1.0, -1.0});
  add_wall(plan, "b", {-0.5, -1.0}, {std::nextafter(-1.0, -2.0), -1.0});
  EXPECT_EQ(fine_feature(plan),
            std::optional<std::string>(
                "an end of wall 'b' lies 2.22e-16 m along their line from an end of wall 'a'"));

  Plan meeting = empty_plan();
  add_wall(meeting, "a", {0.0, 2.0}, {4.0, 2.0});
  add_wall(meeting, "b", {4.0, 2.0}, {7.0, 2.0});
  add_wall(meeting, "c", {7.001, 2.0}, {9.0, 2.0});
  EXPECT_EQ(fine_feature(meeting), std::nullopt);
}

TEST(FineFeatures, ACornerPastTenKilometresIsNamedWithItsDistance) {
  Plan plan = empty_plan();
  add_wall(plan, "near", {0.0, 0.0}, {4.0, 0.0});
  add_wall(plan, "far", {-749984.0, -749974.0}, {-749984.0, -750000.0});
  EXPECT_EQ(fine_feature(plan),
            std::optional<std::string>(
                "wall 'far' reaches (-749984, -749974), 1.06e+06 m from the origin"));
}

}  // namespace
}  // namespace roomcad
