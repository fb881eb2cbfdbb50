// SPDX-License-Identifier: GPL-3.0-or-later
// Exact verdicts on version-2 geometry (docs/plan-format.md, "Version 2"): levels resolved,
// sloped tops, opening outlines, arc walls as their chords, slabs.
#include <gtest/gtest.h>

#include "plan_cases.h"

namespace roomcad {
namespace {

using namespace roomcad::testing;

Plan two_levels() {
  Plan p = plan_with({});
  p.site.max_height = 9;
  p.levels = {Level{.id = "ground", .elevation = 0, .height = 3},
              Level{.id = "first", .elevation = 3, .height = 3}};
  return p;
}

Wall on(std::string level, Wall w) {
  w.level = std::move(level);
  return w;
}

Slab slab(std::string id, std::string level, Polygon outline, double top = 0,
          double thickness = 0.2) {
  return Slab{.id = std::move(id),
              .level = std::move(level),
              .outline = std::move(outline),
              .top = top,
              .thickness = thickness};
}

Polygon square(double x0, double y0, double x1, double y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

TEST(Version2Checks, WallsOnDifferentLevelsOverlapOnlyWhereTheirHeightsDo) {
  Plan p = two_levels();
  // Side by side, 0.2 m apart, 0.25 m thick: one per storey, the upper one then reaching
  // down through a 0.2 m floor.
  p.walls = {on("ground", make_wall("g", {0, 0}, {4, 0}, 0.25, 3)),
             on("first", make_wall("f", {0, 0.2}, {4, 0.2}, 0.25, 3))};
  EXPECT_TRUE(validate(p, no_rooms()).ok());
  p.walls[1].base = -0.2;  // from z = 2.8: 0.2 m into the ground storey's wall
  p.walls[1].height = 3.2;
  EXPECT_EQ(error_codes(validate(p, no_rooms())), Codes{Code::wall_overlap});
}

TEST(Version2Checks, OpeningUnderASlopedTopIsJudgedAtEveryCornerOfItsOutline) {
  // Binary fractions throughout: the verdicts are exact for the numbers as read.
  Plan p = plan_with({make_wall("knee", {0, 0}, {4, 0}, 0.2, 0.5)});
  p.walls[0].height_at_end = 2.5;  // the top rises 0.5 m per metre
  // A window from u = 3 to 3.5, up to v = 1.875: the top is 2 at u = 3, so it fits.
  p.openings = {make_opening("w", OpeningType::window, "knee", 3, 0.5, 0.875, 1.0)};
  EXPECT_TRUE(validate(p, no_rooms()).ok());
  // Moved to u = 2.5: the top is 1.75 at its left edge, under its top 1.875.
  p.openings[0].offset = 2.5;
  const Report r = validate(p, no_rooms());
  ASSERT_EQ(error_codes(r), Codes{Code::opening_outside_wall});
  EXPECT_NE(r.items[0].message.find("sloped"), std::string::npos) << r.items[0].message;
  // Exactly on the slope is inside: its top-left corner at (2.75, 1.875) where the top is.
  p.openings[0].offset = 2.75;
  EXPECT_TRUE(validate(p, no_rooms()).ok());
  // A triangle whose high corner is on the right, under the slope where the rectangle is not.
  p.openings[0].offset = 2.5;
  p.openings[0].shape = {{0, 0}, {1, 0}, {1, 1}};
  EXPECT_TRUE(validate(p, no_rooms()).ok());
}

TEST(Version2Checks, ShapedOpeningsOverlapByTheirOutlinesNotTheirRectangles) {
  Plan p = plan_with({make_wall("a", {0, 0}, {6, 0})});
  // Two triangles in overlapping rectangles, apart along the diagonal: no overlap.
  p.openings = {make_opening("t1", OpeningType::window, "a", 1, 1, 1, 1),
                make_opening("t2", OpeningType::window, "a", 1.5, 1, 1, 1)};
  p.openings[0].shape = {{0, 0}, {1, 0}, {0, 1}};      // lower left half
  p.openings[1].shape = {{0.5, 1}, {0, 1}, {0, 0.5}};  // the corner at its top left
  EXPECT_TRUE(validate(p, no_rooms()).ok());
  // They touch along x + y = 1.5 when the second's corner grows to the diagonal: still none.
  p.openings[1].shape = {{1, 1}, {0, 1}, {0, 0}};
  // t2's lower-left triangle in frame of a: u in [1.5, 2.5], hypotenuse from (1.5,1) to (2.5,2)
  EXPECT_EQ(error_codes(validate(p, no_rooms())), Codes{Code::opening_overlap});
}

TEST(Version2Checks, ArcWallIsItsChords) {
  Plan p = plan_with({make_wall("bow", {0, 0}, {4, 0}, 0.25, 2.5)});
  p.walls[0].arc_extent = 90;  // bulges south, through (2, 2 - 2 sqrt 2)
  // Its polyline is longer than the chord (4.44 m): an opening from 4 to 4.3 fits.
  p.openings = {make_opening("w", OpeningType::window, "bow", 4, 0.3, 1, 1)};
  EXPECT_TRUE(validate(p, no_rooms()).ok());
  p.openings[0].offset = 4.3;  // past its end (pi * sqrt 2 / 2 = 4.443)
  EXPECT_EQ(error_codes(validate(p, no_rooms())), Codes{Code::opening_outside_wall});
  p.openings.clear();
  // A wall beside the arc's bulge (its centre line at y = -0.6, the arc's below -0.78 there)
  // overlaps it; a wall near the chord does not.
  p.walls.push_back(make_wall("x", {1.5, -0.6}, {2.5, -0.6}, 0.4, 2.5));
  EXPECT_EQ(error_codes(validate(p, no_rooms())), Codes{Code::wall_overlap});
  p.walls[1] = make_wall("x", {1.9, 0.2}, {2.1, 0.2}, 0.1, 2.5);
  EXPECT_TRUE(validate(p, no_rooms()).ok());
}

TEST(Version2Checks, SlabsOverlapWhenTheirAreasAndBandsDo) {
  Plan p = two_levels();
  p.slabs = {slab("s1", "first", square(0, 0, 4, 4)), slab("s2", "first", square(4, 0, 8, 4))};
  EXPECT_TRUE(validate(p, no_rooms()).ok());  // side by side: touching
  p.slabs[1].outline = square(3.5, 0, 8, 4);
  const Report r = validate(p, no_rooms());
  ASSERT_EQ(error_codes(r), Codes{Code::slab_overlap});
  EXPECT_EQ(r.items[0].objects, (Ids{"s1", "s2"}));
  // On top of one another (the second's band is 0.2 m higher): no overlap.
  p.slabs[1].top = 0.2;
  EXPECT_TRUE(validate(p, no_rooms()).ok());
  // A landing inside the stair well of the other: no overlap; grown past the well's edge: one.
  p.slabs = {slab("floor", "first", square(0, 0, 8, 8)),
             slab("landing", "first", square(2, 2, 3, 3))};
  p.slabs[0].holes = {square(2, 2, 4, 4)};
  EXPECT_TRUE(validate(p, no_rooms()).ok());
  p.slabs[1].outline = square(2, 2, 4.001, 3);
  EXPECT_EQ(error_codes(validate(p, no_rooms())), Codes{Code::slab_overlap});
}

TEST(Version2Checks, SlabThroughAnOpeningBlocksIt) {
  Plan p = two_levels();
  p.walls = {on("ground", make_wall("a", {0, 0}, {6, 0}, 0.25, 3))};
  p.openings = {make_opening("w", OpeningType::window, "a", 1, 1, 1.0, 2.0)};  // z 2 .. 3
  // The first floor, z 2.75 .. 3, runs into the wall from the south.
  p.slabs = {slab("first_floor", "first", square(-1, -3, 7, 0), 0, 0.25)};
  const Report r = validate(p, no_rooms());
  ASSERT_EQ(error_codes(r), Codes{Code::opening_blocked});
  EXPECT_EQ(r.items[0].objects, (Ids{"w", "a", "first_floor"}));
  p.openings[0].height = 0.75;  // up to z = 2.75: touching the slab's underside
  EXPECT_TRUE(validate(p, no_rooms()).ok());
  p.openings[0].height = 1.0;
  p.slabs[0].outline = square(-1, -3, 7, -0.125);  // up to the wall's face: touching
  EXPECT_TRUE(validate(p, no_rooms()).ok());
  p.slabs[0].holes = {square(0.5, -0.5, 2.5, -0.25)};  // a hole does not unblock what it misses
  p.slabs[0].outline = square(-1, -3, 7, 0);
  EXPECT_EQ(error_codes(validate(p, no_rooms())), Codes{Code::opening_blocked});
}

TEST(Version2Checks, SlabsAndLevelsStayInsideTheSiteAndUnderMaxHeight) {
  Plan p = two_levels();
  p.slabs = {slab("s", "first", square(0, 0, 70, 4))};  // the site ends at x = 64
  EXPECT_EQ(error_codes(validate(p, no_rooms())), Codes{Code::out_of_bounds});
  p.slabs = {slab("s", "ground", square(0, 0, 4, 4))};  // z -0.2 .. 0: below the ground
  EXPECT_EQ(error_codes(validate(p, no_rooms())), Codes{Code::out_of_bounds});
  p.slabs.clear();
  p.levels[1].height = 6.5;  // a nominal storey past max_height is no error: its walls are judged
  EXPECT_TRUE(validate(p, no_rooms()).ok());
  p.levels[1].elevation = 9.5;  // its floor above max_height is
  const Report r = validate(p, no_rooms());
  ASSERT_EQ(error_codes(r), Codes{Code::out_of_bounds});
  EXPECT_EQ(r.items[0].objects, Ids{"first"});
  p.levels[1] = {.id = "first", .elevation = 3, .height = 3};
  // A wall of the ground level reaching below it reaches below the ground.
  p.walls = {on("ground", make_wall("a", {0, 0}, {4, 0}))};
  p.walls[0].base = -0.1;
  EXPECT_EQ(error_codes(validate(p, no_rooms())), Codes{Code::out_of_bounds});
  p.walls[0].level.clear();  // without a level a negative base is not a value at all
  EXPECT_EQ(error_codes(validate(p, no_rooms())), Codes{Code::invalid_value});
}

TEST(Version2Checks, OutlinesMustBeSimpleAndHolesInside) {
  Plan p = two_levels();
  p.slabs = {slab("bow_tie", "first", {{0, 0}, {4, 4}, {4, 0}, {0, 4}})};
  EXPECT_EQ(error_codes(validate(p, no_rooms())), Codes{Code::invalid_value});
  p.slabs = {slab("s", "first", square(0, 0, 4, 4))};
  p.slabs[0].holes = {square(3, 3, 5, 5)};
  EXPECT_EQ(error_codes(validate(p, no_rooms())), Codes{Code::invalid_value});
  p.slabs[0].holes = {square(1, 1, 2, 2), square(2, 1, 3, 2)};  // two holes touching
  EXPECT_EQ(error_codes(validate(p, no_rooms())), Codes{Code::invalid_value});
  p.slabs[0].holes = {square(1, 1, 2, 2), square(2.5, 1, 3, 2)};
  EXPECT_TRUE(validate(p, no_rooms()).ok());
  p.walls = {make_wall("a", {0, 0}, {4, 0})};
  p.openings = {make_opening("w", OpeningType::window, "a", 1, 1, 1, 1)};
  p.openings[0].shape = {{0, 0}, {1, 1}, {1, 0}, {0, 1}};
  EXPECT_EQ(error_codes(validate(p, no_rooms())), Codes{Code::invalid_value});
  p.openings[0].shape = {{0, 0}, {1.5, 0}, {0, 1}};
  EXPECT_EQ(error_codes(validate(p, no_rooms())), Codes{Code::invalid_value});
}

// A door in a wall that reaches below its level's floor is at the floor when its sill is that
// depth exactly. The fix gives the depth as a person reads it, and the exact value where the
// rounded one would leave the door off the floor (Sweet Home 3D's float depths).
TEST(Version2Checks, DoorAboveTheFloorFixGivesTheExactDepthWhereRoundingWouldNotClearIt) {
  for (const auto& [depth, fix] :
       {std::pair{0.12, "set its sill to 0.12 m, the depth"},
        std::pair{0.11999988555908203,
                  "set its sill to 0.120 m (exactly 0.11999988555908203 m)"}}) {
    Plan p = two_levels();
    Wall w = on("first", make_wall("w", {0, 0}, {4, 0}, 0.2));
    w.base = -depth;
    w.height = 3;
    p.walls = {w};
    p.openings = {make_opening("d", OpeningType::door, "w", 1, 0.9, 2.1, depth + 0.1)};
    Report r = validate(p);
    ASSERT_EQ(r.items.size(), 1u);
    EXPECT_EQ(r.items[0].code, Code::door_above_floor);
    EXPECT_TRUE(r.items[0].fix.starts_with(fix)) << r.items[0].fix;
    p.openings[0].sill = depth;  // the fix, exactly as written, clears it
    EXPECT_TRUE(validate(p).items.empty());
  }
}

}  // namespace
}  // namespace roomcad
