// SPDX-License-Identifier: GPL-3.0-or-later
// Rooms from the wall arrangement, their clear areas, and the room warnings.
#include <cmath>

#include <gtest/gtest.h>

#include "plan_cases.h"

namespace roomcad {
namespace {

using namespace roomcad::testing;

/// Two 4 x 4 m rooms (centre lines) side by side, 0.2 m walls; a door between them and a
/// window in the south wall of the west room only.
Plan two_rooms() {
  return plan_with({make_wall("s", {0, 0}, {8, 0}, 0.2), make_wall("e", {8, 0}, {8, 4}, 0.2),
                    make_wall("n", {8, 4}, {0, 4}, 0.2), make_wall("w", {0, 4}, {0, 0}, 0.2),
                    make_wall("m", {4, 0}, {4, 4}, 0.2)},
                   {make_opening("d", OpeningType::door, "m", 1, 0.9, 2.1, 0),
                    make_opening("win", OpeningType::window, "s", 1, 1.2, 1.2, 0.9)});
}

TEST(Rooms, TwoRoomsWithClearAreasAndTheirOpenings) {
  const std::vector<Room> rooms = find_rooms(two_rooms());
  ASSERT_EQ(rooms.size(), 2u);
  // Numbered from the south-west; clear floor 3.8 x 3.8 m inside 0.2 m walls.
  EXPECT_NEAR(rooms[0].area, 3.8 * 3.8, 1e-9);
  EXPECT_NEAR(rooms[1].area, 3.8 * 3.8, 1e-9);
  EXPECT_EQ(rooms[0].walls, (Ids{"m", "n", "s", "w"}));
  EXPECT_EQ(rooms[1].walls, (Ids{"e", "m", "n", "s"}));
  EXPECT_EQ(rooms[0].doors, Ids{"d"});
  EXPECT_EQ(rooms[1].doors, Ids{"d"});
  EXPECT_EQ(rooms[0].windows, Ids{"win"});
  EXPECT_TRUE(rooms[1].windows.empty());
  ASSERT_EQ(rooms[0].outline.size(), 4u);
  for (const Point2& c : rooms[0].outline) {  // the clear floor: [0.1, 3.9] x [0.1, 3.9]
    EXPECT_TRUE(std::fabs(c.x - 0.1) < 1e-12 || std::fabs(c.x - 3.9) < 1e-12) << c.x;
    EXPECT_TRUE(std::fabs(c.y - 0.1) < 1e-12 || std::fabs(c.y - 3.9) < 1e-12) << c.y;
  }
}

TEST(Rooms, WarningsForARoomWithoutWindowAndWithoutDoor) {
  Plan p = two_rooms();
  Report r = validate(p);
  EXPECT_TRUE(r.ok());
  ASSERT_EQ(r.items.size(), 1u);
  EXPECT_EQ(r.items[0].code, Code::room_without_window);
  EXPECT_EQ(r.items[0].objects, (Ids{"e", "m", "n", "s"}));
  EXPECT_NE(r.items[0].message.find("room 2"), std::string::npos) << r.items[0].message;

  p.openings.erase(p.openings.begin());  // no door anywhere now
  r = validate(p);
  EXPECT_EQ(r.warning_count(), 3u);
  EXPECT_EQ(validate(p, no_rooms()).warning_count(), 0u);
}

TEST(Rooms, OpenPlansHaveNoRoomsAndRoomsInsideRoomsAreSubtracted) {
  Plan open = two_rooms();
  open.walls.erase(open.walls.begin() + 1);  // no east wall: only the west room is closed
  EXPECT_EQ(find_rooms(open).size(), 1u);

  Plan nested =
      plan_with({make_wall("s", {0, 0}, {10, 0}, 0.2), make_wall("e", {10, 0}, {10, 10}, 0.2),
                 make_wall("n", {10, 10}, {0, 10}, 0.2), make_wall("w", {0, 10}, {0, 0}, 0.2),
                 make_wall("is", {4, 4}, {6, 4}, 0.2), make_wall("ie", {6, 4}, {6, 6}, 0.2),
                 make_wall("in", {6, 6}, {4, 6}, 0.2), make_wall("iw", {4, 6}, {4, 4}, 0.2)});
  const std::vector<Room> rooms = find_rooms(nested);
  ASSERT_EQ(rooms.size(), 2u);
  EXPECT_NEAR(rooms[0].area, 9.8 * 9.8 - 2 * 2, 1e-9);  // centre-line area of the inner room
  EXPECT_NEAR(rooms[1].area, 1.8 * 1.8, 1e-9);
}

TEST(Rooms, CrossingWallsAndToleranceJoinsUseTheExactArrangement) {
  // Two walls crossing in an X inside a square (the crossing is no wall end): four rooms.
  Plan cross =
      plan_with({make_wall("s", {0, 0}, {8, 0}, 0.2), make_wall("e", {8, 0}, {8, 8}, 0.2),
                 make_wall("n", {8, 8}, {0, 8}, 0.2), make_wall("w", {0, 8}, {0, 0}, 0.2),
                 make_wall("h", {0, 4}, {8, 4}, 0.2), make_wall("v", {4, 0}, {4, 8}, 0.2)});
  std::vector<Room> rooms = find_rooms(cross);
  ASSERT_EQ(rooms.size(), 4u);
  for (const Room& r : rooms) EXPECT_NEAR(r.area, 3.8 * 3.8, 1e-9);
  EXPECT_EQ(rooms[0].walls, (Ids{"h", "s", "v", "w"}));
  // A corner whose ends are 0.5 um apart (within the tolerance) still closes its room.
  Plan gap =
      plan_with({make_wall("s", {0, 0}, {4, 0}, 0.2), make_wall("e", {4, 0}, {4, 4}, 0.2),
                 make_wall("n", {4, 4}, {0, 4}, 0.2), make_wall("w", {0, 4}, {0, 0.5e-6}, 0.2)});
  rooms = find_rooms(gap);
  ASSERT_EQ(rooms.size(), 1u);
  EXPECT_NEAR(rooms[0].area, 3.8 * 3.8, 1e-5);
}

TEST(Rooms, TwoBoundaryVerticesThatRoundToOneDoubleLeaveAFiniteOutline) {
  // From 4-BedroomHouse: "e2" starts at the double nearest to where the sloping north wall
  // crosses x = 13.455; the exact crossing and that double are two vertices of the room's
  // boundary, and the edge between them has no length in doubles.
  const Plan plan =
      plan_with({make_wall("n", {11.252909, 0.054999795}, {13.588015, 0.055}, 0.26),
                 make_wall("e1", {13.455, 0.055}, {13.455, -4.661}, 0.26),
                 make_wall("e2", {13.455, 0.054999988322553664}, {13.455, -4.661}, 0.26),
                 make_wall("s", {13.455, -4.661}, {11.252909, -4.661}, 0.26),
                 make_wall("w", {11.252909, -4.661}, {11.252909, 0.054999795}, 0.26)});
  const std::vector<Room> rooms = find_rooms(plan);
  ASSERT_EQ(rooms.size(), 1u);
  for (const Point2& c : rooms[0].outline)
    EXPECT_TRUE(std::isfinite(c.x) && std::isfinite(c.y)) << c.x << ", " << c.y;
  EXPECT_NEAR(rooms[0].area, (13.455 - 11.252909 - 0.26) * (0.055 + 4.661 - 0.26), 1e-6);
}

TEST(Rooms, SidesNearlyInLineMeetByAStepNotAKilometreAway) {
  // A 4 x 3 m room whose south side is two walls of different thickness with a kink of a
  // thousandth of a degree: their inner faces, 5 cm apart and nearly parallel, would meet
  // 3 km away (how walls drawn over each other gave rooms of 400,000 m2). They meet by a
  // step, and the clear floor stays inside the walls.
  const Plan plan =
      plan_with({make_wall("s1", {0, 0}, {2, 0}, 0.2), make_wall("s2", {2, 0}, {4, 0.00004}, 0.1),
                 make_wall("e", {4, 0.00004}, {4, 3}, 0.2), make_wall("n", {4, 3}, {0, 3}, 0.2),
                 make_wall("w", {0, 3}, {0, 0}, 0.2)});
  const std::vector<Room> rooms = find_rooms(plan);
  ASSERT_EQ(rooms.size(), 1u);
  for (const Point2& c : rooms[0].outline) {
    EXPECT_GE(c.x, 0.1 - 1e-9);
    EXPECT_LE(c.x, 3.9 + 1e-9);
    EXPECT_GE(c.y, 0.05 - 1e-9);
    EXPECT_LE(c.y, 2.9 + 1e-9);
  }
  EXPECT_NEAR(rooms[0].area, 1.9 * 2.8 + 1.9 * 2.85,
              1e-3);  // west half 10 cm off the centre line, east 5
}

TEST(Rooms, ASliverBetweenWallsAHairApartHasNoClearFloor) {
  // Two walls 15 cm thick drawn 1 um apart and slightly askew (arif-home): the sliver between
  // their centre lines is a closed region thinner than its walls.
  const Plan plan =
      plan_with({make_wall("a", {0, 0}, {5, 0}, 0.15), make_wall("b", {0, 0}, {5, 0.000001}, 0.15),
                 make_wall("c", {5, 0}, {5, 0.000001}, 0.15)});
  const std::vector<Room> rooms = find_rooms(plan);
  for (const Room& r : rooms) {
    EXPECT_LT(r.area, 0.01);
    for (const Point2& c : r.outline)
      EXPECT_LT(std::hypot(c.x - 2.5, c.y), 3.0) << c.x << ", " << c.y;
  }
}

TEST(Openings, OutsideWallMessageSaysHowFarAndHowToFix) {
  const Plan p = plan_with({make_wall("s", {0, 0}, {4, 0})},
                           {make_opening("w2", OpeningType::window, "s", 2.95, 1.2, 1.2, 0.9)});
  const Report r = validate(p, no_rooms());
  ASSERT_EQ(error_codes(r), Codes{Code::opening_outside_wall});
  EXPECT_NE(r.items[0].message.find("window 'w2' ends 0.15 m past the end of wall 's'"),
            std::string::npos)
      << r.items[0].message;
  EXPECT_EQ(r.items[0].fix, "move it 0.15 m toward the start, or make it 1.05 m wide");
}

TEST(Openings, BlockedDoorFixOffersClearOffsets) {
  const Plan p = plan_with({make_wall("a", {0, 0}, {4, 0}), make_wall("b", {2, 0}, {2, 3})},
                           {make_opening("d", OpeningType::door, "a", 1.5, 0.9, 2.1, 0)});
  const Report r = validate(p, no_rooms());
  ASSERT_EQ(error_codes(r), Codes{Code::opening_blocked});
  EXPECT_EQ(r.items[0].objects, (Ids{"d", "a", "b"}));
  EXPECT_EQ(r.items[0].fix,
            "move d along a clear of b: offset 0.97 (before it) or offset 2.13 (after it)");
}

TEST(Openings, OverlapAndNoOverlapAcrossDifferentHeights) {
  Plan p = plan_with({make_wall("s", {0, 0}, {4, 0})},
                     {make_opening("w1", OpeningType::window, "s", 0.5, 1, 1, 0.3),
                      make_opening("w2", OpeningType::window, "s", 1, 1, 0.5, 1.3)});
  EXPECT_EQ(error_codes(validate(p, no_rooms())), Codes{});  // stacked: w2 starts at w1's top
  p.openings[1].sill = 1.2;
  const Report r = validate(p, no_rooms());
  ASSERT_EQ(error_codes(r), Codes{Code::opening_overlap});
  EXPECT_EQ(r.items[0].objects, (Ids{"w1", "w2"}));
}

}  // namespace
}  // namespace roomcad
