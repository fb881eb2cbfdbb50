// SPDX-License-Identifier: GPL-3.0-or-later
#include "render/floor_plan.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "validation/validate.h"

namespace roomcad {
namespace {

// One straight wall, 4 m along x, 0.2 m thick, with a window (sill 0.9, top 2.2) at u = 1..2
// and a door at u = 2.5..3.3. At 1:50 a metre is 20 mm.
Plan one_wall_plan() {
  Plan plan;
  Wall wall;
  wall.id = "w";
  wall.from = {0, 0};
  wall.to = {4, 0};
  wall.thickness = 0.2;
  plan.walls.push_back(wall);
  Opening window;
  window.id = "win";
  window.type = OpeningType::window;
  window.wall = "w";
  window.offset = 1.0;
  window.width = 1.0;
  window.sill = 0.9;
  window.height = 1.3;
  Opening door;
  door.id = "door";
  door.wall = "w";
  door.offset = 2.5;
  door.width = 0.8;
  plan.openings = {door, window};  // out of order on purpose: drawing sorts along the wall
  return plan;
}

/// Where plan point (u, across) of the wall lies on the drawing's paper: 20 mm a metre, north
/// up, from the wall's top-left corner (the first cut part's, u = 0, across = 0.1).
struct WallPaper {
  Point2 corner;
  explicit WallPaper(const FloorPlanDrawing& d) : corner{INFINITY, INFINITY} {
    for (const Point2& p : d.cut_walls.at(0)) {
      corner = {std::min(corner.x, p.x), std::min(corner.y, p.y)};
    }
  }
  Point2 operator()(double u, double across) const {
    return {corner.x + 20.0 * u, corner.y + 20.0 * (0.1 - across)};
  }
};

void expect_near(Point2 got, Point2 want) {
  EXPECT_NEAR(got.x, want.x, 1e-9);
  EXPECT_NEAR(got.y, want.y, 1e-9);
}

/// @return the [min, max] paper x of a polygon.
std::pair<double, double> x_span(const PaperPolygon& polygon) {
  const auto [lo, hi] = std::minmax_element(polygon.begin(), polygon.end(),
                                            [](Point2 a, Point2 b) { return a.x < b.x; });
  return {lo->x, hi->x};
}

TEST(FloorPlan, CutsTheWallAtTheOpeningsTheSectionPasses) {
  const FloorPlanDrawing d = draw_floor_plan(one_wall_plan(), {});
  const WallPaper paper(d);
  ASSERT_EQ(d.cut_walls.size(), 3u);
  const double want[3][2] = {{0.0, 1.0}, {2.0, 2.5}, {3.3, 4.0}};
  for (int i = 0; i < 3; ++i) {
    const auto [lo, hi] = x_span(d.cut_walls[i]);
    EXPECT_NEAR(lo, paper(want[i][0], 0).x, 1e-9) << i;
    EXPECT_NEAR(hi, paper(want[i][1], 0).x, 1e-9) << i;
  }
  // The window symbol: three lines along the wall, on both faces and the centre line.
  ASSERT_EQ(d.windows.size(), 3u);
  for (int i = 0; i < 3; ++i) {
    const double across = -0.1 + 0.1 * i;
    expect_near(d.windows[i].a, paper(1.0, across));
    expect_near(d.windows[i].b, paper(2.0, across));
  }
  // The page holds everything with a 10 mm border: the door swing reaches furthest up.
  EXPECT_NEAR(d.door_swings[0].centre.y - d.door_swings[0].radius, 10.0, 1e-9);
  EXPECT_GT(d.width, 4 * 20 + 20.0);
  EXPECT_GT(d.height, 0.9 * 20 + 20.0 + 25.0);
}

TEST(FloorPlan, DrawsTheDoorLeafAndSwingPerHingeAndSwing) {
  Plan plan = one_wall_plan();
  FloorPlanDrawing d = draw_floor_plan(plan, {});
  WallPaper paper(d);
  // hinge left, swing in: turns about u = 2.5 on the left face, opens towards +y.
  ASSERT_EQ(d.door_leaves.size(), 1u);
  ASSERT_EQ(d.door_swings.size(), 1u);
  expect_near(d.door_leaves[0].a, paper(2.5, 0.1));
  expect_near(d.door_leaves[0].b, paper(2.5, 0.9));
  expect_near(d.door_swings[0].centre, paper(2.5, 0.1));
  expect_near(d.door_swings[0].from, paper(2.5, 0.9));
  expect_near(d.door_swings[0].to, paper(3.3, 0.1));
  EXPECT_DOUBLE_EQ(d.door_swings[0].radius, 16.0);
  // hinge right, swing out: turns about u = 3.3 on the right face, opens towards -y.
  plan.openings[0].hinge = Hinge::right;
  plan.openings[0].swing = Swing::out;
  d = draw_floor_plan(plan, {});
  paper = WallPaper(d);
  expect_near(d.door_leaves[0].a, paper(3.3, -0.1));
  expect_near(d.door_leaves[0].b, paper(3.3, -0.9));
  expect_near(d.door_swings[0].to, paper(2.5, -0.1));
}

TEST(FloorPlan, WindowOutsideTheCutLeavesTheWallWhole) {
  const FloorPlanDrawing d = draw_floor_plan(one_wall_plan(), {.cut_height = 2.5});
  EXPECT_TRUE(d.windows.empty());
  EXPECT_EQ(d.cut_walls.size(), 2u);  // only the door is cut
  EXPECT_EQ(d.door_leaves.size(), 1u);
}

TEST(FloorPlan, WallsBelowAndAboveTheCutAreSeenNotCut) {
  Plan plan = one_wall_plan();
  plan.walls[0].height = 0.8;
  FloorPlanDrawing d = draw_floor_plan(plan, {});
  EXPECT_TRUE(d.cut_walls.empty());
  EXPECT_EQ(d.walls_below.size(), 1u);
  EXPECT_TRUE(d.door_leaves.empty());
  plan.walls[0].height = 2.8;
  plan.walls[0].base = 1.5;
  d = draw_floor_plan(plan, {});
  EXPECT_EQ(d.walls_above.size(), 1u);
  EXPECT_TRUE(d.walls_below.empty());
}

TEST(FloorPlan, DimensionsScaleBarAndTitle) {
  const FloorPlanDrawing d = draw_floor_plan(one_wall_plan(), {.scale = 50});
  std::vector<std::string> texts;
  for (const PaperText& t : d.dimension_texts) texts.push_back(t.text);
  // The wall's own length, then the overall width and depth of the plan.
  EXPECT_EQ(texts, (std::vector<std::string>{"4.00", "4.00", "0.20"}));
  EXPECT_DOUBLE_EQ(d.dimension_texts[2].rotate_deg, -90.0);  // read from the right
  EXPECT_EQ(d.scale_bar_black.size() + d.scale_bar_white.size(), 5u);
  ASSERT_GE(d.labels.size(), 3u);
  EXPECT_EQ(d.labels[1].text, "2 m");  // the longest round length fitting 40 mm at 1:50
  EXPECT_NE(d.labels.back().text.find("section at 1.00 m, scale 1:50"), std::string::npos);
}

TEST(FloorPlan, NamesRoomsAndDimensionsOuterWallsOutside) {
  // A 4 x 3 m box drawn clockwise, split by a partition at x = 3: two rooms.
  Plan plan;
  const auto add_wall = [&](const char* id, Point2 from, Point2 to) {
    Wall w;
    w.id = id;
    w.from = from;
    w.to = to;
    w.thickness = 0.2;
    plan.walls.push_back(w);
  };
  add_wall("w", {1, 1}, {1, 4});
  add_wall("n", {1, 4}, {5, 4});
  add_wall("e", {5, 4}, {5, 1});
  add_wall("s", {5, 1}, {1, 1});
  add_wall("part", {3, 1}, {3, 4});
  ASSERT_TRUE(validate(plan).ok());
  const std::vector<Room> rooms = find_rooms(plan);
  ASSERT_EQ(rooms.size(), 2u);
  const FloorPlanDrawing d = draw_floor_plan(plan, {});
  ASSERT_EQ(d.rooms.size(), 2u);
  ASSERT_EQ(d.room_labels.size(), 4u);  // name and area of each
  EXPECT_EQ(d.room_labels[0].text, "Room 1");
  EXPECT_EQ(d.room_labels[1].text, fmt::format("{:.2f} m²", rooms[0].area));
  EXPECT_EQ(d.room_labels[3].text, fmt::format("{:.2f} m²", rooms[1].area));
  // Four outer walls and the two overall sizes; the partition has rooms on both sides.
  std::vector<std::string> texts;
  for (const PaperText& t : d.dimension_texts) texts.push_back(t.text);
  EXPECT_EQ(texts, (std::vector<std::string>{"3.00", "4.00", "3.00", "4.00", "4.20", "3.20"}));
  // The south wall's dimension sits below the walls, the west wall's to their left, although
  // the walls run clockwise (their right side is the inside).
  double walls_bottom = -INFINITY;
  double walls_left = INFINITY;
  for (const PaperPolygon& part : d.cut_walls) {
    for (const Point2& p : part) {
      walls_bottom = std::max(walls_bottom, p.y);
      walls_left = std::min(walls_left, p.x);
    }
  }
  EXPECT_GT(d.dimension_texts[3].at.y, walls_bottom);  // "s"
  EXPECT_LT(d.dimension_texts[0].at.x, walls_left);    // "w"
}

TEST(FloorPlan, RejectsBadOptions) {
  const Status scale = check_floor_plan_options({.scale = 0});
  EXPECT_EQ(scale.code(), Code::usage_error);
  EXPECT_NE(scale.message().find("scale"), std::string::npos);
  const Status cut = check_floor_plan_options({.cut_height = -1});
  EXPECT_EQ(cut.code(), Code::usage_error);
  EXPECT_NE(cut.message().find("cut height"), std::string::npos);
  EXPECT_THROW((void)draw_floor_plan(one_wall_plan(), {.scale = NAN}), PreconditionError);
  EXPECT_TRUE(check_floor_plan_options({}).ok());
}

}  // namespace
}  // namespace roomcad
