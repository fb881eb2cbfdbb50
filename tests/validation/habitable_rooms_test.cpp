// SPDX-License-Identifier: GPL-3.0-or-later
// room_without_window asks a window only of rooms a person stays in: by the name the plan
// gives a room (`rooms[]`), else by its size and shape; a rules file changes both.
#include <gtest/gtest.h>

#include <string>

#include "plan_cases.h"
#include "validation/room_labels.h"

namespace roomcad {
namespace {

using namespace roomcad::testing;

/// A row of windowless rooms along y = 0..4 with 0.2 m walls, each with a door in the south
/// wall or the next room: a 4 x 4 m room (x 0..4), another (x 4..8), two 2 x 2 m closets
/// (x 8..10, either side of a wall at y = 2) and a corridor 1.5 m wide and 8 m long (y 4..5.5,
/// x 0..8).
Plan windowless_rooms() {
  return plan_with({make_wall("s", {0, 0}, {10, 0}, 0.2), make_wall("e", {10, 0}, {10, 4}, 0.2),
                    make_wall("n", {10, 4}, {0, 4}, 0.2), make_wall("w", {0, 4}, {0, 0}, 0.2),
                    make_wall("m1", {4, 0}, {4, 4}, 0.2), make_wall("m2", {8, 0}, {8, 4}, 0.2),
                    make_wall("c", {8, 2}, {10, 2}, 0.2), make_wall("cn", {0, 5.5}, {8, 5.5}, 0.2),
                    make_wall("cw", {0, 4}, {0, 5.5}, 0.2), make_wall("ce", {8, 4}, {8, 5.5}, 0.2)},
                   {make_opening("d1", OpeningType::door, "s", 1, 0.9, 2.1, 0),
                    make_opening("d2", OpeningType::door, "s", 5, 0.9, 2.1, 0),
                    make_opening("d3", OpeningType::door, "s", 8.5, 0.9, 2.1, 0),
                    make_opening("d4", OpeningType::door, "m2", 2.5, 0.9, 2.1, 0),
                    make_opening("d5", OpeningType::door, "n", 7, 0.9, 2.1, 0)});
}

/// The objects of each room_without_window warning, in report order.
std::vector<Ids> windowless(const Report& report) {
  std::vector<Ids> out;
  for (const Diagnostic& d : report.items)
    if (d.code == Code::room_without_window) out.push_back(d.objects);
  return out;
}

const Ids kWestRoom{"m1", "n", "s", "w"};
const Ids kMiddleRoom{"m1", "m2", "n", "s"};

TEST(HabitableRooms, UnnamedRoomsUnderSixSquareMetresAndCorridorsAreNotAskedForAWindow) {
  const Report r = validate(windowless_rooms());
  EXPECT_TRUE(r.ok());
  // The closets (3.24 m² clear) and the corridor (1.3 x 7.8 m clear) are not warned about.
  EXPECT_EQ(windowless(r), (std::vector<Ids>{kWestRoom, kMiddleRoom}));
}

TEST(HabitableRooms, ANamedRoomIsAskedUnlessAWordOfItsNameIsARoomNotLivedIn) {
  Plan plan = windowless_rooms();
  plan.rooms = {{.id = "name_a", .at = {2, 2}, .name = "Master Bathroom"},
                {.id = "name_b", .at = {6, 2}, .name = "Kitchen"},
                {.id = "name_c", .at = {9, 1}, .name = "Study"},
                {.id = "name_d", .at = {4, 4.7}, .name = "stairs"}};
  const Report r = validate(plan);
  // The bathroom is not asked; the kitchen is; the 3.2 m² study is, by its name; "stairs"
  // matches "stair".
  ASSERT_EQ(windowless(r), (std::vector<Ids>{kMiddleRoom, {"c", "e", "m2", "s"}}));
  EXPECT_NE(r.items.back().message.find("(Study, 3.24 m²"), std::string::npos)
      << r.items.back().message;
}

TEST(HabitableRooms, ANameOnAnotherLevelOrOutsideEveryRoomNamesNone) {
  Plan plan = windowless_rooms();
  plan.rooms = {{.id = "a", .at = {2, 2}, .name = "Bath"}};
  const std::vector<Room> rooms = find_rooms(plan);
  ASSERT_NE(room_labels(rooms, plan)[0], nullptr);
  EXPECT_EQ(room_labels(rooms, plan)[0]->name, "Bath");
  plan.rooms[0].level = "upper";
  EXPECT_EQ(room_labels(rooms, plan)[0], nullptr);
  plan.rooms[0] = {.id = "a", .at = {20, 20}, .name = "Bath"};
  for (const RoomLabel* label : room_labels(rooms, plan)) EXPECT_EQ(label, nullptr);
}

TEST(HabitableRooms, ARulesFileSetsTheAreaTheCorridorWidthAndTheNames) {
  const Result<RuleSet> rules = parse_rule_set(
      R"({"habitable_rooms": {"min_area": 2.0, "corridor_width": 1.0,
                               "not_habitable": ["Kitchen"]}})",
      "rooms.json");
  ASSERT_TRUE(rules.ok()) << rules.error();
  EXPECT_EQ(rules.value().habitable_rooms.not_habitable, (std::vector<std::string>{"kitchen"}));
  Plan plan = windowless_rooms();
  plan.rooms = {{.id = "name_b", .at = {6, 2}, .name = "Kitchen"}};
  const Report r = validate(plan, {.rules = rules.value()});
  // Now the closets and the corridor are asked, the kitchen is not.
  EXPECT_EQ(windowless(r).size(), 4u);
  for (const Ids& objects : windowless(r)) EXPECT_NE(objects, kMiddleRoom);

  for (const char* bad : {R"({"habitable_rooms": {"min_area": -1}})",
                          R"({"habitable_rooms": {"not_habitable": "bath"}})",
                          R"({"habitable_rooms": {"min_aera": 3}})"}) {
    const Result<RuleSet> refused = parse_rule_set(bad, "rooms.json");
    ASSERT_FALSE(refused.ok()) << bad;
    EXPECT_EQ(refused.code(), Code::usage_error);
    EXPECT_NE(refused.message().find("rooms.json: /habitable_rooms/"), std::string::npos)
        << refused.message();
  }
}

}  // namespace
}  // namespace roomcad
