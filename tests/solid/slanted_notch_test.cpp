// SPDX-License-Identifier: GPL-3.0-or-later
// Random-plan finding S4 (docs/stress-findings.md): an opening flush with the free end of a
// slanted wall (a notch) left, on the CGAL path, a sliver between the opening's end at u = 0
// and the wall's rounded end cap; written in doubles it made an open, self-intersecting
// solid. These are the smallest plans found by removing walls and openings from the failing
// random plans (seeds 89 and 183) while the failure lasted.
#include <gtest/gtest.h>

#include "support/model_support.h"

namespace roomcad {
namespace {

using test::add_opening;
using test::add_wall;
using test::empty_plan;
using test::expect_paths_agree;
using test::expect_valid_walls;

// From seed 89: a slanted wall with a window flush with its from end.
Plan slanted_notched_wall() {
  Plan plan = empty_plan();
  Wall& w = add_wall(plan, "w0", {18.95, 22.09}, {-21.26, -24.37});
  w.thickness = 0.233, w.height = 2.75;
  add_opening(plan, "o7", OpeningType::window, "w0", 0.0, 1.0, 0.9, 1.5);
  return plan;
}

TEST(SlantedNotch, WindowFlushWithAFreeEndOnBothPaths) {
  expect_paths_agree(slanted_notched_wall(), 0);
}

TEST(SlantedNotch, NotchedWallBuiltInACgalCluster) {
  Plan plan = slanted_notched_wall();
  Wall& through = add_wall(plan, "w4", {6.37, -41.5}, {-27.2695, -20});
  through.thickness = 0.5, through.height = 3.6737;
  expect_valid_walls(plan, BooleanPath::automatic, 0);
  expect_valid_walls(plan, BooleanPath::nef, 0);
}

// From seed 183: a window flush with the from end and the base of a raised wall crossing
// another wall.
TEST(SlantedNotch, NotchedRaisedWallCrossingAnother) {
  Plan plan = empty_plan();
  Wall& a = add_wall(plan, "w1", {-14.91, -34.7085}, {15.0643, -45.91});
  a.thickness = 0.445, a.height = 4;
  Wall& b = add_wall(plan, "w5", {32.3171, -12}, {-19.7105, -43.2627});
  b.thickness = 0.4496, b.height = 3, b.base = 0.8;
  add_opening(plan, "o15", OpeningType::window, "w5", 0.0, 1.1, 0.0, 1.36);
  expect_valid_walls(plan, BooleanPath::automatic, 0);
  expect_valid_walls(plan, BooleanPath::nef, 0);
}

}  // namespace
}  // namespace roomcad
