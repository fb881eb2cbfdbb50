// SPDX-License-Identifier: GPL-3.0-or-later
// invalid_value, duplicate_id, unknown_reference, and "one mistake gives one error".
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "plan_cases.h"

namespace roomcad {
namespace {

using namespace roomcad::testing;

Light light(std::string id) {
  Light l;
  l.id = std::move(id);
  return l;
}

Camera camera(std::string id) {
  Camera c;
  c.id = std::move(id);
  c.eye = {0, 0, 5};
  return c;
}

Plan good_plan() {
  return plan_with({make_wall("a", {0, 0}, {4, 0}), make_wall("b", {4, 0}, {4, 3})},
                   {make_opening("d", OpeningType::door, "a", 1, 0.9, 2.1, 0)});
}

TEST(Values, AGoodPlanHasNoErrors) {
  const Report r = validate(good_plan(), no_rooms());
  EXPECT_TRUE(r.ok());
  EXPECT_EQ(r.items.size(), 0u);
}

TEST(Values, EachBadNumberIsOneInvalidValueAndSilencesGeometry) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const std::vector<std::pair<const char*, std::function<void(Plan&)>>> mistakes = {
      {"negative thickness", [](Plan& p) { p.walls[0].thickness = -0.2; }},
      {"zero thickness", [](Plan& p) { p.walls[0].thickness = 0; }},
      {"NaN thickness", [&](Plan& p) { p.walls[0].thickness = nan; }},
      {"zero height", [](Plan& p) { p.walls[0].height = 0; }},
      {"negative base", [](Plan& p) { p.walls[0].base = -1; }},
      {"infinite end", [&](Plan& p) { p.walls[0].to.x = inf; }},
      {"zero-length wall", [](Plan& p) { p.walls[0].to = p.walls[0].from; }},
      {"zero opening width", [](Plan& p) { p.openings[0].width = 0; }},
      {"negative opening height", [](Plan& p) { p.openings[0].height = -2; }},
      {"negative sill", [](Plan& p) { p.openings[0].sill = -0.1; }},
      {"NaN offset", [&](Plan& p) { p.openings[0].offset = nan; }},
      {"zero cell size", [](Plan& p) { p.site.cell_size = 0; }},
      {"zero cells", [](Plan& p) { p.site.cells[1] = 0; }},
      {"negative max height", [](Plan& p) { p.site.max_height = -6; }},
      {"zero tolerance", [](Plan& p) { p.site.tolerance = 0; }},
      {"NaN origin", [&](Plan& p) { p.site.origin.y = nan; }},
      {"ambient above 1",
       [](Plan& p) {
         p.lights.push_back(light("l"));
         p.lights[0].ambient = 1.5;
       }},
      {"zero light direction",
       [](Plan& p) {
         p.lights.push_back(light("l"));
         p.lights[0].direction = {0, 0, 0};
       }},
      {"camera eye at target",
       [](Plan& p) {
         p.cameras.push_back(camera("c"));
         p.cameras[0].target = p.cameras[0].eye;
       }},
      {"zero fov",
       [](Plan& p) {
         p.cameras.push_back(camera("c"));
         p.cameras[0].fov_deg = 0;
       }},
      {"NaN view height",
       [&](Plan& p) {
         p.cameras.push_back(camera("c"));
         p.cameras[0].projection = Projection::orthographic;
         p.cameras[0].view_height = nan;
       }},
      {"empty id", [](Plan& p) { p.walls[1].id = ""; }},
  };
  for (const auto& [name, apply] : mistakes) {
    SCOPED_TRACE(name);
    Plan p = good_plan();
    apply(p);
    const Report r = validate(p, no_rooms());
    EXPECT_EQ(error_codes(r), Codes{Code::invalid_value});
    ASSERT_FALSE(r.items.empty());
    EXPECT_FALSE(r.items[0].message.empty());
    EXPECT_FALSE(r.items[0].fix.empty());
  }
}

TEST(Values, MessageNamesObjectFieldAndValue) {
  Plan p = good_plan();
  p.walls[1].thickness = -0.2;
  const Report r = validate(p, no_rooms());
  ASSERT_EQ(r.items.size(), 1u);
  EXPECT_EQ(r.items[0].objects, Ids{"b"});
  EXPECT_NE(r.items[0].message.find("wall 'b'"), std::string::npos) << r.items[0].message;
  EXPECT_NE(r.items[0].message.find("thickness is -0.2"), std::string::npos) << r.items[0].message;
}

TEST(Values, DuplicateIdsAcrossAllKindsOfObject) {
  Plan p = good_plan();
  p.openings[0].id = "b";            // same as a wall
  p.cameras.push_back(camera("a"));  // same as the other wall
  const Report r = validate(p, no_rooms());
  EXPECT_EQ(error_codes(r), (Codes{Code::duplicate_id, Code::duplicate_id}));
  EXPECT_EQ(r.items[0].objects, Ids{"a"});
  EXPECT_NE(r.items[0].message.find("walls[0], cameras[0]"), std::string::npos)
      << r.items[0].message;
}

TEST(Values, UnknownReferenceIsReportedAndNotCheckedFurther) {
  Plan p = good_plan();
  p.openings[0].wall = "nope";
  p.openings[0].offset = 100;  // would be outside its wall, but there is no wall
  const Report r = validate(p, no_rooms());
  EXPECT_EQ(error_codes(r), Codes{Code::unknown_reference});
  EXPECT_NE(r.items[0].message.find("'nope'"), std::string::npos);
}

TEST(Values, OpeningOnABadWallIsNotCheckedFurther) {
  Plan p = good_plan();
  p.walls[0].height = -1;
  p.openings[0].height = 5;  // taller than the wall would be: not reported, the wall is bad
  EXPECT_EQ(error_codes(validate(p, no_rooms())), Codes{Code::invalid_value});
}

TEST(Values, AllProblemsComeInOneRun) {
  Plan p = good_plan();
  p.walls[0].thickness = 0;
  p.openings.push_back(
      make_opening("x", OpeningType::window, "b", 2.5, 1, 1, 0.9));  // past b's end
  p.walls.push_back(make_wall("c", {1, 1}, {3, 1}));
  p.walls.push_back(make_wall("c2", {1, 1.1}, {3, 1.1}));  // overlaps c
  p.lights.push_back(light("x"));                          // duplicate of the window
  const Report r = validate(p, no_rooms());
  EXPECT_EQ(error_codes(r), (Codes{Code::invalid_value, Code::duplicate_id, Code::wall_overlap,
                                   Code::opening_outside_wall}));
}

TEST(Values, WarningsForUnknownFieldsAndRaisedDoors) {
  Plan p = good_plan();
  p.walls[0].extra.push_back({"colour", "\"#ffffff\""});
  p.openings[0].sill = 0.2;
  const Report r = validate(p, no_rooms());
  EXPECT_TRUE(r.ok());
  ASSERT_EQ(r.warning_count(), 2u);
  EXPECT_EQ(r.items[0].code, Code::unknown_field);
  EXPECT_NE(r.items[0].message.find("'colour'"), std::string::npos);
  EXPECT_EQ(r.items[1].code, Code::door_above_floor);
  ValidateOptions quiet = no_rooms();
  quiet.unknown_field_warnings = false;
  EXPECT_EQ(validate(p, quiet).warning_count(), 1u);
}

}  // namespace
}  // namespace roomcad
