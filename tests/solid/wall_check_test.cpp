// SPDX-License-Identifier: GPL-3.0-or-later
// check_walls (solid/wall_check.h), the verdict of `roomcad build --check`: its volume limit
// is 1e-9 relative plus what rounding the vertices to doubles allows, so a solid as exact as
// doubles can write passes and one of another volume does not.
#include <gtest/gtest.h>

#include "support/model_support.h"

namespace roomcad {
namespace {

using test::add_opening;
using test::add_wall;
using test::empty_plan;
using test::kDoor;
using test::kWindow;

TEST(WallCheck, AUnitBoxMayBeOffByOneBillionthPlusItsAreaTimesAnUlp) {
  Plan plan = empty_plan();
  Wall& w = add_wall(plan, "box", {0.0, 0.5}, {1.0, 0.5});
  w.thickness = 1.0, w.height = 1.0;
  const Model model = build_model(plan);
  // Its vertices reach 1 m (an ulp of 2.2e-16 m) and its faces have 6 square metres.
  EXPECT_DOUBLE_EQ(vertex_rounding(model.walls), 0x1p-52);
  EXPECT_DOUBLE_EQ(volume_tolerance(model.walls, 1.0), 1e-9 + 6.0 * 0x1p-52);
  const WallCheck check = check_walls(model, plan);
  EXPECT_TRUE(check.ok);
  EXPECT_DOUBLE_EQ(check.limit, 1e-9 + 6.0 * 0x1p-52);
}

// A wall a hundredth of a micrometre thick, 48 m long, 40 m from the origin, cut in two by a
// full-height gap and with a window at its end (a fuzzed plan, stress finding S6): the
// corners of its pieces are rounded by up to 3.6e-15 m across its 5e-9 m half thickness, so
// its volume can be off by 1e-7 of itself however it is built. That passes; a plan whose
// volume is 1e-3 larger does not.
TEST(WallCheck, AWallAHundredthOfAMicrometreThickPassesWithinWhatRoundingAllowsAndNoMore) {
  Plan plan = empty_plan();
  Wall& w = add_wall(plan, "hair", {-13.9, 43.100000000000001},
                     {-33.900000000000006, -0.90000000000000047});
  w.thickness = 1e-8, w.height = 25.0;
  add_opening(plan, "gap", kDoor, "hair", 16.666091947189145, 15.0, 0.0, 25.0);
  add_opening(plan, "window", kWindow, "hair", 48.332183884378288, 1e-8, 7.0, 18.0);
  const Model model = build_model(plan);
  const WallCheck check = check_walls(model, plan);
  EXPECT_GT(check.relative, 1e-9);
  EXPECT_TRUE(check.ok) << check.relative;

  Plan thicker = plan;
  thicker.walls[0].thickness = 1.001e-8;
  EXPECT_FALSE(check_walls(model, thicker).ok);
}

// A solid of 5.7e-15 m^3 that spans 46 m, 10 m high, 36 m from the origin (a fuzzed plan,
// stress finding S6: a wall a hundredth of a micrometre long and thick, and one as thick and
// as high, 46.9 m long, mitred to it). Summed in doubles, even relative to one of its points,
// its triangles' volumes read 110 times the analytic volume; check_solid sums them exactly.
TEST(WallCheck, ATinySolidSpanningMetresFarFromTheOriginHasItsVolume) {
  Plan plan = empty_plan();
  Wall& a = add_wall(plan, "a", {36.099999999999994, 46.099999999999994},
                     {36.100000000000001, 46.100000009999995});
  a.thickness = 1e-8, a.height = 10.0, a.base = -5.0;
  Wall& b =
      add_wall(plan, "b", {6.0999999999999988, 10.1}, {36.100000000000001, 46.100000009999995});
  b.thickness = 1e-8, b.height = 1e-8, b.base = -5.0;
  const WallCheck check = check_walls(build_model(plan), plan);
  EXPECT_TRUE(check.solid.is_valid());
  EXPECT_LT(check.relative, 1e-6);
  EXPECT_TRUE(check.ok) << check.solid.volume << " against " << check.analytic;
}

// Built without its slabs (`--parts walls`), the solid is the walls' alone, and so is the
// volume it is checked against: it was checked against the volume with the floor slab (2.4 m^3
// more) and failed; so did `build --parts walls --check` on examples/version2/two-storey.json.
TEST(WallCheck, AModelBuiltWithoutItsSlabsIsCheckedAgainstTheWallsAlone) {
  Plan plan = empty_plan();
  test::add_room(plan, "r", 0.0, 0.0, 4.0, 3.0);
  Slab& floor = plan.slabs.emplace_back();
  floor.id = "floor", floor.outline = {{0.0, 0.0}, {4.0, 0.0}, {4.0, 3.0}, {0.0, 3.0}},
  floor.top = 0.0, floor.thickness = 0.2;
  for (const bool slabs : {true, false}) {
    SCOPED_TRACE(slabs ? "with slabs" : "without slabs");
    const Model model = build_model(plan, BuildOptions{.parts = {.slabs = slabs}});
    const WallCheck check = check_walls(model, plan);
    EXPECT_TRUE(check.ok) << check.solid.volume << " against " << check.analytic;
  }
}

}  // namespace
}  // namespace roomcad
